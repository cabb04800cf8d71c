#ifndef TEXCC_GRAPH_EDIT_H
#define TEXCC_GRAPH_EDIT_H

// Live edits without the compiler: change an argument's value or rewire a node input, and get
// the re-encoded args.bin (and programs). The runtime's --set and interactive mode use this.

#include "texcc/Graph/Compile.h"
#include "texcc/Graph/Diff.h"

#include <string>

namespace texcc::graph {

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

  /// Validates E against the signatures and applies it (setArgument or rewire). On a refusal
  /// (Diags says why) the graph and the compiled graph are unchanged: an edit is validated
  /// once, by the apply that makes it.
  bool apply(const Edit &E, DiagnosticSink &Diags);

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
  bool recompile(DiagnosticSink &Diags);

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
};

} // namespace texcc::graph

#endif
