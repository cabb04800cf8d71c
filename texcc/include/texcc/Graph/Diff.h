#ifndef TEXCC_GRAPH_DIFF_H
#define TEXCC_GRAPH_DIFF_H

// Edits of a graph as data. An Edit gives one node argument a new value (a constant, or a
// reference to a node's output, an attribute or an image); diff() says which edits take one
// graph to another, applyEdit() applies one to the model. texrender's live session turns a
// saved graph.json into these edits and its control channel's lines parse into them; the
// GraphEditor (Edit.h) validates and applies them to the compiled graph.

#include "texcc/Graph/Graph.h"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace texcc::graph {

struct Edit {
  enum class Kind {
    /// NODE.ARG takes Value as written ({"node": n} and {"attr": a} included); a new constant
    /// of a baked argument stays baked.
    Set,
    /// NODE.ARG reads the output of node Value.Ref (Value is a NodeRef).
    Rewire,
  };
  Kind K = Kind::Set;
  std::string Node, Arg;
  ArgValue Value;
};

/// The rewiring of NODE.ARG onto the output of node Source.
Edit rewireEdit(std::string Node, std::string Arg, std::string Source);

/// The edit as a line of texrender's edit syntax: "set NODE.ARG=VALUE" (VALUE as graph.json
/// writes it, compact) or "rewire NODE.ARG=SOURCE".
std::string editText(const Edit &E);

/// Applies E to the model G, without the signatures' checks (GraphEditor::apply makes them):
/// the argument is replaced, or added after the node's others. False, G unchanged and Why
/// said, when G has no node E.Node.
bool applyEdit(Graph &G, const Edit &E, std::string &Why);

/// The edits that take Old to New, in New's node and argument order, when the two differ in
/// node arguments only: a new value, a reference to another node, attribute or image, a
/// reference back to a constant, an argument added. Locations and the order of a node's
/// arguments are not differences. Anything else needs texcc and is refused: std::nullopt,
/// with the first such difference in Why (a node added, removed, reordered or given another
/// function, an argument removed, an argument baked or unbaked, the sources, the images or
/// the materials changed).
std::optional<std::vector<Edit>> diff(const Graph &Old, const Graph &New, std::string &Why);

/// Whether A and B are the same graph (diff finds no difference).
bool sameGraph(const Graph &A, const Graph &B);

/// A number, a vector or an array (not a reference to a node, an attribute or an image).
bool isConstant(const ArgValue &A);

/// Whether two argument values are equal (kind, numbers bit for bit as parsed, integer-ness,
/// rows, reference, a constant's bake); locations aside.
bool sameValue(const ArgValue &A, const ArgValue &B);

/// An argument as graph.json writes it: numbers as parsed (an integer stays an integer, a
/// double round-trips exactly), {"node"|"attr"|"image": ref}, a baked constant as
/// {"value": v, "bake": true}.
nlohmann::ordered_json argumentJson(const ArgValue &A);

/// The graph.json text of G: keys in the model's order (texcc numbers the materials in the
/// order graph.json lists them). Parsing the result gives G again (locations aside).
nlohmann::ordered_json graphJson(const Graph &G);

} // namespace texcc::graph

#endif
