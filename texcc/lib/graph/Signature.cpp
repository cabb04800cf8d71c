// The attribute and setting tables of DESIGN.md. The attribute order is ABI: the index is the
// id the kernel and args.bin use (TEXCC_ATTR_* in kernels/common/texcc_abi.h).

#include "texcc/Graph/Signature.h"

namespace texcc::graph {

const std::vector<std::pair<std::string, BaseType>> &attributeTable() {
  static const std::vector<std::pair<std::string, BaseType>> Table = {
      {"WorldPos", BaseType::Float3},   {"ObjectPos", BaseType::Float3},
      {"Normal", BaseType::Float3},     {"GeomNormal", BaseType::Float3},
      {"Tangent", BaseType::Float3},    {"TexCoord0", BaseType::Float2},
      {"AO", BaseType::Float},          {"ViewDir", BaseType::Float3},
  };
  return Table;
}

int attributeId(const std::string &Name) {
  const auto &Table = attributeTable();
  for (size_t I = 0; I < Table.size(); ++I)
    if (Table[I].first == Name)
      return static_cast<int>(I);
  return -1;
}

const std::vector<std::pair<std::string, BaseType>> &settingTable() {
  static const std::vector<std::pair<std::string, BaseType>> Table = {
      {"Time", BaseType::Float},
      {"Frame", BaseType::Int},
      {"CameraPos", BaseType::Float3},
  };
  return Table;
}

} // namespace texcc::graph
