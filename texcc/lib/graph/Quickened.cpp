// Encoding with the interp kernel's quickened opcodes (docs/modes.md): an instruction whose
// function and argument sources (constant, int value, value-stack slot, which attribute,
// broadcast or not) match an entry of the table runs that entry's case, which reads every
// argument straight from where the pattern says instead of decoding the kind of each source
// word, and has int constants as literals. The table is given: the interp backend chooses it
// (texcc/lib/codegen/Quickening.cpp), a live edit takes the kernel's; encodeArgsBin writes the
// opcodes. The typed sources and their one spelling in layout.json live here.

#include "texcc/Graph/Passes.h"

#include <limits>
#include <stdexcept>
#include <map>
#include <utility>

namespace texcc::graph {

ArgumentSource argumentSource(const CompiledArg &A) {
  ArgumentSource S;
  if (A.Type.Base == BaseType::Int && !A.Type.IsGlobalArray &&
      A.Src == CompiledArg::Source::Constant && A.Values.size() == 1) {
    S.K = ArgumentSource::Kind::IntValue;
    S.Value = static_cast<int32_t>(A.Values[0]);
    return S;
  }
  const bool Decoded = !A.Type.IsGlobalArray && A.Type.Base != BaseType::Int &&
                       A.Type.Base != BaseType::Sampler;
  if (!Decoded || A.Src == CompiledArg::Source::Constant)
    return S;
  S.Broadcast = A.Broadcast;
  if (A.Src == CompiledArg::Source::Node) {
    S.K = ArgumentSource::Kind::Slot;
    return S;
  }
  S.K = ArgumentSource::Kind::Attribute;
  S.AttrId = A.AttrId;
  return S;
}

std::string spellSource(const ArgumentSource &S) {
  const std::string Broadcast = S.Broadcast ? ".x" : "";
  switch (S.K) {
  case ArgumentSource::Kind::Constant:
    return "const";
  case ArgumentSource::Kind::IntValue:
    return "int:" + std::to_string(S.Value);
  case ArgumentSource::Kind::Slot:
    return "slot" + Broadcast;
  case ArgumentSource::Kind::Attribute:
    return "attr:" + attributeTable().at(S.AttrId).first + Broadcast;
  }
  return "const";
}

bool parseSource(const std::string &Text, ArgumentSource &S) {
  S = ArgumentSource();
  if (Text == "const")
    return true;
  if (Text.rfind("int:", 0) == 0) {
    size_t End = 0;
    try {
      const long long V = std::stoll(Text.substr(4), &End);
      if (End != Text.size() - 4 || V < std::numeric_limits<int32_t>::min() ||
          V > std::numeric_limits<int32_t>::max())
        return false;
      S.K = ArgumentSource::Kind::IntValue;
      S.Value = static_cast<int32_t>(V);
      return true;
    } catch (const std::exception &) {
      return false;
    }
  }
  S.Broadcast = Text.size() > 2 && Text.compare(Text.size() - 2, 2, ".x") == 0;
  const std::string Base = S.Broadcast ? Text.substr(0, Text.size() - 2) : Text;
  if (Base == "slot") {
    S.K = ArgumentSource::Kind::Slot;
    return true;
  }
  if (Base.rfind("attr:", 0) == 0 && attributeId(Base.substr(5)) >= 0) {
    S.K = ArgumentSource::Kind::Attribute;
    S.AttrId = attributeId(Base.substr(5));
    return true;
  }
  return false;
}

namespace {

/// A pattern without its opcode, as a map key: patterns are looked up once per instruction (a
/// scan of the patterns seen so far was quadratic in the number of distinct functions).
using PatternKey = std::pair<std::string, std::vector<ArgumentSource>>;
PatternKey keyOf(const QuickenedOp &Q) { return {Q.Fn, Q.Sources}; }

std::string describe(const QuickenedOp &Q) {
  std::string S = "'" + Q.Fn + "' (";
  for (size_t P = 0; P < Q.Sources.size(); ++P)
    S += (P ? ", " : "") + spellSource(Q.Sources[P]);
  return S + ")";
}

} // namespace

QuickenedOp instructionPattern(const CompiledGraph &CG, const CompiledMaterial &M, size_t J) {
  QuickenedOp P;
  const CompiledNode &N = CG.Nodes[M.Program[J].Node];
  P.Fn = N.Fn;
  for (const CompiledArg &A : N.Args)
    P.Sources.push_back(argumentSource(A));
  return P;
}

void applyQuickened(CompiledGraph &CG, std::vector<QuickenedOp> Table, std::ostream *Log) {
  std::vector<unsigned> Uses(Table.size(), 0);
  std::map<PatternKey, size_t> TableIndex; // the first entry of each pattern
  for (size_t K = 0; K < Table.size(); ++K)
    TableIndex.emplace(keyOf(Table[K]), K);
  for (CompiledMaterial &M : CG.Materials)
    for (size_t J = 0; J < M.Program.size(); ++J) {
      Instruction &In = M.Program[J];
      In.Quick = -1;
      auto It = TableIndex.find(keyOf(instructionPattern(CG, M, J)));
      if (It != TableIndex.end()) {
        In.Quick = static_cast<int>(It->second);
        ++Uses[In.Quick];
      }
    }
  CG.Quickened = std::move(Table);
  if (!Log)
    return;
  for (size_t K = 0; K < CG.Quickened.size(); ++K)
    *Log << "quickened: opcode " << CG.Quickened[K].Opcode << ": " << describe(CG.Quickened[K])
         << ", " << Uses[K] << " instruction" << (Uses[K] == 1 ? "" : "s") << "\n";
}

} // namespace texcc::graph
