#ifndef TEXCC_SUPPORT_ATOMICWRITE_H
#define TEXCC_SUPPORT_ATOMICWRITE_H

// Writing one file so that readers never see it half-written: the new contents go to a hidden
// temporary next to it (".NAME.tmp<pid>", or ".NAME.tmp<pid>.<n>" for a process's further
// writes, which removeStaleTemporaries recognises), then rename() puts it in place in one step.
// The one helper for every single-file writer of texcc and texrender (texcc-graph's outputs,
// images, the program cache); texcc's OUTDIR, several files that change together, has its
// rollback on top of the same naming (codegen::writeOutputsAtomically). No LLVM.

#include <cstddef>
#include <functional>
#include <string>

namespace texcc {

/// The one low-level writer of every output file: creates or truncates Path (mode 0666 less the
/// umask), writes Size bytes with write(2), every call's result checked (a short write is
/// continued, EINTR retried), and checks close(). On failure returns false and sets Why to the
/// cause (strerror: "No space left on device", "File too large", ...); Path may then hold part
/// of the data (callers write a temporary and remove it). stdio and iostreams are not used:
/// fclose()'s and a stream's last flush were where a full disk's error went unnoticed.
bool writeWholeFile(const std::string &Path, const void *Data, size_t Size, std::string &Why);

/// Whether Path can be replaced by a new regular file: true when it does not exist or is a
/// regular file (or a symlink to one, or a dangling one); otherwise Why says what it is ("it is
/// a folder", "it is a device, not a regular file", "it is a FIFO, ...", "it is a socket, ...").
/// Renaming a file over /dev/full would replace the device (as root).
bool checkReplaceable(const std::string &Path, std::string &Why);

/// A fresh temporary's path for Path (".NAME.tmp<pid>[.<n>]" beside it), for writers that rename
/// several files together (texrender's OutputGroup).
std::string temporaryPathFor(const std::string &Path);

/// Calls Write with the temporary's path; when it returns true, renames the temporary to Path.
/// Path is first checked with checkReplaceable (nothing is written when it fails). On any failure (Write returns false or throws, the rename fails) the temporary is removed,
/// Path keeps its old contents, and the result is false (Why says why; an exception from
/// Write propagates after the removal). Path's folder must exist.
bool writeAtomicallyWith(const std::string &Path,
                         const std::function<bool(const std::string &Temp, std::string &Why)> &Write,
                         std::string &Why);

/// Contents, byte for byte, to Path (writeAtomicallyWith, writeWholeFile).
bool writeFileAtomically(const std::string &Path, const std::string &Contents, std::string &Why);
bool writeFileAtomically(const std::string &Path, const void *Data, size_t Size, std::string &Why);

} // namespace texcc

#endif
