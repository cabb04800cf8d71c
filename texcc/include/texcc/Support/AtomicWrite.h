#ifndef TEXCC_SUPPORT_ATOMICWRITE_H
#define TEXCC_SUPPORT_ATOMICWRITE_H

// Writing one file so that readers never see it half-written: the new contents go to a hidden
// temporary next to it (".NAME.tmp<pid>", or ".NAME.tmp<pid>.<n>" for a process's further
// writes, which removeStaleTemporaries recognises), then rename() puts it in place in one step.
// The one helper for every single-file writer of texcc and texrender (texcc-graph's outputs,
// images, the program cache); texcc's OUTDIR, several files that change together, has its
// rollback on top of the same naming (codegen::writeOutputsAtomically). No LLVM.

#include <functional>
#include <string>

namespace texcc {

/// Calls Write with the temporary's path; when it returns true, renames the temporary to Path.
/// On any failure (Write returns false or throws, the rename fails) the temporary is removed,
/// Path keeps its old contents, and the result is false (Why says why; an exception from
/// Write propagates after the removal). Path's folder must exist.
bool writeAtomicallyWith(const std::string &Path,
                         const std::function<bool(const std::string &Temp, std::string &Why)> &Write,
                         std::string &Why);

/// Contents, byte for byte, to Path (writeAtomicallyWith).
bool writeFileAtomically(const std::string &Path, const std::string &Contents, std::string &Why);

} // namespace texcc

#endif
