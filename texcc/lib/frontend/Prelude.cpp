// The parse-time prelude: declares the embedded API for Clang. It is never emitted; the generated
// kernel gets kernels/common/texcc_device.h instead, and the front end lowers every use.
//
// readAttr/readSetting are C overloads (`overloadable`) selected by `enable_if` on the string
// literal, one per name, so that Clang itself types readAttr("Normal") as float3 and reports a
// mismatch at the user's own line. The last overload has no enable_if: Clang picks it for an
// unknown name or a non-literal argument, and the front end reports texcc's own error there. It
// returns float, which converts implicitly to every vector type, so that no second error follows.
#include "ApiTables.h"

#include "texcc/Frontend/Frontend.h"

namespace texcc::frontend {

static std::string overloads(const char *Fn, const ApiTable &Table) {
  std::string Out;
  for (const auto &[Name, Type] : Table)
    Out += graph::spelling(Type) + " " + Fn +
           "(__constant char *name) __attribute__((overloadable, enable_if(" +
           "__builtin_strcmp(name, \"" + Name + "\") == 0, \"\")));\n";
  Out += std::string("float __attribute__((overloadable)) ") + Fn + "(__constant char *name);\n";
  return Out;
}

const std::string &parsePrelude() {
  static const std::string Text = [] {
    std::string P = "#pragma clang system_header\n"
                    "/* texcc parse-time prelude: the embedded API (see docs/frontend.md). */\n"
                    "typedef int sam2D;\n"
                    "float4 tex2D(sam2D image, float2 uv);\n"
                    "float4 tex2DFiltered(sam2D image, float2 uv, int interpolation, "
                    "int extension, int straight);\n";
    P += overloads("readAttr", graph::attributeTable());
    P += overloads("readSetting", graph::settingTable());
    return P;
  }();
  return Text;
}

} // namespace texcc::frontend
