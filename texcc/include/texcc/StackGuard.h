#ifndef TEXCC_STACKGUARD_H
#define TEXCC_STACKGUARD_H

// Clang parses and checks expressions recursively: a macro that expands to a 2^16-term sum
// (or any very deep expression) overflows the 8 MiB main-thread stack and the process dies of
// SIGSEGV, as clang itself does; so does texrender, whose OpenCL compiler (PoCL) runs clang in
// process on such a kernel. texcc, texcc-fe and texrender therefore run on a thread with a large stack
// (lazily committed, so it costs only what is used) and a guard region below it; running into
// the guard is reported as a one-line error and exit status 1, never as a crash. Any other
// fault is left to crash as usual.

#include <cstddef>
#include <functional>

namespace texcc {

/// The stack the tools run on: 512 MiB (docs/reliability.md gives the limits it sets).
constexpr size_t LargeStackBytes = size_t(512) << 20;

/// Runs Main on a thread with a StackBytes stack and returns its result. If Main exhausts that
/// stack, prints "<Tool>: error: out of stack space ..." on stderr and exits with status 1.
/// $TEXCC_STACK_MB, when set, replaces StackBytes.
int runWithLargeStack(const std::function<int()> &Main, const char *Tool,
                      size_t StackBytes = LargeStackBytes);

} // namespace texcc

#endif
