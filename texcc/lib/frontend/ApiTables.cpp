#include "ApiTables.h"

#include <algorithm>

namespace texcc::frontend {

std::string sortedNames(const ApiTable &Table) {
  std::vector<std::string> Names;
  for (const auto &Entry : Table)
    Names.push_back(Entry.first);
  std::sort(Names.begin(), Names.end());
  std::string Out;
  for (const auto &N : Names)
    Out += (Out.empty() ? "" : ", ") + N;
  return Out;
}

} // namespace texcc::frontend
