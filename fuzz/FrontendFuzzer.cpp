// fuzz-frontend: one in-memory user source through the front end: a Clang parse with the
// texcc prelude, renaming, embedded-API lowering, context threading, restrictions, signature
// collection, then render(). Every identifier followed by '(' is requested as a texture
// function so that signature collection runs on whatever the input defines. Each input costs
// a Clang invocation (tens of milliseconds): run with -timeout and -rss_limit_mb.
#include "texcc/Frontend/Frontend.h"

#include <cctype>
#include <cstdint>

namespace fe = texcc::frontend;

/// The names in Text that look like calls or definitions: an identifier, spaces, '('.
static std::set<std::string> calledNames(const std::string &Text) {
  std::set<std::string> Names;
  size_t I = 0;
  while (I < Text.size()) {
    if (!std::isalpha(static_cast<unsigned char>(Text[I])) && Text[I] != '_') {
      ++I;
      continue;
    }
    size_t Begin = I;
    while (I < Text.size() && (std::isalnum(static_cast<unsigned char>(Text[I])) || Text[I] == '_'))
      ++I;
    size_t J = I;
    while (J < Text.size() && (Text[J] == ' ' || Text[J] == '\t'))
      ++J;
    if (J < Text.size() && Text[J] == '(')
      Names.insert(Text.substr(Begin, I - Begin));
  }
  return Names;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *Data, size_t Size) {
  // Clang's work grows faster than linearly in pathological inputs; long ones only slow the
  // search down.
  if (Size > 16384)
    return -1;
  const std::string Path = "/texcc-fuzz/input.cl";
  const std::string Text(reinterpret_cast<const char *>(Data), Size);
  fe::FrontendOptions Opts;
  Opts.VirtualFiles[Path] = Text;
  auto Result = fe::runFrontend({Path}, calledNames(Text), Opts, llvm::nulls());
  if (!Result) {
    llvm::consumeError(Result.takeError());
    return 0;
  }
  for (const fe::TranslatedSource &S : Result->Sources) {
    (void)S.render();
    // The reachable-only rendering the texcc driver uses.
    for (const auto &[Texture, Reach] : Result->Reachable)
      (void)S.render(Reach);
  }
  return 0;
}
