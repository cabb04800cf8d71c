// The attribute table against the OpenCL side: texcc_abi.h is included as the runtime includes
// it (C++, cl_float4 members), and every id of Attributes.def must equal its TEXCC_ATTR_* macro,
// so the kernels cannot drift from the table.

#include "texcc/Kernel/Attributes.h"

#include "texcc_abi.h"

namespace texcc::kernel {

#define TEXCC_ATTRIBUTE(Name, Components, AbiId)                                                 \
  static_assert(static_cast<unsigned>(Attribute::Name) == (AbiId),                               \
                "Attributes.def: " #Name " is not " #AbiId " of texcc_abi.h");
#include "texcc/Kernel/Attributes.def"

static_assert(NumAttributes == TEXCC_ATTR_COUNT,
              "Attributes.def and texcc_abi.h's TEXCC_ATTR_COUNT differ");
static_assert(attributeId("AO") == TEXCC_ATTR_AO && attributeId("nope") == -1);

} // namespace texcc::kernel
