#ifndef TEXCC_OUTOFMEMORY_H
#define TEXCC_OUTOFMEMORY_H

// Out of memory as one line that says what was being allocated, and exit status 1:
//   texcc: error: out of memory while encoding args.bin
// instead of "terminate called after throwing an instance of 'std::bad_alloc'" and SIGABRT.
//
// The big steps of a tool run inside whileAllocating("encoding args.bin", ...), which names the
// step. A tool that calls installOutOfMemoryHandler() exits from the failed allocation itself
// (std::set_new_handler), with no unwinding: Clang and LLVM are built without exceptions (a
// std::bad_alloc through them leaves their objects half-built, and destroying them crashes),
// and nlohmann::json allocates in its destructor (an exception there is std::terminate). Every
// step of texcc that can run out of memory comes before its outputs are renamed into place, so
// nothing is left half-written (a temporary is removed by the next run, texcc/StaleTemporaries.h).
// Without the handler (texrender), a std::bad_alloc reaches the tool's top-level catch, which
// prints reportOutOfMemory(). Header only, no LLVM: the graph library, the runtime and the tools
// all use it.

#include <cstdio>
#include <cstdlib>
#include <new>
#include <utility>

namespace texcc {

namespace detail {
inline const char *&toolName() {
  static const char *Name = "texcc";
  return Name;
}
/// The innermost whileAllocating() step of this process (the tools run one thread).
inline const char *&currentStep() {
  static const char *Step = nullptr;
  return Step;
}
inline char *&reserve() {
  static char *Block = nullptr;
  return Block;
}
} // namespace detail

/// A std::bad_alloc that says what was being allocated. It keeps its own copy of the text
/// (a step may name a file, "loading OBJ 'mesh.obj'", in a string that unwinding destroys),
/// in a fixed buffer: neither making nor reporting it allocates. Longer text is cut.
class OutOfMemory : public std::bad_alloc {
public:
  explicit OutOfMemory(const char *Step) {
    std::snprintf(While, sizeof(While), "%s", Step ? Step : "");
  }
  const char *what() const noexcept override { return "out of memory"; }
  char While[512];
};

/// Runs F as the step While: a failed allocation inside is reported as "out of memory while
/// <While>" (the innermost step wins). While must live until F returns (a string the caller
/// built before the call, or static text).
template <typename Fn> decltype(auto) whileAllocating(const char *While, Fn &&F) {
  struct Scope {
    const char *Outer;
    explicit Scope(const char *W) : Outer(detail::currentStep()) { detail::currentStep() = W; }
    ~Scope() { detail::currentStep() = Outer; }
  } S(While);
  try {
    return std::forward<Fn>(F)();
  } catch (const OutOfMemory &) {
    throw;
  } catch (const std::bad_alloc &) {
    throw OutOfMemory(While);
  }
}

/// Prints the one line for the step While (or for the current step when While is nullptr) and
/// exits with status 1 at once (_Exit: no destructors, which might allocate).
[[noreturn]] inline void exitOutOfMemory(const char *While = nullptr) {
  if (!While)
    While = detail::currentStep();
  if (While)
    std::fprintf(stderr, "%s: error: out of memory while %s\n", detail::toolName(), While);
  else
    std::fprintf(stderr, "%s: error: out of memory\n", detail::toolName());
  std::fflush(stderr);
  std::_Exit(1);
}

/// Makes a failed allocation anywhere in the process print the one line of Tool and exit with
/// status 1. A 1 MiB reserve, freed first, leaves room for printing.
inline void installOutOfMemoryHandler(const char *Tool) {
  detail::toolName() = Tool;
  detail::reserve() = static_cast<char *>(std::malloc(size_t(1) << 20));
  std::set_new_handler([] {
    std::free(detail::reserve());
    detail::reserve() = nullptr;
    exitOutOfMemory();
  });
}

/// While it lives, a failed allocation exits at once with "<Tool>: error: out of memory while
/// <current step>" and status 1, as installOutOfMemoryHandler does for a whole tool: for a
/// step whose unwinding would allocate in a tool that otherwise unwinds (texrender). A
/// nlohmann::json array being destroyed allocates a vector of its size, so a std::bad_alloc
/// while parsing a large JSON file, unwinding through the half-built value, was std::terminate.
class ExitOnOutOfMemory {
public:
  explicit ExitOnOutOfMemory(const char *Tool)
      : OuterTool(detail::toolName()), Outer(std::set_new_handler([] { exitOutOfMemory(); })) {
    detail::toolName() = Tool;
  }
  ~ExitOnOutOfMemory() {
    std::set_new_handler(Outer);
    detail::toolName() = OuterTool;
  }
  ExitOnOutOfMemory(const ExitOnOutOfMemory &) = delete;
  ExitOnOutOfMemory &operator=(const ExitOnOutOfMemory &) = delete;

private:
  const char *OuterTool;
  std::new_handler Outer;
};

/// For a tool's top-level catch: prints "<Tool>: error: out of memory while <what>" (or
/// "... out of memory" when E does not say) on stderr, without allocating.
inline void reportOutOfMemory(const char *Tool, const std::bad_alloc &E) {
  if (const auto *O = dynamic_cast<const OutOfMemory *>(&E))
    std::fprintf(stderr, "%s: error: out of memory while %s\n", Tool, O->While);
  else
    std::fprintf(stderr, "%s: error: out of memory\n", Tool);
}

} // namespace texcc

#endif
