#ifndef TEXCC_LIB_FRONTEND_APITABLES_H
#define TEXCC_LIB_FRONTEND_APITABLES_H

// The names and types of the embedded API come from the graph library's tables
// (texcc/Graph/Signature.h), the single source of truth; this adds what diagnostics need.

#include "texcc/Graph/Signature.h"

#include <string>
#include <utility>
#include <vector>

namespace texcc::frontend {

using ApiTable = std::vector<std::pair<std::string, graph::BaseType>>;

/// "AO, GeomNormal, Normal, ..." (sorted), for "expected one of" messages.
std::string sortedNames(const ApiTable &Table);

} // namespace texcc::frontend

#endif
