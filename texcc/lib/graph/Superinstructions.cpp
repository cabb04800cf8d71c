// Superinstructions of the interp kernel (docs/modes.md): fused pairs F -> G.p of adjacent
// instructions, chosen from the pairs the programs contain (texcc) or taken from the kernel's
// table (live edits), and marked on the programs; encodeArgsBin writes their opcodes.

#include "texcc/Graph/Passes.h"

#include <algorithm>
#include <map>
#include <tuple>
#include <unordered_map>

namespace texcc::graph {

namespace {

using Pattern = std::tuple<std::string, std::string, unsigned>; // First, Second, Param

/// How many times a node is read in one material (only the nodes it reads: a vector over every
/// node per material was quadratic memory, 1.65 GB for 20,000 materials).
using ReaderCounts = std::unordered_map<unsigned, unsigned>;

/// How many times each node is read in M: by arguments of M's instructions and as an output.
ReaderCounts readers(const CompiledGraph &CG, const CompiledMaterial &M) {
  ReaderCounts Count;
  for (const Instruction &In : M.Program)
    for (const CompiledArg &A : CG.Nodes[In.Node].Args)
      if (A.Src == CompiledArg::Source::Node)
        ++Count[A.NodeIndex];
  for (const MaterialOutput &O : M.Outputs)
    ++Count[O.Node];
  return Count;
}

bool isLight(const CompiledGraph &CG, const std::string &Fn, unsigned LightCost) {
  auto It = CG.Signatures.find(Fn);
  return It != CG.Signatures.end() && It->second.Cost >= 1 && It->second.Cost <= LightCost;
}

/// The parameter of instruction J+1 that reads instruction J's result, when that is its only
/// reader in M (Readers: readers()); the pair can then run as one superinstruction.
std::optional<unsigned> fusedParam(const CompiledGraph &CG, const CompiledMaterial &M,
                                   size_t J, const ReaderCounts &Readers) {
  if (J + 1 >= M.Program.size())
    return std::nullopt;
  unsigned First = M.Program[J].Node;
  auto Read = Readers.find(First);
  if (Read == Readers.end() || Read->second != 1)
    return std::nullopt;
  const CompiledNode &Second = CG.Nodes[M.Program[J + 1].Node];
  for (size_t P = 0; P < Second.Args.size(); ++P) {
    const CompiledArg &A = Second.Args[P];
    if (A.Src == CompiledArg::Source::Node && A.NodeIndex == First)
      return static_cast<unsigned>(P);
  }
  return std::nullopt;
}

} // namespace

std::string fedParamName(const CompiledGraph &CG, const Superinstruction &S) {
  auto It = CG.Signatures.find(S.Second);
  if (It == CG.Signatures.end() || S.Param >= It->second.Params.size())
    return "";
  return It->second.Params[S.Param].Name;
}

void selectSuperinstructions(CompiledGraph &CG, const CompileOptions &Opts, std::ostream *Log) {
  std::vector<ReaderCounts> Readers;
  for (const CompiledMaterial &M : CG.Materials)
    Readers.push_back(readers(CG, M));
  auto PatternAt = [&](size_t MI, size_t J) -> std::optional<Pattern> {
    const CompiledMaterial &M = CG.Materials[MI];
    std::optional<unsigned> P = fusedParam(CG, M, J, Readers[MI]);
    if (!P)
      return std::nullopt;
    return Pattern{CG.Nodes[M.Program[J].Node].Fn, CG.Nodes[M.Program[J + 1].Node].Fn, *P};
  };

  std::vector<Superinstruction> Table = Opts.Superinstructions;
  const bool Choose = Table.empty() && Opts.MaxSuperinstructions > 0;
  if (Choose) {
    // Every adjacent fusable pair of two light functions, counted over all programs.
    std::map<Pattern, unsigned> Count;
    for (size_t MI = 0; MI < CG.Materials.size(); ++MI)
      for (size_t J = 0; J + 1 < CG.Materials[MI].Program.size(); ++J)
        if (std::optional<Pattern> P = PatternAt(MI, J))
          if (isLight(CG, std::get<0>(*P), Opts.LightCost) &&
              isLight(CG, std::get<1>(*P), Opts.LightCost))
            ++Count[*P];
    std::vector<std::pair<Pattern, unsigned>> Ranked(Count.begin(), Count.end());
    std::stable_sort(Ranked.begin(), Ranked.end(),
                     [](const auto &A, const auto &B) { return A.second > B.second; });
    if (Ranked.size() > Opts.MaxSuperinstructions)
      Ranked.resize(Opts.MaxSuperinstructions);
    for (const auto &[P, N] : Ranked) {
      (void)N;
      Superinstruction S;
      S.First = std::get<0>(P);
      S.Second = std::get<1>(P);
      S.Param = std::get<2>(P);
      Table.push_back(S);
    }
  }

  // Non-overlapping, greedy along each program: a pair in the table is fused unless its first
  // instruction is already the second half of the pair before.
  auto Apply = [&](const std::vector<Superinstruction> &T) {
    std::vector<unsigned> Uses(T.size(), 0);
    for (size_t MI = 0; MI < CG.Materials.size(); ++MI) {
      std::vector<Instruction> &Program = CG.Materials[MI].Program;
      for (Instruction &In : Program)
        In.Super = -1;
      for (size_t J = 0; J + 1 < Program.size(); ++J) {
        std::optional<Pattern> P = PatternAt(MI, J);
        if (!P)
          continue;
        auto It = std::find_if(T.begin(), T.end(), [&](const Superinstruction &S) {
          return Pattern{S.First, S.Second, S.Param} == *P;
        });
        if (It == T.end())
          continue;
        Program[J].Super = static_cast<int>(It - T.begin());
        ++Uses[Program[J].Super];
        ++J; // the second instruction runs inside the superinstruction
      }
    }
    return Uses;
  };
  std::vector<unsigned> Uses = Apply(Table);
  if (Choose) {
    // A chosen pair that every occurrence lost to an overlapping one would be a dead case in
    // the kernel: drop it (the others' decisions do not depend on it) and number the rest.
    std::vector<Superinstruction> Kept;
    for (size_t K = 0; K < Table.size(); ++K)
      if (Uses[K]) {
        Table[K].Opcode = static_cast<unsigned>(CG.FunctionsById.size() + Kept.size());
        Kept.push_back(Table[K]);
      }
    Table = std::move(Kept);
    Uses = Apply(Table);
  }
  CG.Superinstructions = Table;
  if (!Log)
    return;
  for (size_t K = 0; K < Table.size(); ++K) {
    const Superinstruction &S = Table[K];
    *Log << "superinstructions: opcode " << S.Opcode << ": '" << S.First << "' -> '" << S.Second
         << "." << fedParamName(CG, S) << "', fused " << Uses[K] << " time" << (Uses[K] == 1 ? "" : "s")
         << "\n";
  }
  for (const CompiledMaterial &M : CG.Materials)
    for (size_t J = 0; J < M.Program.size(); ++J)
      if (M.Program[J].Super >= 0)
        *Log << "superinstructions: material '" << M.Name << "': #" << J << " '"
             << CG.Nodes[M.Program[J].Node].Id << "' -> #" << J + 1 << " '"
             << CG.Nodes[M.Program[J + 1].Node].Id << "' run as opcode "
             << Table[M.Program[J].Super].Opcode << "\n";
}

} // namespace texcc::graph
