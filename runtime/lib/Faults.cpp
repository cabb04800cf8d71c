// The texture kernels' fault record (docs/abi.md "Faults", docs/reliability.md "User code"):
// the first safety check of user code that tripped in a launch (a loop past the budget, a
// __global array read out of bounds), turned into one error naming node, line and pixel. The
// words are texcc::describeTextureFault's, which texcc-eval prints too.
#include "texrender/Error.h"
#include "texrender/Renderer.h"

#include "texcc/Kernel/TextureFault.h"

namespace texrender {

void Renderer::checkTextureFaults(const cl::Buffer &Active) {
  cl_int F[TEXCC_FAULT_WORDS] = {};
  Cl->read(B["textureFaults"], F, sizeof F);
  if (F[TEXCC_FAULT_KIND] == TEXCC_FAULT_NONE)
    return;
  // Cleared, so that a renderer that goes on after the error (--watch) starts clean.
  const cl_int Zero[TEXCC_FAULT_WORDS] = {};
  Cl->write(B["textureFaults"], Zero, sizeof Zero);
  cl_int Path = 0;
  RtPath P{};
  Cl->read(Active, &Path, sizeof Path, size_t(F[TEXCC_FAULT_HIT]) * sizeof(cl_int));
  Cl->read(B["paths"], &P, sizeof P, size_t(Path) * sizeof(RtPath));
  const std::string_view ArgsBin(reinterpret_cast<const char *>(Lay.ArgsBin.data()),
                                 Lay.ArgsBin.size());
  throw TextureFault(texcc::describeTextureFault(F, Lay.Manifest, ArgsBin) + " at pixel (" +
              std::to_string(P.pixel % unsigned(Settings.Width)) + ", " +
              std::to_string(P.pixel / unsigned(Settings.Width)) + ")");
}

} // namespace texrender
