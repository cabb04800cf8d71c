#include "texcc/Version.h"

#include "texcc/Config.h"

namespace texcc {

const char *versionString() { return TEXCC_VERSION; }

} // namespace texcc
