// The attribute and setting tables of DESIGN.md. The attributes are the kernel library's one
// table (texcc/Kernel/Attributes.def, checked against kernels/common/texcc_abi.h), typed here.

#include "texcc/Graph/Signature.h"
#include "texcc/Kernel/Attributes.h"

namespace texcc::graph {

const std::vector<std::pair<std::string, BaseType>> &attributeTable() {
  static const std::vector<std::pair<std::string, BaseType>> Table = [] {
    std::vector<std::pair<std::string, BaseType>> T;
    for (const kernel::AttributeInfo &A : kernel::AttributeTable)
      T.push_back({A.Name, A.Components == 1   ? BaseType::Float
                           : A.Components == 2 ? BaseType::Float2
                                               : BaseType::Float3});
    return T;
  }();
  return Table;
}

int attributeId(const std::string &Name) { return kernel::attributeId(Name); }

const std::vector<std::pair<std::string, BaseType>> &settingTable() {
  static const std::vector<std::pair<std::string, BaseType>> Table = {
      {"Time", BaseType::Float},
      {"Frame", BaseType::Int},
      {"CameraPos", BaseType::Float3},
  };
  return Table;
}

} // namespace texcc::graph
