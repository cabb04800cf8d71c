// --dump=graph: a Graphviz view of the compiled graph for people inspecting a kernel. Nodes show
// their function, record and argument sources/offsets; edges go from a child to the argument it
// feeds; each material is a box whose dashed edges list its program in order with the result
// stack slot, and its outputs.
#include "Emit.h"

using namespace texcc::graph;

namespace texcc::codegen {

static std::string dotEscape(const std::string &S) {
  std::string Out;
  for (char C : S) {
    if (C == '"' || C == '\\' || C == '{' || C == '}' || C == '<' || C == '>' || C == '|')
      Out += '\\';
    Out += C;
  }
  return Out;
}

static std::string argSource(const CompiledArg &A) {
  std::string S;
  switch (A.Src) {
  case CompiledArg::Source::Node:
    S = "node " + std::to_string(A.NodeIndex);
    break;
  case CompiledArg::Source::Attribute:
    S = "attr " + attributeTable().at(A.AttrId).first;
    break;
  case CompiledArg::Source::Constant:
    if (A.Type.IsGlobalArray) {
      S = "array[" + std::to_string(A.ArrayCount) + "] @" + std::to_string(A.ArrayByteOffset);
    } else {
      S = "const";
      bool IsInt = A.Type.Base == BaseType::Int || A.Type.Base == BaseType::Sampler;
      for (double V : A.Values)
        S += " " + (IsInt ? intLiteral(V) : floatLiteral(V));
    }
    break;
  }
  if (A.Broadcast)
    S += " (broadcast)";
  return S;
}

std::string generateGraphDot(const CompiledGraph &CG) {
  std::ostringstream OS;
  OS << "digraph texcc {\n"
     << "  // graph: " << CG.GraphPath << "; value stack: " << CG.StackSlots
     << " slots; spill: " << (CG.Spill ? "yes" : "no") << "\n"
     << "  rankdir=LR;\n"
     << "  node [shape=record, fontname=\"monospace\", fontsize=10];\n";
  for (unsigned I = 0; I < CG.Nodes.size(); ++I) {
    const CompiledNode &N = CG.Nodes[I];
    OS << "  n" << I << " [label=\"{" << I << ": " << dotEscape(N.Id) << " = "
       << dotEscape(N.Fn) << "() : " << spelling(N.Return) << " | fnId " << N.FnId
       << ", record @" << N.RecordOffset << " (" << N.RecordSize << " B)";
    for (size_t P = 0; P < N.Args.size(); ++P) {
      const CompiledArg &A = N.Args[P];
      OS << " | <a" << P << "> " << dotEscape(A.Name) << ": " << dotEscape(spelling(A.Type))
         << " +" << A.BlockOffset << " = " << dotEscape(argSource(A));
    }
    OS << "}\"];\n";
  }
  for (unsigned I = 0; I < CG.Nodes.size(); ++I)
    for (size_t P = 0; P < CG.Nodes[I].Args.size(); ++P)
      if (CG.Nodes[I].Args[P].Src == CompiledArg::Source::Node)
        OS << "  n" << CG.Nodes[I].Args[P].NodeIndex << " -> n" << I << ":a" << P << ";\n";
  for (const CompiledMaterial &M : CG.Materials) {
    OS << "  m" << M.Index << " [shape=box, style=bold, label=\"material " << M.Index << ": "
       << dotEscape(M.Name) << "\\nprogram @word " << M.ProgramWordOffset << ", "
       << M.StackSlots << " slots\"];\n";
    for (size_t Step = 0; Step < M.Program.size(); ++Step)
      OS << "  m" << M.Index << " -> n" << M.Program[Step].Node << " [style=dashed, label=\"#"
         << Step << " -> slot " << M.Program[Step].ResultSlot << "\"];\n";
    for (size_t K = 0; K < M.Outputs.size(); ++K)
      OS << "  n" << M.Outputs[K].Node << " -> m" << M.Index << " [color=blue, label=\"out"
         << K << " (slot " << M.Outputs[K].Slot << ")\"];\n";
  }
  OS << "}\n";
  return OS.str();
}

} // namespace texcc::codegen
