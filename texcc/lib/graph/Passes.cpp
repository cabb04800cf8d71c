// The DAG passes of compileGraph(): removal of unreached nodes, merging of identical nodes,
// function ids, DFS programs, liveness-based stack slots, the wavefront order.

#include "texcc/Graph/Passes.h"

#include "Json.h"

#include <algorithm>
#include <cstring>
#include <limits>
#include <set>

namespace texcc::graph {

namespace {

/// The distinct node arguments of a node, in argument order.
std::vector<unsigned> childrenOf(const CompiledNode &N) {
  std::vector<unsigned> C;
  for (const CompiledArg &A : N.Args)
    if (A.Src == CompiledArg::Source::Node &&
        std::find(C.begin(), C.end(), A.NodeIndex) == C.end())
      C.push_back(A.NodeIndex);
  return C;
}

/// Rewrites the graph keeping the nodes with Keep[i]; a reference to node i becomes a
/// reference to Rep[i] (itself, or the node it was merged into). Material outputs that end up
/// naming the same node are merged, and the BSDF inputs renumbered.
void compactNodes(CompiledGraph &CG, const std::vector<bool> &Keep,
                  const std::vector<unsigned> &Rep) {
  std::vector<unsigned> NewIndex(CG.Nodes.size(), 0);
  std::vector<CompiledNode> Nodes;
  for (size_t I = 0; I < CG.Nodes.size(); ++I)
    if (Keep[I]) {
      NewIndex[I] = static_cast<unsigned>(Nodes.size());
      Nodes.push_back(std::move(CG.Nodes[I]));
    }
  for (CompiledNode &N : Nodes)
    for (CompiledArg &A : N.Args)
      if (A.Src == CompiledArg::Source::Node)
        A.NodeIndex = NewIndex[Rep[A.NodeIndex]];
  CG.Nodes = std::move(Nodes);
  for (CompiledMaterial &M : CG.Materials) {
    std::vector<MaterialOutput> Outputs;
    std::vector<unsigned> OutputIndex;
    for (MaterialOutput O : M.Outputs) {
      O.Node = NewIndex[Rep[O.Node]];
      auto It = std::find_if(Outputs.begin(), Outputs.end(),
                             [&](const MaterialOutput &X) { return X.Node == O.Node; });
      OutputIndex.push_back(static_cast<unsigned>(It - Outputs.begin()));
      if (It == Outputs.end())
        Outputs.push_back(O);
    }
    M.Outputs = std::move(Outputs);
    std::vector<CompiledBsdf *> Work = {&M.Bsdf};
    while (!Work.empty()) {
      CompiledBsdf *B = Work.back();
      Work.pop_back();
      for (CompiledBsdfInput &In : B->Inputs)
        if (In.IsOutput)
          In.Output = OutputIndex[In.Output];
      for (auto &C : B->Children)
        Work.push_back(&C.second);
    }
  }
}

/// Children-first order of every node (postorder of a DFS in node order).
std::vector<unsigned> postOrder(const CompiledGraph &CG) {
  std::vector<unsigned> Order;
  std::vector<bool> Seen(CG.Nodes.size(), false);
  for (unsigned Root = 0; Root < CG.Nodes.size(); ++Root) {
    if (Seen[Root])
      continue;
    std::vector<std::pair<unsigned, size_t>> Stack = {{Root, 0}};
    Seen[Root] = true;
    while (!Stack.empty()) {
      auto &[N, Next] = Stack.back();
      const auto &Args = CG.Nodes[N].Args;
      if (Next == Args.size()) {
        Order.push_back(N);
        Stack.pop_back();
        continue;
      }
      const CompiledArg &A = Args[Next++];
      if (A.Src == CompiledArg::Source::Node && !Seen[A.NodeIndex]) {
        Seen[A.NodeIndex] = true;
        Stack.push_back({A.NodeIndex, 0});
      }
    }
  }
  return Order;
}

std::string constantKey(const CompiledArg &A) {
  std::string K;
  for (double V : A.Values) {
    char Buf[sizeof V];
    std::memcpy(Buf, &V, sizeof V);
    K.append(Buf, sizeof V);
  }
  return K + "#" + std::to_string(A.ArrayCount);
}

} // namespace

void removeUnreachableNodes(CompiledGraph &CG, std::ostream *Log) {
  std::vector<bool> Reached(CG.Nodes.size(), false);
  std::vector<unsigned> Work;
  for (const CompiledMaterial &M : CG.Materials)
    for (const MaterialOutput &O : M.Outputs)
      Work.push_back(O.Node);
  while (!Work.empty()) {
    unsigned N = Work.back();
    Work.pop_back();
    if (Reached[N])
      continue;
    Reached[N] = true;
    for (unsigned C : childrenOf(CG.Nodes[N]))
      Work.push_back(C);
  }
  std::vector<unsigned> Rep(CG.Nodes.size());
  for (size_t I = 0; I < CG.Nodes.size(); ++I) {
    Rep[I] = static_cast<unsigned>(I);
    if (!Reached[I] && Log)
      *Log << "remove-unused: removed node '" << CG.Nodes[I].Id
           << "' (no material reaches it)\n";
  }
  compactNodes(CG, Reached, Rep);
}

void mergeIdenticalNodes(CompiledGraph &CG, std::ostream *Log) {
  size_t Count = CG.Nodes.size();
  // Children first, so that a node's key names the classes of its children. A class survives
  // as its first member in file order.
  std::map<std::string, unsigned> ClassOfKey;
  std::vector<unsigned> ClassOf(Count), Survivor;
  for (unsigned N : postOrder(CG)) {
    const CompiledNode &CN = CG.Nodes[N];
    std::string Key = CN.Fn + "@" + std::to_string(CN.PositionOffset) + "(";
    for (const CompiledArg &A : CN.Args) {
      Key += A.Name + "=" + std::to_string(static_cast<int>(A.Src)) + ":" +
             (A.Broadcast ? "b" : "") + ":";
      if (A.Src == CompiledArg::Source::Node)
        Key += std::to_string(ClassOf[A.NodeIndex]);
      else if (A.Src == CompiledArg::Source::Attribute)
        Key += std::to_string(A.AttrId);
      else
        Key += constantKey(A) + (A.Bake ? "k" : "");
      Key += ";";
    }
    auto [It, Inserted] = ClassOfKey.emplace(Key, static_cast<unsigned>(Survivor.size()));
    if (Inserted)
      Survivor.push_back(N);
    ClassOf[N] = It->second;
    Survivor[It->second] = std::min(Survivor[It->second], N);
  }
  std::vector<unsigned> Rep(Count);
  for (size_t I = 0; I < Count; ++I)
    Rep[I] = Survivor[ClassOf[I]];
  std::vector<bool> Keep(Count);
  for (size_t I = 0; I < Count; ++I)
    Keep[I] = Rep[I] == I;
  for (size_t I = 0; I < Count; ++I) {
    if (Keep[I])
      continue;
    CompiledNode &Survivor = CG.Nodes[Rep[I]];
    Survivor.MergedIds.push_back(CG.Nodes[I].Id);
    for (const std::string &Id : CG.Nodes[I].MergedIds)
      Survivor.MergedIds.push_back(Id);
    if (Log)
      *Log << "merge-identical: merged node '" << CG.Nodes[I].Id << "' into '" << Survivor.Id
           << "' (same function '" << Survivor.Fn << "', same arguments)\n";
  }
  compactNodes(CG, Keep, Rep);
}

void assignFunctionIds(CompiledGraph &CG, const SignatureMap &Sigs, const CompileOptions &Opts,
                       std::ostream *Log) {
  std::map<std::string, unsigned> Ids;
  std::set<unsigned> Used;
  for (const CompiledNode &N : CG.Nodes) {
    auto Fixed = Opts.FixedFunctionIds.find(N.Fn);
    if (Fixed != Opts.FixedFunctionIds.end()) {
      Ids[N.Fn] = Fixed->second;
      Used.insert(Fixed->second);
    }
  }
  for (const auto &KV : Opts.FixedFunctionIds)
    Used.insert(KV.second);
  for (const QuickenedOp &Q : Opts.Quickened) // the kernel's quickened opcodes
    Used.insert(Q.Opcode);
  CG.Signatures.clear();
  std::set<std::string> Attributes, Settings;
  // The smallest free id: Used only grows, so the search goes on from the last one (from 0
  // every time it was quadratic in the number of functions).
  unsigned FirstFree = 0;
  for (CompiledNode &N : CG.Nodes) {
    if (!Ids.count(N.Fn)) {
      while (Used.count(FirstFree))
        ++FirstFree;
      const unsigned Id = FirstFree;
      Used.insert(Id);
      Ids[N.Fn] = Id;
      if (Log)
        *Log << "function-ids: '" << N.Fn << "' gets id " << Id << "\n";
    }
    N.FnId = Ids[N.Fn];
    auto It = Sigs.find(N.Fn);
    if (It != Sigs.end()) {
      CG.Signatures[N.Fn] = It->second;
      Attributes.insert(It->second.Attributes.begin(), It->second.Attributes.end());
      Settings.insert(It->second.Settings.begin(), It->second.Settings.end());
    }
    for (const CompiledArg &A : N.Args)
      if (A.Src == CompiledArg::Source::Attribute)
        Attributes.insert(attributeTable()[A.AttrId].first);
  }
  // The functions only dead nodes name: the interpreter has a case for them too (a rewiring
  // may make them live), so they get ids after the live ones; their attributes and settings
  // are read only once they are live.
  for (const std::string &Fn : CG.GraphFunctions) {
    auto It = Sigs.find(Fn);
    if (Ids.count(Fn) || It == Sigs.end())
      continue;
    auto Fixed = Opts.FixedFunctionIds.find(Fn);
    unsigned Id = 0;
    if (Fixed != Opts.FixedFunctionIds.end()) {
      Id = Fixed->second;
    } else {
      while (Used.count(FirstFree))
        ++FirstFree;
      Id = FirstFree;
      Used.insert(Id);
      if (Log)
        *Log << "function-ids: '" << Fn << "' gets id " << Id << " (only dead nodes name it)\n";
    }
    Ids[Fn] = Id;
    CG.Signatures[Fn] = It->second;
  }
  CG.FunctionsById.clear();
  for (const auto &[Name, Id] : Ids) {
    if (CG.FunctionsById.size() <= Id)
      CG.FunctionsById.resize(Id + 1);
    CG.FunctionsById[Id] = Name;
  }
  CG.Attributes.assign(Attributes.begin(), Attributes.end());
  CG.Settings.assign(Settings.begin(), Settings.end());
  CG.MaxOutputs = 1;
  for (const CompiledMaterial &M : CG.Materials)
    CG.MaxOutputs = std::max<unsigned>(CG.MaxOutputs, static_cast<unsigned>(M.Outputs.size()));
}

std::vector<unsigned> slotNeeds(const CompiledGraph &CG) {
  std::vector<unsigned> Need(CG.Nodes.size(), 1);
  for (unsigned N : postOrder(CG)) {
    std::vector<unsigned> C;
    for (unsigned Child : childrenOf(CG.Nodes[N]))
      C.push_back(Need[Child]);
    std::sort(C.rbegin(), C.rend());
    unsigned Max = 1;
    for (size_t I = 0; I < C.size(); ++I)
      Max = std::max<unsigned>(Max, C[I] + static_cast<unsigned>(I));
    Need[N] = Max;
  }
  return Need;
}

namespace {

/// Node indices sorted by decreasing need, stable.
std::vector<unsigned> byNeed(std::vector<unsigned> Nodes, const std::vector<unsigned> &Need) {
  std::stable_sort(Nodes.begin(), Nodes.end(),
                   [&](unsigned A, unsigned B) { return Need[A] > Need[B]; });
  return Nodes;
}

} // namespace

void orderPrograms(CompiledGraph &CG, std::ostream *Log) {
  std::vector<unsigned> Need = slotNeeds(CG);
  std::vector<std::vector<unsigned>> Children(CG.Nodes.size());
  for (size_t I = 0; I < CG.Nodes.size(); ++I)
    Children[I] = byNeed(childrenOf(CG.Nodes[I]), Need);
  // Per-node state is allocated once and reset after each material through its program (every
  // node seen is in it): per material it would cost time in nodes x materials.
  std::vector<bool> Seen(CG.Nodes.size(), false);
  for (CompiledMaterial &M : CG.Materials) {
    M.Program.clear();
    std::vector<unsigned> Roots;
    for (const MaterialOutput &O : M.Outputs)
      Roots.push_back(O.Node);
    for (unsigned Root : byNeed(Roots, Need)) {
      if (Seen[Root])
        continue;
      Seen[Root] = true;
      std::vector<std::pair<unsigned, size_t>> Stack = {{Root, 0}};
      while (!Stack.empty()) {
        auto &[N, Next] = Stack.back();
        if (Next == Children[N].size()) {
          Instruction In;
          In.Node = N;
          M.Program.push_back(In);
          if (Log)
            *Log << "order: material '" << M.Name << "': " << M.Program.size() << ". '"
                 << CG.Nodes[N].Id << "' (needs " << Need[N] << " slot"
                 << (Need[N] == 1 ? "" : "s") << ")\n";
          Stack.pop_back();
          continue;
        }
        unsigned C = Children[N][Next++];
        if (!Seen[C]) {
          Seen[C] = true;
          Stack.push_back({C, 0});
        }
      }
    }
    for (const Instruction &In : M.Program)
      Seen[In.Node] = false;
  }
}

void allocateStackSlots(CompiledGraph &CG, unsigned StackLimit, std::ostream *Log) {
  constexpr size_t Forever = std::numeric_limits<size_t>::max();
  // The slot a node got in an earlier material: reused when free, so that records (whose
  // source words name the slots of a node's children) can be shared between materials.
  std::vector<int> EarlierSlot(CG.Nodes.size(), -1);
  CG.StackSlots = 0;
  // Allocated once, reset after each material (see orderPrograms).
  std::vector<size_t> LastReader(CG.Nodes.size(), 0);
  std::vector<int> SlotOf(CG.Nodes.size(), -1);
  for (CompiledMaterial &M : CG.Materials) {
    for (size_t I = 0; I < M.Program.size(); ++I)
      for (unsigned C : childrenOf(CG.Nodes[M.Program[I].Node]))
        LastReader[C] = I;
    for (const MaterialOutput &O : M.Outputs)
      LastReader[O.Node] = Forever;
    std::set<unsigned> Free;
    unsigned Count = 0;
    for (size_t I = 0; I < M.Program.size(); ++I) {
      Instruction &In = M.Program[I];
      // Arguments are read before the result is written: their slots are free for it.
      for (unsigned C : childrenOf(CG.Nodes[In.Node]))
        if (LastReader[C] == I)
          Free.insert(static_cast<unsigned>(SlotOf[C]));
      unsigned Slot;
      int Earlier = EarlierSlot[In.Node];
      if (Earlier >= 0 && Free.count(static_cast<unsigned>(Earlier)))
        Slot = static_cast<unsigned>(Earlier);
      else if (!Free.empty())
        Slot = *Free.begin();
      else
        Slot = Count++;
      Free.erase(Slot);
      In.ResultSlot = Slot;
      SlotOf[In.Node] = static_cast<int>(Slot);
      if (EarlierSlot[In.Node] < 0)
        EarlierSlot[In.Node] = static_cast<int>(Slot);
      if (Log)
        *Log << "stack-slots: material '" << M.Name << "': '" << CG.Nodes[In.Node].Id
             << "' -> slot " << Slot << "\n";
    }
    for (MaterialOutput &O : M.Outputs) {
      O.Slot = static_cast<unsigned>(SlotOf[O.Node]);
      LastReader[O.Node] = 0;
    }
    for (const Instruction &In : M.Program) {
      SlotOf[In.Node] = -1;
      for (unsigned C : childrenOf(CG.Nodes[In.Node]))
        LastReader[C] = 0;
    }
    M.StackSlots = Count;
    CG.StackSlots = std::max(CG.StackSlots, Count);
  }
  CG.StackLimit = StackLimit;
  CG.Spill = CG.StackSlots > StackLimit;
  if (Log)
    *Log << "stack-slots: peak " << CG.StackSlots << " slot" << (CG.StackSlots == 1 ? "" : "s")
         << " over " << CG.Materials.size() << " material"
         << (CG.Materials.size() == 1 ? "" : "s") << "; limit " << StackLimit
         << (CG.Spill ? ": values spill to global memory" : ": private")
         << "\n";
}

void computeWavefrontOrder(CompiledGraph &CG, std::ostream *Log) {
  // Each program is topological and holds its nodes' children, so the first occurrences in
  // the concatenated programs are a topological order of every live node.
  CG.WavefrontOrder.clear();
  std::vector<bool> Seen(CG.Nodes.size(), false);
  for (const CompiledMaterial &M : CG.Materials)
    for (const Instruction &In : M.Program)
      if (!Seen[In.Node]) {
        Seen[In.Node] = true;
        CG.WavefrontOrder.push_back(In.Node);
        if (Log)
          *Log << "wavefront: launch " << CG.WavefrontOrder.size() - 1 << ": '"
               << CG.Nodes[In.Node].Id << "'\n";
      }
}

} // namespace texcc::graph
