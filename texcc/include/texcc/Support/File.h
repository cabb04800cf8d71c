#ifndef TEXCC_SUPPORT_FILE_H
#define TEXCC_SUPPORT_FILE_H

// Reading the files that texcc and texrender need whole (graphs, scenes, layouts, kernels,
// signatures): one helper for every reader, so that a FIFO, a device or a folder given where a
// file is needed is one clear error and never a hang (an open() of a FIFO with no writer blocks,
// a read of /dev/zero never ends). No LLVM: the graph library and the runtime use it.

#include <string>

namespace texcc {

/// Opens Path without blocking (O_NONBLOCK, so that a FIFO never blocks) and checks that it is a
/// regular file. On failure returns false and sets Why to the reason, without the path:
/// "no such file", "it is a folder", "it is a FIFO, not a regular file", "it is a device, not a
/// regular file", "it is a socket, not a regular file", "too many levels of symbolic links", or
/// strerror() of the failing call in lower case (e.g. "permission denied").
bool checkRegularFile(const std::string &Path, std::string &Why);

/// As checkRegularFile, and reads the whole file into Text.
bool readRegularFile(const std::string &Path, std::string &Text, std::string &Why);

} // namespace texcc

#endif
