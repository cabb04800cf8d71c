// Quickened opcodes of the interp kernel (docs/modes.md): an instruction whose function and
// argument sources (constant, value-stack slot, which attribute, broadcast or not) match an
// entry of the table runs that entry's case, which reads every argument straight from where
// the pattern says instead of decoding the kind of each source word. Chosen from the patterns
// the programs contain (texcc) or taken from the kernel's table (live edits); encodeArgsBin
// writes their opcodes.

#include "texcc/Graph/Passes.h"

#include <algorithm>
#include <map>

namespace texcc::graph {

std::string argumentSource(const CompiledArg &A) {
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

using Pattern = std::pair<std::string, std::vector<std::string>>; // function, sources

Pattern patternOf(const CompiledNode &N) {
  Pattern P{N.Fn, {}};
  for (const CompiledArg &A : N.Args)
    P.second.push_back(argumentSource(A));
  return P;
}

/// Whether instruction J is one half of a superinstruction: its first (the opcode is the
/// superinstruction's) or its second (skipped: the superinstruction's case runs it).
bool runsInSuperinstruction(const CompiledMaterial &M, size_t J) {
  return M.Program[J].Super >= 0 || (J > 0 && M.Program[J - 1].Super >= 0);
}

} // namespace

void selectQuickened(CompiledGraph &CG, const CompileOptions &Opts, std::ostream *Log) {
  std::vector<QuickenedOp> Table = Opts.Quickened;
  if (Table.empty() && Opts.MaxQuickened > 0) {
    // Every pattern of an instruction that runs its own case, counted over all programs;
    // ties in order of first occurrence.
    std::map<Pattern, unsigned> Count;
    std::vector<Pattern> Order;
    for (const CompiledMaterial &M : CG.Materials)
      for (size_t J = 0; J < M.Program.size(); ++J) {
        if (runsInSuperinstruction(M, J))
          continue;
        Pattern P = patternOf(CG.Nodes[M.Program[J].Node]);
        if (Count[P]++ == 0)
          Order.push_back(P);
      }
    std::stable_sort(Order.begin(), Order.end(), [&](const Pattern &A, const Pattern &B) {
      return Count[A] > Count[B];
    });
    if (Order.size() > Opts.MaxQuickened)
      Order.resize(Opts.MaxQuickened);
    const unsigned First =
        static_cast<unsigned>(CG.FunctionsById.size() + CG.Superinstructions.size());
    for (const Pattern &P : Order) {
      QuickenedOp Q;
      Q.Opcode = First + static_cast<unsigned>(Table.size());
      Q.Fn = P.first;
      Q.Sources = P.second;
      Table.push_back(Q);
    }
  }
  std::vector<unsigned> Uses(Table.size(), 0);
  for (CompiledMaterial &M : CG.Materials)
    for (size_t J = 0; J < M.Program.size(); ++J) {
      Instruction &In = M.Program[J];
      In.Quick = -1;
      if (runsInSuperinstruction(M, J))
        continue;
      const Pattern P = patternOf(CG.Nodes[In.Node]);
      auto It = std::find_if(Table.begin(), Table.end(), [&](const QuickenedOp &Q) {
        return Q.Fn == P.first && Q.Sources == P.second;
      });
      if (It != Table.end()) {
        In.Quick = static_cast<int>(It - Table.begin());
        ++Uses[In.Quick];
      }
    }
  CG.Quickened = Table;
  if (!Log)
    return;
  for (size_t K = 0; K < Table.size(); ++K) {
    *Log << "quickened: opcode " << Table[K].Opcode << ": '" << Table[K].Fn << "' (";
    for (size_t P = 0; P < Table[K].Sources.size(); ++P)
      *Log << (P ? ", " : "") << Table[K].Sources[P];
    *Log << "), " << Uses[K] << " instruction" << (Uses[K] == 1 ? "" : "s") << "\n";
  }
}

} // namespace texcc::graph
