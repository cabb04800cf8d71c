// The texture kernels' fault record (docs/abi.md "Faults", docs/reliability.md "User code"):
// the first safety check of user code that tripped in a launch (a loop past the budget, a
// __global array read out of bounds), turned into one error naming node, line and pixel.
#include "texrender/Error.h"
#include "texrender/Renderer.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>

namespace texrender {

using json = nlohmann::json;

namespace {

/// The id of the node that ran, and its function's file (the name only), from layout.json: At
/// is TEXCC_AT_NODE | node index, or the index of the instruction in material Mat's program,
/// whose record offset (args.bin) names the node.
struct FaultNode {
  std::string Id = "?", File = "?";
};

FaultNode faultNode(const Layout &Lay, int Mat, uint32_t At) {
  FaultNode Out;
  json J = json::parse(Lay.Text, nullptr, /*allow_exceptions=*/false);
  if (!J.is_object() || !J["nodes"].is_array())
    return Out;
  const json &Nodes = J["nodes"];
  const json *Node = nullptr;
  if (At & TEXCC_AT_NODE) {
    const uint32_t Index = At & ~uint32_t(TEXCC_AT_NODE);
    if (Index < Nodes.size())
      Node = &Nodes[Index];
  } else if (J["materials"].is_array() && Mat >= 0 && size_t(Mat) < J["materials"].size()) {
    const uint64_t ProgramWord =
        J["materials"][Mat]["program"].value("wordOffset", uint64_t(0));
    const uint64_t Word = ProgramWord + 4 + 3 * uint64_t(At);
    if ((Word + 1) * 4 <= Lay.ArgsBin.size()) {
      uint32_t Record = 0;
      std::memcpy(&Record, Lay.ArgsBin.data() + 4 * Word, 4);
      for (const json &N : Nodes) {
        bool Match = N["record"].value("offset", uint64_t(~0u)) == Record;
        if (N["copies"].is_array())
          for (const json &C : N["copies"])
            Match = Match || (C.is_number() && C.get<uint64_t>() == Record);
        if (Match) {
          Node = &N;
          break;
        }
      }
    }
  }
  if (!Node)
    return Out;
  Out.Id = Node->value("id", "?");
  const std::string Fn = Node->value("fn", "");
  if (J["functions"].is_array())
    for (const json &F : J["functions"])
      if (F.value("name", "") == Fn)
        Out.File = std::filesystem::path(F.value("file", "?")).filename().string();
  return Out;
}

} // namespace

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
  const FaultNode N = faultNode(Lay, F[TEXCC_FAULT_MATERIAL], uint32_t(F[TEXCC_FAULT_AT]));
  std::string What;
  if (F[TEXCC_FAULT_KIND] == TEXCC_FAULT_LOOP_BUDGET)
    What = "loop ran past its budget of " + std::to_string(F[TEXCC_FAULT_DETAIL]) +
           " iterations (texcc --loop-budget)";
  else if (F[TEXCC_FAULT_KIND] == TEXCC_FAULT_INDEX)
    What = "index " + std::to_string(F[TEXCC_FAULT_DETAIL]) + " is out of bounds of an array of " +
           std::to_string(F[TEXCC_FAULT_EXTRA]) + " elements";
  else
    What = "fault " + std::to_string(F[TEXCC_FAULT_KIND]);
  throw Error("texture node '" + N.Id + "' (" + N.File + ":" + std::to_string(F[TEXCC_FAULT_LINE]) +
              "): " + What + " at pixel (" + std::to_string(P.pixel % unsigned(Settings.Width)) +
              ", " + std::to_string(P.pixel / unsigned(Settings.Width)) + ")");
}

} // namespace texrender
