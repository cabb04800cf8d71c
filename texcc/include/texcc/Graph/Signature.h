#ifndef TEXCC_GRAPH_SIGNATURE_H
#define TEXCC_GRAPH_SIGNATURE_H

// What the graph library needs to know of a user texture function. The front end fills these
// from the user's code; the runtime reads them back from layout.json for live edits.

#include "texcc/Graph/Diagnostics.h"
#include "texcc/Graph/Types.h"

#include <map>
#include <string>
#include <vector>

namespace texcc::graph {

struct Param {
  std::string Name;
  ValueType Type;
};

/// A local of a texture function that depends on constant parameters only: a declaration at
/// the top level of its body whose initializer reads parameters that the body never changes
/// (HoistedFrom) and calls only OpenCL builtins (frontend.md, "Hoisting"). Where a node binds
/// every one of those parameters to a constant, shape code computes it once per material
/// (kernel texcc_uniforms) into the node's parameter block, after the parameters, instead of
/// once per hit.
struct HoistedValue {
  std::string Name;
  BaseType Type = BaseType::Float;  // Float..Float4 or Int
};

struct FunctionSignature {
  std::string Name;          // as the user wrote it, and as graph.json's "fn" names it
  std::string RenamedName;   // the per-file name in the generated kernel, e.g. "noise_fbm3"
  std::string File;          // the source file that defines it
  BaseType Return = BaseType::Float;  // Float..Float4
  std::vector<Param> Params;
  std::vector<std::string> Attributes;  // read by its whole call tree, sorted ("AO", "Normal")
  std::vector<std::string> Settings;    // likewise ("Time")
  /// The size of the code a call inlines to (the front end: statements and expressions of the
  /// body, plus, per call of another user function, that function's Cost); 0 when unknown.
  /// Reported in layout.json (functions[].cost) as a measure of a function's size.
  unsigned Cost = 0;
  /// Locals computed once per material in shape mode, in declaration order (empty in every
  /// other mode: texcc drops them there), and the indices of the parameters they read.
  std::vector<HoistedValue> Hoisted;
  std::vector<unsigned> HoistedFrom;
};

using SignatureMap = std::map<std::string, FunctionSignature>;  // by Name

/// The attributes of DESIGN.md, in id order (the id is the index; it is ABI, see docs/abi.md).
const std::vector<std::pair<std::string, BaseType>> &attributeTable();
/// Attribute id by name, or -1.
int attributeId(const std::string &Name);
/// The settings of DESIGN.md: name and type.
const std::vector<std::pair<std::string, BaseType>> &settingTable();

/// Reads a signatures file: a JSON list of {name, renamed, file, return, params: [{name,
/// type}], attributes, settings}, types spelled as spelling() writes them (texcc-graph's
/// --signatures, and tests). Errors go to Diags with line:col; false on any.
bool readSignaturesJson(const std::string &Path, const std::string &Text, SignatureMap &Sigs,
                        DiagnosticSink &Diags);

} // namespace texcc::graph

#endif
