#ifndef TEXCC_STALETEMPORARIES_H
#define TEXCC_STALETEMPORARIES_H

// texcc and texrender write every output to a hidden temporary next to it (".NAME.tmp<pid>"
// or ".NAME.tmp<pid>.<n>", texcc/Support/AtomicWrite.h;
// texcc also keeps ".NAME.old.tmp<pid>" backups) and rename it into place. A process killed
// meanwhile leaves those behind; the next run into the folder removes them with this.

#include <string>
#include <vector>

namespace texcc {

/// Removes Dir/.NAME.tmp<pid>[.<n>] and Dir/.NAME.old.tmp<pid>[.<n>], for each NAME in Names, whose process
/// <pid> no longer exists. Errors are ignored (the files are only clutter).
void removeStaleTemporaries(const std::string &Dir, const std::vector<std::string> &Names);

} // namespace texcc

#endif
