// The fault record in words (TextureFault.h): the one description that texrender and texcc-eval
// print, so that a fault reads the same from the renderer and from the evaluator. The nodes come
// from the kernel manifest (layout.json read once, by its one reader).
#include "texcc/Kernel/TextureFault.h"

#include "texcc_abi.h"

#include <cstring>
#include <filesystem>

namespace texcc {

namespace {

/// The id of the node that ran, and its function's file (the name only): At is
/// TEXCC_AT_NODE | node index, or the index of the instruction in material Mat's program, whose
/// record offset (args.bin) names the node.
struct FaultNode {
  std::string Id = "?", File = "?";
};

const kernel::NodeLayout *nodeOfInstruction(const kernel::Manifest &M, int Mat, uint32_t At,
                                            std::string_view ArgsBin) {
  if (Mat < 0 || size_t(Mat) >= M.Materials.size())
    return nullptr;
  const uint64_t Word = M.Materials[Mat].ProgramWordOffset + 4 + 3 * uint64_t(At);
  if ((Word + 1) * 4 > ArgsBin.size())
    return nullptr;
  uint32_t Record = 0;
  std::memcpy(&Record, ArgsBin.data() + 4 * Word, 4);
  for (const kernel::NodeLayout &N : M.Nodes) {
    bool Match = N.RecordOffset == Record;
    for (unsigned C : N.Copies)
      Match = Match || C == Record;
    if (Match)
      return &N;
  }
  return nullptr;
}

FaultNode faultNode(const kernel::Manifest &M, std::string_view ArgsBin, int Mat, uint32_t At) {
  FaultNode Out;
  const kernel::NodeLayout *Node = nullptr;
  if (At & TEXCC_AT_NODE) {
    const uint32_t Index = At & ~uint32_t(TEXCC_AT_NODE);
    if (Index < M.Nodes.size())
      Node = &M.Nodes[Index];
  } else {
    Node = nodeOfInstruction(M, Mat, At, ArgsBin);
  }
  if (!Node)
    return Out;
  Out.Id = Node->Id;
  for (const kernel::FunctionLayout &F : M.Functions)
    if (F.Name == Node->Fn)
      Out.File = std::filesystem::path(F.File).filename().string();
  return Out;
}

} // namespace

std::string describeTextureFault(const int32_t *Words, const kernel::Manifest &M,
                                 std::string_view ArgsBin) {
  const FaultNode N =
      faultNode(M, ArgsBin, Words[TEXCC_FAULT_MATERIAL], uint32_t(Words[TEXCC_FAULT_AT]));
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
