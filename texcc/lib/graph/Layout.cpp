// Argument layout and the encoding of args.bin (docs/abi.md).

#include "texcc/Graph/Passes.h"

#include <algorithm>
#include <cstring>

namespace texcc::graph {

namespace {

uint32_t alignTo(uint32_t V, uint32_t A) { return (V + A - 1) / A * A; }

/// The source words of a node's record as one instruction of material M sees them.
std::vector<uint32_t> sourceWords(const CompiledGraph &CG, const CompiledNode &N,
                                  const std::vector<int> &SlotOf) {
  std::vector<uint32_t> Words;
  for (const CompiledArg &A : N.Args) {
    unsigned Slot = 0;
    if (A.Src == CompiledArg::Source::Node)
      Slot = static_cast<unsigned>(SlotOf[A.NodeIndex]);
    Words.push_back(sourceWord(A, Slot));
  }
  (void)CG;
  return Words;
}

/// Slot of every node in a material's program (-1: not in it). One table for all materials,
/// refilled in the length of each program: a fresh one per material cost nodes x materials.
class ProgramSlots {
public:
  explicit ProgramSlots(const CompiledGraph &CG) : SlotOf(CG.Nodes.size(), -1) {}
  const std::vector<int> &of(const CompiledMaterial &M) {
    for (unsigned N : Filled)
      SlotOf[N] = -1;
    Filled.clear();
    for (const Instruction &In : M.Program) {
      SlotOf[In.Node] = static_cast<int>(In.ResultSlot);
      Filled.push_back(In.Node);
    }
    return SlotOf;
  }

private:
  std::vector<int> SlotOf;
  std::vector<unsigned> Filled;
};

uint32_t elementStride(BaseType B) { return sizeOf(ValueType{B, false}); }

} // namespace

/// Offsets of the parameters, then of the hoisted values, and where the last one ends.
static std::vector<uint32_t> blockOffsets(const FunctionSignature &Sig, uint32_t &End) {
  std::vector<uint32_t> Offsets;
  End = 0;
  auto place = [&](ValueType T) {
    End = alignTo(End, alignOf(T));
    Offsets.push_back(End);
    End += sizeOf(T);
  };
  for (const Param &P : Sig.Params)
    place(P.Type);
  for (const HoistedValue &H : Sig.Hoisted)
    place(ValueType{H.Type, false});
  return Offsets;
}

std::vector<uint32_t> parameterOffsets(const FunctionSignature &Sig, uint32_t &BlockSize) {
  std::vector<uint32_t> Offsets = blockOffsets(Sig, BlockSize);
  BlockSize = alignTo(BlockSize, 16);
  Offsets.resize(Sig.Params.size());
  return Offsets;
}

std::vector<uint32_t> hoistedOffsets(const FunctionSignature &Sig) {
  uint32_t End = 0;
  std::vector<uint32_t> Offsets = blockOffsets(Sig, End);
  Offsets.erase(Offsets.begin(), Offsets.begin() + Sig.Params.size());
  return Offsets;
}

bool hoistsUniforms(const CompiledNode &N, const FunctionSignature &Sig) {
  if (Sig.Hoisted.empty() || Sig.HoistedFrom.empty())
    return false;
  bool AllBaked = true;
  for (unsigned P : Sig.HoistedFrom) {
    if (P >= N.Args.size() || N.Args[P].Src != CompiledArg::Source::Constant ||
        N.Args[P].Type.IsGlobalArray)
      return false;
    AllBaked = AllBaked && N.Args[P].Bake;
  }
  return !AllBaked;
}

uint32_t sourceWordsBytes(size_t NumParams) {
  return alignTo(4 * static_cast<uint32_t>(NumParams), 16);
}

uint32_t parameterBlockStart(const CompiledNode &N, uint32_t RecordOffset) {
  return RecordOffset + sourceWordsBytes(N.Args.size());
}

uint32_t sourceWord(const CompiledArg &A, unsigned Slot) {
  uint32_t Broadcast = A.Broadcast ? 1u << 29 : 0;
  switch (A.Src) {
  case CompiledArg::Source::Constant:
    return 0;
  case CompiledArg::Source::Node:
    return (1u << 30) | Broadcast | (Slot & 0xFFFFu);
  case CompiledArg::Source::Attribute:
    return (2u << 30) | Broadcast | (static_cast<uint32_t>(A.AttrId) & 0xFFFFu);
  }
  return 0;
}

void layoutArguments(CompiledGraph &CG, std::ostream *Log) {
  uint32_t Words = 0;
  for (CompiledMaterial &M : CG.Materials) {
    M.ProgramWordOffset = Words;
    Words += 2 + 3 * static_cast<uint32_t>(M.Program.size()) +
             static_cast<uint32_t>(M.Outputs.size());
  }
  CG.ProgramWords = Words;
  CG.RecordsOffset = alignTo(4 * Words, 16);
  uint32_t Cursor = CG.RecordsOffset;
  for (CompiledNode &N : CG.Nodes) {
    uint32_t BlockSize = 0;
    std::vector<uint32_t> Offsets = parameterOffsets(CG.Signatures.at(N.Fn), BlockSize);
    for (size_t I = 0; I < N.Args.size(); ++I)
      N.Args[I].BlockOffset = Offsets[I];
    N.RecordOffset = Cursor;
    N.RecordSize = sourceWordsBytes(N.Args.size()) + BlockSize;
    N.RecordCopies.clear();
    Cursor += N.RecordSize;
    if (Log)
      *Log << "layout: node '" << N.Id << "': record at byte " << N.RecordOffset << ", "
           << N.RecordSize << " bytes\n";
  }
  // A node's first appearance (materials in order) fixes its record's source words; a material
  // whose slots differ gets a copy with its own words.
  std::vector<std::vector<uint32_t>> PrimaryWords(CG.Nodes.size());
  std::vector<bool> HasPrimary(CG.Nodes.size(), false);
  std::vector<std::vector<std::pair<std::vector<uint32_t>, uint32_t>>> Copies(CG.Nodes.size());
  ProgramSlots Slots(CG);
  for (CompiledMaterial &M : CG.Materials) {
    const std::vector<int> &SlotOf = Slots.of(M);
    for (Instruction &In : M.Program) {
      CompiledNode &N = CG.Nodes[In.Node];
      std::vector<uint32_t> W = sourceWords(CG, N, SlotOf);
      if (!HasPrimary[In.Node]) {
        HasPrimary[In.Node] = true;
        PrimaryWords[In.Node] = W;
      }
      if (W == PrimaryWords[In.Node]) {
        In.RecordOffset = N.RecordOffset;
        continue;
      }
      auto &C = Copies[In.Node];
      auto It = std::find_if(C.begin(), C.end(), [&](const auto &P) { return P.first == W; });
      if (It == C.end()) {
        C.push_back({W, Cursor});
        N.RecordCopies.push_back(Cursor);
        if (Log)
          *Log << "layout: node '" << N.Id << "': material '" << M.Name
               << "' reads its arguments from other slots: record copy at byte " << Cursor
               << "\n";
        Cursor += N.RecordSize;
        It = C.end() - 1;
      }
      In.RecordOffset = It->second;
    }
  }
  for (CompiledNode &N : CG.Nodes)
    for (CompiledArg &A : N.Args) {
      if (!A.Type.IsGlobalArray)
        continue;
      Cursor = alignTo(Cursor, 16);
      A.ArrayByteOffset = Cursor;
      Cursor += A.ArrayCount * elementStride(A.Type.Base);
      if (Log)
        *Log << "layout: node '" << N.Id << "': array '" << A.Name << "' (" << A.ArrayCount
             << " x " << spelling(A.Type.Base) << ") at byte " << A.ArrayByteOffset << "\n";
    }
  CG.ArgsBin.assign(alignTo(Cursor, 16), 0);
}

namespace {

void put32(std::vector<uint8_t> &Bin, uint32_t Offset, uint32_t V) {
  for (int I = 0; I < 4; ++I)
    Bin[Offset + I] = static_cast<uint8_t>(V >> (8 * I));
}

void putFloat(std::vector<uint8_t> &Bin, uint32_t Offset, double D) {
  float F = static_cast<float>(D);
  uint32_t U;
  std::memcpy(&U, &F, 4);
  put32(Bin, Offset, U);
}

void putInt(std::vector<uint8_t> &Bin, uint32_t Offset, double D) {
  put32(Bin, Offset, static_cast<uint32_t>(static_cast<int32_t>(D)));
}

bool isIntLike(BaseType B) { return B == BaseType::Int || B == BaseType::Sampler; }

void encodeRecord(std::vector<uint8_t> &Bin, const CompiledNode &N, uint32_t Offset,
                  const std::vector<uint32_t> &Words) {
  for (size_t I = 0; I < Words.size(); ++I)
    put32(Bin, Offset + 4 * static_cast<uint32_t>(I), Words[I]);
  uint32_t Block = parameterBlockStart(N, Offset);
  for (const CompiledArg &A : N.Args)
    encodeArgumentValue(Bin, Block, A);
}

} // namespace

void encodeArgumentValue(std::vector<uint8_t> &Bin, uint32_t BlockStart, const CompiledArg &A) {
  if (A.Src != CompiledArg::Source::Constant)
    return;
  uint32_t At = BlockStart + A.BlockOffset;
  if (A.Type.IsGlobalArray) {
    put32(Bin, At, A.ArrayByteOffset);
    put32(Bin, At + 4, A.ArrayCount);
    unsigned Comp = componentCount(A.Type.Base);
    uint32_t Stride = elementStride(A.Type.Base);
    for (unsigned E = 0; E < A.ArrayCount; ++E)
      for (unsigned C = 0; C < Comp; ++C) {
        uint32_t Where = A.ArrayByteOffset + E * Stride + 4 * C;
        double V = A.Values[E * Comp + C];
        isIntLike(A.Type.Base) ? putInt(Bin, Where, V) : putFloat(Bin, Where, V);
      }
    return;
  }
  for (size_t C = 0; C < A.Values.size(); ++C) {
    uint32_t Where = At + 4 * static_cast<uint32_t>(C);
    isIntLike(A.Type.Base) ? putInt(Bin, Where, A.Values[C]) : putFloat(Bin, Where, A.Values[C]);
  }
}

void encodeArgsBin(CompiledGraph &CG) {
  std::vector<uint8_t> &Bin = CG.ArgsBin;
  std::fill(Bin.begin(), Bin.end(), 0);
  for (const CompiledMaterial &M : CG.Materials) {
    uint32_t W = 4 * M.ProgramWordOffset;
    put32(Bin, W, static_cast<uint32_t>(M.Program.size()));
    put32(Bin, W + 4, static_cast<uint32_t>(M.Outputs.size()));
    W += 8;
    for (const Instruction &In : M.Program) {
      put32(Bin, W, In.Quick >= 0 ? CG.Quickened[In.Quick].Opcode : CG.Nodes[In.Node].FnId);
      // Bump (Bump.h): bits 30-31 of the result word are the position offset the node runs
      // with (the interpreter's decoder; 0 in a graph without bump).
      put32(Bin, W + 4, In.ResultSlot | CG.Nodes[In.Node].PositionOffset << 30);
      put32(Bin, W + 8, In.RecordOffset);
      W += 12;
    }
    for (const MaterialOutput &O : M.Outputs) {
      put32(Bin, W, O.Slot);
      W += 4;
    }
  }
  // Every record: the primary one with the words of the node's first material, each copy with
  // the words of a material that uses it.
  ProgramSlots Slots(CG);
  for (const CompiledMaterial &M : CG.Materials) {
    const std::vector<int> &SlotOf = Slots.of(M);
    for (const Instruction &In : M.Program) {
      const CompiledNode &N = CG.Nodes[In.Node];
      encodeRecord(Bin, N, In.RecordOffset, sourceWords(CG, N, SlotOf));
    }
  }
}

} // namespace texcc::graph
