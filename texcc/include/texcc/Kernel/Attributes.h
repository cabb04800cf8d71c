#ifndef TEXCC_KERNEL_ATTRIBUTES_H
#define TEXCC_KERNEL_ATTRIBUTES_H

// The hit attributes a texture reads (readAttr), from Attributes.def: every C++ user (the graph
// library, code generation, the runtime, texcc-eval) takes names, ids and widths from here.

#include <cstddef>
#include <string_view>

namespace texcc::kernel {

/// An attribute's id: its index in the table (TEXCC_ATTR_* in texcc_abi.h).
enum class Attribute : unsigned {
#define TEXCC_ATTRIBUTE(Name, Components, AbiId) Name,
#include "texcc/Kernel/Attributes.def"
};

struct AttributeInfo {
  const char *Name;
  unsigned Components; // 1 (float), 2 (float2) or 3 (float3)
};

inline constexpr AttributeInfo AttributeTable[] = {
#define TEXCC_ATTRIBUTE(Name, Components, AbiId) {#Name, Components},
#include "texcc/Kernel/Attributes.def"
};

inline constexpr unsigned NumAttributes = sizeof(AttributeTable) / sizeof(AttributeTable[0]);

/// The id of the attribute called Name, or -1.
constexpr int attributeId(std::string_view Name) {
  for (unsigned I = 0; I < NumAttributes; ++I)
    if (Name == AttributeTable[I].Name)
      return static_cast<int>(I);
  return -1;
}

/// The name of attribute Id ("?" when out of range).
constexpr const char *attributeName(unsigned Id) {
  return Id < NumAttributes ? AttributeTable[Id].Name : "?";
}

} // namespace texcc::kernel

#endif
