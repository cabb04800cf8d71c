// Quickened opcodes of the interp kernel (docs/modes.md): an instruction whose function and argument sources (constant, int value, value-stack slot, which
// attribute, broadcast or not) match an entry of the table runs that entry's case, which reads
// every argument straight from where the pattern says instead of decoding the kind of each
// source word, and has int constants as literals. Chosen from the patterns
// the programs contain (texcc) or taken from the kernel's table (live edits); encodeArgsBin
// writes their opcodes.

#include "texcc/Graph/Passes.h"

#include <algorithm>
#include <map>
#include <utility>

namespace texcc::graph {

std::string argumentSource(const CompiledArg &A) {
  if (A.Type.Base == BaseType::Int && !A.Type.IsGlobalArray &&
      A.Src == CompiledArg::Source::Constant && A.Values.size() == 1)
    return "int:" + std::to_string(static_cast<long long>(A.Values[0]));
  const bool Decoded = !A.Type.IsGlobalArray && A.Type.Base != BaseType::Int &&
                       A.Type.Base != BaseType::Sampler;
  if (!Decoded || A.Src == CompiledArg::Source::Constant)
    return "const";
  const std::string Broadcast = A.Broadcast ? ".x" : "";
  if (A.Src == CompiledArg::Source::Node)
    return "slot" + Broadcast;
  return "attr:" + attributeTable().at(A.AttrId).first + Broadcast;
}

namespace {

std::vector<std::string> sourcesOf(const CompiledNode &N) {
  std::vector<std::string> S;
  for (const CompiledArg &A : N.Args)
    S.push_back(argumentSource(A));
  return S;
}

/// The pattern instruction J of M runs: its function and sources. Opcode unset.
QuickenedOp patternAt(const CompiledGraph &CG, const CompiledMaterial &M, size_t J) {
  QuickenedOp P;
  const CompiledNode &N = CG.Nodes[M.Program[J].Node];
  P.Fn = N.Fn;
  P.Sources = sourcesOf(N);
  return P;
}

/// A pattern without its opcode, as a map key: patterns are looked up once per instruction (a
/// scan of the patterns seen so far was quadratic in the number of distinct functions).
using PatternKey = std::pair<std::string, std::vector<std::string>>;
PatternKey keyOf(const QuickenedOp &Q) { return {Q.Fn, Q.Sources}; }

std::string describe(const QuickenedOp &Q) {
  std::string S = "'" + Q.Fn + "' (";
  for (size_t P = 0; P < Q.Sources.size(); ++P)
    S += (P ? ", " : "") + Q.Sources[P];
  return S + ")";
}

} // namespace

void selectQuickened(CompiledGraph &CG, const CompileOptions &Opts, std::ostream *Log) {
  std::vector<QuickenedOp> Table = Opts.Quickened;
  if (Table.empty() && Opts.MaxQuickened > 0) {
    // Every instruction's pattern, counted over all programs; ties in order of first
    // occurrence.
    std::vector<QuickenedOp> Order;
    std::vector<unsigned> Count;
    std::map<PatternKey, size_t> IndexOf;
    for (const CompiledMaterial &M : CG.Materials)
      for (size_t J = 0; J < M.Program.size(); ++J) {
        QuickenedOp P = patternAt(CG, M, J);
        auto [It, New] = IndexOf.emplace(keyOf(P), Order.size());
        if (New) {
          Order.push_back(std::move(P));
          Count.push_back(1);
        } else {
          ++Count[It->second];
        }
      }
    std::vector<size_t> Rank(Order.size());
    for (size_t K = 0; K < Rank.size(); ++K)
      Rank[K] = K;
    std::stable_sort(Rank.begin(), Rank.end(),
                     [&](size_t A, size_t B) { return Count[A] > Count[B]; });
    if (Rank.size() > Opts.MaxQuickened)
      Rank.resize(Opts.MaxQuickened);
    const unsigned First = static_cast<unsigned>(CG.FunctionsById.size());
    for (size_t K : Rank) {
      QuickenedOp Q = Order[K];
      Q.Opcode = First + static_cast<unsigned>(Table.size());
      Table.push_back(Q);
    }
  }
  std::vector<unsigned> Uses(Table.size(), 0);
  std::map<PatternKey, size_t> TableIndex; // the first entry of each pattern
  for (size_t K = 0; K < Table.size(); ++K)
    TableIndex.emplace(keyOf(Table[K]), K);
  for (CompiledMaterial &M : CG.Materials)
    for (size_t J = 0; J < M.Program.size(); ++J) {
      Instruction &In = M.Program[J];
      In.Quick = -1;
      auto It = TableIndex.find(keyOf(patternAt(CG, M, J)));
      if (It != TableIndex.end()) {
        In.Quick = static_cast<int>(It->second);
        ++Uses[In.Quick];
      }
    }
  CG.Quickened = Table;
  if (!Log)
    return;
  for (size_t K = 0; K < Table.size(); ++K)
    *Log << "quickened: opcode " << Table[K].Opcode << ": " << describe(Table[K]) << ", "
         << Uses[K] << " instruction" << (Uses[K] == 1 ? "" : "s") << "\n";
}

} // namespace texcc::graph
