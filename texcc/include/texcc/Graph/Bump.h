#ifndef TEXCC_GRAPH_BUMP_H
#define TEXCC_GRAPH_BUMP_H

// Bump, a node texcc generates (docs/graph.md "Bump"): graph.json's `bump` node (height,
// strength, distance, normal) becomes a call of texcc_bump over the height evaluated three
// times: at the hit, and with the position moved along the surface's tangent and bitangent.
// The moved evaluations are copies of the height subgraph's position-dependent nodes whose
// CompiledNode::PositionOffset is 1 or 2: before such a node runs, the generated code sets the
// position offset of the texture context (texcc_position_offset), which the WorldPos and
// ObjectPos accessors add. The copies read the same constants as the nodes they copy, so an
// edit of a height value stays an upload (GraphEditor patches every copy).

#include "texcc/Graph/Passes.h"

namespace texcc::graph {

/// The graph.json function name of the user's bump node, and texcc's built-in functions.
inline constexpr const char *BumpFunction = "bump";
inline constexpr const char *BumpEvalFunction = "texcc_bump";
inline constexpr const char *OffsetWorldPosFunction = "texcc_attr_WorldPos";
inline constexpr const char *OffsetObjectPosFunction = "texcc_attr_ObjectPos";

/// Sigs plus the signatures of the built-in functions above (no user function may take their
/// names: the user's wins, and then a bump graph does not compile).
SignatureMap withBuiltinSignatures(const SignatureMap &Sigs);

/// resolveGraph() on the user's graph (its diagnostics), then, if it has bump nodes, on the
/// graph with them expanded: the result has the copies, PositionOffset and OffsetOf set. Sigs
/// must include the built-ins.
std::optional<CompiledGraph> resolveWithBump(const Graph &G, const SignatureMap &Sigs,
                                             const CompileOptions &Opts, DiagnosticSink &Diags);

/// Whether any node runs with a moved position (the kernel then needs the offset machinery).
bool usesPositionOffset(const CompiledGraph &CG);

} // namespace texcc::graph

#endif
