#ifndef TEXCC_GRAPH_GRAPH_H
#define TEXCC_GRAPH_GRAPH_H

// The graph.json (version 1) model, as parsed: nodes, their arguments, materials (BSDF trees).
// Every element keeps its JSON path and line:col for diagnostics.

#include "texcc/Graph/Diagnostics.h"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace texcc::graph {

/// One argument of a node, or one input of a BSDF, as written in graph.json.
struct ArgValue {
  enum class Kind {
    Number,      // 4.0, 6
    Vector,      // [0.7, 0.7, 0.7]       (2..4 numbers)
    Array,       // [[0.0, ...], [...]] or [1, 2, 3] for a __global const T* parameter
    NodeRef,     // { "node": "n" }
    AttrRef,     // { "attr": "AO" }
    ImageRef,    // { "image": "brick" }
  };
  Kind K = Kind::Number;
  std::vector<double> Numbers;              // Number (1 element), Vector, flat Array
  std::vector<std::vector<double>> Rows;    // Array of arrays (each row one element)
  bool IsArrayOfRows = false;
  bool IsInteger = false;                   // Number written without fraction/exponent
  /// `{"value": 3, "bake": true}` or `texcc --bake NODE.ARG`: shape (and inline) code has the
  /// value as a literal and it is part of the material's shape; interp still reads args.bin.
  bool Bake = false;
  std::string Ref;                          // NodeRef / AttrRef / ImageRef target
  SourceLoc Loc;                            // where the value starts
  std::string JsonPath;                     // e.g. "/nodes/1/args/stops"
  SourceLoc KeyLoc;                         // where its key ("stops") starts
};

struct Node {
  std::string Id;
  std::string Fn;                           // user function name (before renaming)
  std::vector<std::pair<std::string, ArgValue>> Args;  // in file order
  SourceLoc Loc;
  std::string JsonPath;                     // "/nodes/3"
  SourceLoc IdLoc;                          // the "id" value
  SourceLoc FnLoc;                          // the "fn" value
};

/// A BSDF tree node: "diffuse" {color}, "glossy" {color, roughness}, "mirror" {color},
/// "emission" {color, strength}, "principled" {baseColor, metallic, roughness, specular,
/// emissionColor, emissionStrength}, "blend" {mask, a, b}; every scattering one takes an
/// optional "normal". Inputs are constants or node refs.
struct Bsdf {
  std::string Type;
  std::vector<std::pair<std::string, ArgValue>> Inputs;  // color, roughness, mask, strength...
  std::vector<std::pair<std::string, Bsdf>> Children;    // blend: a, b
  SourceLoc Loc;
  std::string JsonPath;
};

struct Material {
  std::string Name;
  Bsdf Root;
  SourceLoc Loc;                             // the material's key in "materials"
};

/// The colour spaces an image may be read in, as Blender names them: "sRGB", "Linear Rec.709",
/// "Non-Color" (graph.md "Images").
const std::vector<std::string> &imageColorSpaces();

struct Graph {
  std::string Path;                          // graph.json as given (for diagnostics)
  std::vector<std::string> Sources;          // "sources", relative to the graph's folder
  std::vector<std::pair<std::string, std::string>> Images;  // name -> path, file order
  /// name -> colour space, for the images written as {"path", "colorspace"} with one (absent:
  /// the file's default, sRGB for 8- and 16-bit files, linear for float ones).
  std::map<std::string, std::string> ImageColorSpaces;
  std::vector<Node> Nodes;                   // file order
  std::vector<Material> Materials;           // file order

  const Node *findNode(const std::string &Id) const;
  Node *findNode(const std::string &Id);
};

/// The inputs each BSDF type takes, in canonical order ("blend": mask, a, b). Empty for an
/// unknown type.
const std::vector<std::string> &bsdfInputs(const std::string &Type);
/// Every BSDF type: diffuse, glossy, mirror, emission, principled, blend.
const std::vector<std::string> &bsdfTypes();
/// Whether a BSDF may leave this input out ("normal" everywhere; every principled input).
bool bsdfInputOptional(const std::string &Type, const std::string &Input);
/// Whether the input is a float3 (color, baseColor, emissionColor, normal); the others: float.
bool bsdfInputIsVector(const std::string &Input);

/// Parses one argument value written as JSON text ("0.5", "[1,0,0]", "[[0,1],[1,2]]",
/// "{\"node\": \"n\"}"), as the live-edit API receives it. Reports errors against File.
std::optional<ArgValue> parseArgValue(const std::string &File, const std::string &Text,
                                      DiagnosticSink &Diags);

/// Marks the constant argument ARG of node NODE as baked (`texcc --bake NODE.ARG`; the node id
/// is everything before the last '.'). On an unknown node or argument, or an argument that is
/// not a number or a vector, returns false and says why in Error.
bool markBaked(Graph &G, const std::string &NodeDotArg, std::string &Error);

/// Parses graph.json text. Reports malformed JSON (with line:col), wrong value kinds, unknown
/// keys, duplicate ids, unknown BSDF types and inputs. Returns std::nullopt on any error.
/// Does not need function signatures; see validateGraph() for checks that do.
std::optional<Graph> parseGraph(const std::string &Path, const std::string &Text,
                                DiagnosticSink &Diags);

} // namespace texcc::graph

#endif
