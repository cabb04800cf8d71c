// The interp backend's quickened-opcode table: the most frequent instruction patterns.
#include "texcc/Codegen/Quickening.h"

#include "texcc/Graph/Passes.h"

#include <algorithm>
#include <map>
#include <utility>

namespace texcc::codegen {

std::vector<graph::QuickenedOp> chooseQuickened(const graph::CompiledGraph &CG, unsigned Max) {
  if (Max == 0)
    return {};
  // Every instruction's pattern, counted over all programs; ties in order of first occurrence.
  // A map from pattern to its index: a scan of the patterns seen so far was quadratic in the
  // number of distinct functions.
  using Key = std::pair<std::string, std::vector<graph::ArgumentSource>>;
  std::vector<graph::QuickenedOp> Order;
  std::vector<unsigned> Count;
  std::map<Key, size_t> IndexOf;
  for (const graph::CompiledMaterial &M : CG.Materials)
    for (size_t J = 0; J < M.Program.size(); ++J) {
      graph::QuickenedOp P = graph::instructionPattern(CG, M, J);
      auto [It, New] = IndexOf.emplace(Key{P.Fn, P.Sources}, Order.size());
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
  if (Rank.size() > Max)
    Rank.resize(Max);
  std::vector<graph::QuickenedOp> Table;
  const unsigned First = static_cast<unsigned>(CG.FunctionsById.size());
  for (size_t K : Rank) {
    graph::QuickenedOp Q = Order[K];
    Q.Opcode = First + static_cast<unsigned>(Table.size());
    Table.push_back(std::move(Q));
  }
  return Table;
}

} // namespace texcc::codegen
