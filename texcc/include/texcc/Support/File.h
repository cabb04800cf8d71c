#ifndef TEXCC_SUPPORT_FILE_H
#define TEXCC_SUPPORT_FILE_H

// Reading the files that texcc and texrender need whole (graphs, scenes, layouts, kernels,
// signatures): one helper for every reader, so that a FIFO, a device or a folder given where a
// file is needed is one clear error and never a hang (an open() of a FIFO with no writer blocks,
// a read of /dev/zero never ends). No LLVM: the graph library and the runtime use it.

#include <cstddef>
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

/// The same, refusing a file of more than MaxBytes (Why: "it is N bytes (X MiB), more than the
/// Y MiB limit") before reading it.
bool readRegularFile(const std::string &Path, std::string &Text, std::string &Why,
                     size_t MaxBytes);
/// That reason, for a file of Size bytes (the front end's check of a source's size).
std::string tooLarge(unsigned long long Size, size_t MaxBytes);

/// The largest graph texcc reads: a 70 MB graph (12 million numbers in an array) compiles in
/// about 4 s and 1.2 GB; the reader is linear, so this bounds the time and memory (issue 40).
constexpr size_t MaxGraphBytes = size_t(64) << 20;
/// The largest texture source file (each source, each #include'd file): clang's front end and
/// texcc's passes take about 0.5 s per MB (a 10 MB function: 5 s).
constexpr size_t MaxSourceBytes = size_t(8) << 20;

} // namespace texcc

#endif
