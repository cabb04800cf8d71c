#ifndef TEXCC_GRAPH_EDIT_H
#define TEXCC_GRAPH_EDIT_H

// Live edits without the compiler: change an argument's value or rewire a node input, and get
// the re-encoded args.bin (and programs). The runtime's --set and interactive mode use this.

#include "texcc/Graph/Compile.h"
#include "texcc/Graph/Diff.h"

#include <cstdint>
#include <optional>
#include <string>

namespace texcc::graph {

/// An edit that GraphEditor::check validated against one state of the graph: the graph with
/// the edit and its resolution against the kernel's signatures (resolveWithBump), which is all
/// that applying it needs. Only check() makes one; GraphEditor::apply(CheckedEdit &&) encodes
/// it without validating it again.
class CheckedEdit {
public:
  Edit::Kind kind() const { return K; }
  const std::string &node() const { return NodeId; }
  const std::string &arg() const { return Arg; }
  /// The graph with the edit: the one the next edit of a sequence is checked against.
  const Graph &graph() const { return Edited; }
  /// The typed edit again, its value as graph() has it.
  Edit edit() const;

private:
  friend class GraphEditor;
  CheckedEdit() = default;
  Edit::Kind K = Edit::Kind::Set;
  std::string NodeId, Arg;
  Graph Edited;
  CompiledGraph Resolved;
  // The editor's graph states (GraphEditor::State) the edit was checked against and leads to.
  uint64_t Base = 0, Result = 0;
};

class GraphEditor {
public:
  /// Takes the graph and the signatures of the kernel's functions; FnIds pins the ids the
  /// kernel was generated with.
  GraphEditor(Graph G, SignatureMap Sigs, CompileOptions Opts);

  /// Compiles the initial graph. False (with Diags filled) on error.
  bool init(DiagnosticSink &Diags);

  /// Sets NODE.ARG to a constant given as text ("0.5", "[1,0,0]", "3", "[[0,1,0,0,1],...]").
  /// When the layout does not change, only the bytes of that argument change in args.bin.
  bool setArgument(const std::string &NodeId, const std::string &Arg, const std::string &Value,
                   DiagnosticSink &Diags);
  /// The same with the value parsed (a reference included).
  bool setArgument(const std::string &NodeId, const std::string &Arg, ArgValue Value,
                   DiagnosticSink &Diags);
  /// Makes NODE.ARG read the output of another node ({ "node": Source }).
  bool rewire(const std::string &NodeId, const std::string &Arg, const std::string &SourceNode,
              DiagnosticSink &Diags);

  /// Validates E against the signatures and applies it (check, then apply(CheckedEdit &&)). On
  /// a refusal (Diags says why) the graph and the compiled graph are unchanged.
  bool apply(const Edit &E, DiagnosticSink &Diags);

  /// Validates E against the graph as it is now, the one validation an edit gets: the edited
  /// graph resolved against the signatures (an unknown node or argument, a value of the wrong
  /// type or size, a cycle ...). std::nullopt when it is refused (Diags says why). Changes
  /// nothing.
  std::optional<CheckedEdit> check(const Edit &E, DiagnosticSink &Diags) const;
  /// The same against the graph as After leaves it: a sequence is checked whole, each edit
  /// against the one before, before any of it is applied (texrender's --set and edit script).
  std::optional<CheckedEdit> check(const CheckedEdit &After, const Edit &E,
                                   DiagnosticSink &Diags) const;
  /// Applies C without validating it: its argument's bytes patched in args.bin when the
  /// argument keeps its layout, else the passes run on C's resolution (compileResolved).
  /// False, with C and the editor unchanged, when C was checked against another state of the
  /// graph (the edits of a sequence apply in their order).
  bool apply(CheckedEdit &&C);
  /// Takes Old's graph state, so that edits checked against Old apply here without being
  /// validated again, when this editor validates alike: the same graph, and the same return
  /// and parameters for every function its nodes name (a regenerated kernel of the same
  /// sources). False, and nothing taken, otherwise.
  bool continueFrom(const GraphEditor &Old);
  /// How many edits check() has validated in this process (the live path's tests count them).
  static uint64_t validations();

  const CompiledGraph &compiled() const { return CG; }
  const Graph &graph() const { return G; }
  /// True when the last edit needs a kernel the current one cannot run (a function not in
  /// the kernel, more stack slots than TEXCC_STACK_SLOTS, more outputs than TEXCC_MAX_OUTPUTS,
  /// or needsAttributeCase()).
  bool needsRebuild() const { return NeedsRebuild; }
  /// True when the only reason for needsRebuild() is a value stack deeper than the kernel's
  /// (a kernel built with headroom may still run the edited graph).
  bool needsOnlyStackSlots() const { return NeedsRebuild && !NeedsCode; }
  /// True when the last edit made a node argument read an attribute that no node argument of
  /// the initial graph read (`set n.p={"attr": "Normal"}`): the interpreter's attribute
  /// decoder has no case for it.
  bool needsAttributeCase() const { return NeedsAttributeCase; }
  /// True when the last edit made a node of a function the kernel has no case for live (not
  /// one of the pinned function ids): no kernel of this graph, fallback included, runs it.
  bool needsFunction() const { return NeedsFunction; }

private:
  std::optional<CheckedEdit> checkAgainst(const Graph &Base, uint64_t BaseState, const Edit &E,
                                          DiagnosticSink &Diags) const;
  /// The fast path of a set: C's new constant patched into args.bin where the argument is a
  /// constant of a live, unmerged node and keeps its size. False when it cannot be.
  bool patchInPlace(const CheckedEdit &C);
  void recompile(CompiledGraph Resolved);

  Graph G;
  SignatureMap Sigs;
  CompileOptions Opts;
  CompiledGraph CG;
  unsigned KernelStackSlots = 0;
  unsigned KernelMaxOutputs = 0;
  std::vector<int> KernelArgumentAttributes; // sorted: the interpreter's attribute decoder
  bool NeedsRebuild = false;
  bool NeedsCode = false;    // a reason other than value-stack slots
  bool NeedsAttributeCase = false;
  bool NeedsFunction = false;
  // Which state of the graph this is (a number no other state of any editor has; a copy of
  // the editor shares it): a checked edit applies only to the state it was checked against.
  uint64_t State;
};

} // namespace texcc::graph

#endif
