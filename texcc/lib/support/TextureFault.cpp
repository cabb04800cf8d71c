// The fault record in words (TextureFault.h): the one description that texrender and texcc-eval
// print, so that a fault reads the same from the renderer and from the evaluator.
#include "texcc/Support/TextureFault.h"

#include "texcc_abi.h"

#include <nlohmann/json.hpp>

#include <cstring>
#include <filesystem>

namespace texcc {

using Json = nlohmann::json;

namespace {

/// The id of the node that ran, and its function's file (the name only), from layout.json: At
/// is TEXCC_AT_NODE | node index, or the index of the instruction in material Mat's program,
/// whose record offset (args.bin) names the node.
struct FaultNode {
  std::string Id = "?", File = "?";
};

const Json *nodeOfInstruction(const Json &J, int Mat, uint32_t At, std::string_view ArgsBin) {
  if (!J["materials"].is_array() || Mat < 0 || size_t(Mat) >= J["materials"].size())
    return nullptr;
  const uint64_t ProgramWord = J["materials"][Mat]["program"].value("wordOffset", uint64_t(0));
  const uint64_t Word = ProgramWord + 4 + 3 * uint64_t(At);
  if ((Word + 1) * 4 > ArgsBin.size())
    return nullptr;
  uint32_t Record = 0;
  std::memcpy(&Record, ArgsBin.data() + 4 * Word, 4);
  for (const Json &N : J["nodes"]) {
    bool Match = N["record"].value("offset", uint64_t(~0u)) == Record;
    if (N["copies"].is_array())
      for (const Json &C : N["copies"])
        Match = Match || (C.is_number() && C.get<uint64_t>() == Record);
    if (Match)
      return &N;
  }
  return nullptr;
}

FaultNode faultNode(std::string_view LayoutText, std::string_view ArgsBin, int Mat, uint32_t At) {
  FaultNode Out;
  const Json J = Json::parse(LayoutText, nullptr, /*allow_exceptions=*/false);
  if (!J.is_object() || !J["nodes"].is_array())
    return Out;
  const Json &Nodes = J["nodes"];
  const Json *Node = nullptr;
  if (At & TEXCC_AT_NODE) {
    const uint32_t Index = At & ~uint32_t(TEXCC_AT_NODE);
    if (Index < Nodes.size())
      Node = &Nodes[Index];
  } else {
    Node = nodeOfInstruction(J, Mat, At, ArgsBin);
  }
  if (!Node)
    return Out;
  Out.Id = Node->value("id", "?");
  const std::string Fn = Node->value("fn", "");
  if (J["functions"].is_array())
    for (const Json &F : J["functions"])
      if (F.value("name", "") == Fn)
        Out.File = std::filesystem::path(F.value("file", "?")).filename().string();
  return Out;
}

} // namespace

std::string describeTextureFault(const int32_t *Words, std::string_view LayoutText,
                                 std::string_view ArgsBin) {
  const FaultNode N = faultNode(LayoutText, ArgsBin, Words[TEXCC_FAULT_MATERIAL],
                                uint32_t(Words[TEXCC_FAULT_AT]));
  std::string What;
  if (Words[TEXCC_FAULT_KIND] == TEXCC_FAULT_LOOP_BUDGET)
    What = "loop ran past its budget of " + std::to_string(uint32_t(Words[TEXCC_FAULT_DETAIL])) +
           " iterations (texcc --loop-budget)";
  else if (Words[TEXCC_FAULT_KIND] == TEXCC_FAULT_INDEX)
    What = "index " + std::to_string(Words[TEXCC_FAULT_DETAIL]) +
           " is out of bounds of an array of " +
           std::to_string(uint32_t(Words[TEXCC_FAULT_EXTRA])) + " elements";
  else
    What = "fault " + std::to_string(Words[TEXCC_FAULT_KIND]);
  return "texture node '" + N.Id + "' (" + N.File + ":" +
         std::to_string(Words[TEXCC_FAULT_LINE]) + "): " + What;
}

} // namespace texcc
