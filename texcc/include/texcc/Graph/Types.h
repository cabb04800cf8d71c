#ifndef TEXCC_GRAPH_TYPES_H
#define TEXCC_GRAPH_TYPES_H

// The value types a texture function may take and return, with OpenCL C 1.2 sizes and
// alignments. Shared by the front end (signature extraction), the graph library (validation,
// argument layout) and code generation. No LLVM here.

#include <optional>
#include <string>

namespace texcc::graph {

enum class BaseType { Float, Float2, Float3, Float4, Int, Sampler };

/// A parameter or return type. `IsGlobalArray` means `__global const Base*`, whose values come
/// from the fake stack (a graph literal array of arrays or of numbers).
struct ValueType {
  BaseType Base = BaseType::Float;
  bool IsGlobalArray = false;

  bool operator==(const ValueType &O) const {
    return Base == O.Base && IsGlobalArray == O.IsGlobalArray;
  }
  bool operator!=(const ValueType &O) const { return !(*this == O); }
};

/// Number of float components of a float..float4 (Int: 1, Sampler: 1).
unsigned componentCount(BaseType B);
/// OpenCL sizes/alignments: float 4/4, float2 8/8, float3 16/16, float4 16/16, int 4/4,
/// sam2D 4/4 (an image index). A global array occupies a {uint byteOffset, uint count} pair
/// in an argument block: 8/4.
unsigned sizeOf(const ValueType &T);
unsigned alignOf(const ValueType &T);
/// OpenCL spelling: "float3", "int", "sam2D", "__global const float4*".
std::string spelling(const ValueType &T);
std::string spelling(BaseType B);
/// Parses a spelling produced by spelling(); std::nullopt for anything else.
std::optional<ValueType> parseSpelling(const std::string &S);

/// Whether a value of type From may feed a parameter of type To: identical types, or the
/// broadcast of a float to float2..4 (DESIGN.md). Arrays only come from literals.
bool isAssignable(BaseType From, const ValueType &To);

} // namespace texcc::graph

#endif
