#ifndef TEXCC_VERSION_H
#define TEXCC_VERSION_H

namespace texcc {

/// The texcc release, e.g. "0.1.0".
const char *versionString();

} // namespace texcc

#endif
