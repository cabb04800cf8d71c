// A large, guarded stack for the tools (see StackGuard.h for why). It lives in the graph
// library because that is the LLVM-free library both texcc and texrender link.
#include "texcc/StackGuard.h"

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <pthread.h>
#include <sys/mman.h>
#include <unistd.h>

namespace texcc {

namespace {

// Below the stack: a fault anywhere in it is an overflow (a frame may skip a small guard).
constexpr size_t GuardBytes = size_t(16) << 20;
constexpr size_t AltStackBytes = size_t(256) << 10;

struct GuardState {
  char *GuardLow = nullptr, *GuardHigh = nullptr;
  char Message[256] = {};
  size_t MessageLength = 0;
  struct sigaction Previous = {};
};
GuardState Guard;

void onSegv(int Signal, siginfo_t *Info, void *) {
  char *Addr = static_cast<char *>(Info->si_addr);
  if (Addr >= Guard.GuardLow && Addr < Guard.GuardHigh) {
    // Only async-signal-safe calls here.
    ssize_t Ignored = ::write(2, Guard.Message, Guard.MessageLength);
    (void)Ignored;
    ::_exit(1);
  }
  // Not ours: let the fault happen again under the previous disposition (a crash).
  sigaction(Signal, &Guard.Previous, nullptr);
}

struct ThreadArgs {
  const std::function<int()> *Main;
  int Result = 1;
};

void *threadMain(void *P) {
  auto *Args = static_cast<ThreadArgs *>(P);
  // The handler must run on a stack of its own: the thread's own is exhausted.
  stack_t Alt = {};
  Alt.ss_sp = ::mmap(nullptr, AltStackBytes, PROT_READ | PROT_WRITE, MAP_PRIVATE | MAP_ANONYMOUS,
                     -1, 0);
  Alt.ss_size = AltStackBytes;
  if (Alt.ss_sp != MAP_FAILED)
    sigaltstack(&Alt, nullptr);
  Args->Result = (*Args->Main)();
  return nullptr;
}

} // namespace

int runWithLargeStack(const std::function<int()> &Main, const char *Tool, size_t StackBytes) {
  // A file size limit (ulimit -f) reached by a write is then the write's error, EFBIG, which
  // the writers report ("cannot write: File too large"), instead of death by SIGXFSZ.
  std::signal(SIGXFSZ, SIG_IGN);
  // TEXCC_STACK_MB: a smaller stack lets a test reach the limit quickly and cheaply.
  if (const char *Env = std::getenv("TEXCC_STACK_MB"); Env && std::atoi(Env) > 0)
    StackBytes = size_t(std::atoi(Env)) << 20;
  const size_t Total = GuardBytes + StackBytes;
  void *Region = ::mmap(nullptr, Total, PROT_READ | PROT_WRITE,
                        MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE | MAP_STACK, -1, 0);
  if (Region == MAP_FAILED)
    return Main(); // no address space to spare: run as before
  char *Low = static_cast<char *>(Region);
  ::mprotect(Low, GuardBytes, PROT_NONE);
  Guard.GuardLow = Low;
  Guard.GuardHigh = Low + GuardBytes;
  Guard.MessageLength = size_t(std::snprintf(
      Guard.Message, sizeof Guard.Message,
      "%s: error: out of stack space (%zu MiB): an input nests too deeply, e.g. a macro that "
      "expands to a huge expression (docs/reliability.md)\n",
      Tool, StackBytes >> 20));
  struct sigaction Action = {};
  Action.sa_sigaction = onSegv;
  Action.sa_flags = SA_SIGINFO | SA_ONSTACK;
  sigemptyset(&Action.sa_mask);
  sigaction(SIGSEGV, &Action, &Guard.Previous);

  pthread_attr_t Attr;
  pthread_attr_init(&Attr);
  pthread_attr_setstack(&Attr, Low + GuardBytes, StackBytes);
  ThreadArgs Args{&Main};
  pthread_t Thread;
  int Result;
  if (pthread_create(&Thread, &Attr, threadMain, &Args) == 0) {
    pthread_join(Thread, nullptr);
    Result = Args.Result;
  } else {
    Result = Main();
  }
  pthread_attr_destroy(&Attr);
  sigaction(SIGSEGV, &Guard.Previous, nullptr);
  ::munmap(Region, Total);
  return Result;
}

} // namespace texcc
