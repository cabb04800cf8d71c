// fuzz-frontend: one in-memory user source through the front end: a Clang parse with the
// texcc prelude, renaming, embedded-API lowering, context threading, restrictions, signature
// collection, hoisting, then render(). Every identifier followed by '(' is requested as a
// texture function so that signature collection runs on whatever the input defines, and every
// identifier is taken for a constant parameter of each, so that hoisting (shape mode's) runs on
// every declaration that could qualify. Each input costs
// a Clang invocation (tens of milliseconds): run with -timeout and -rss_limit_mb.
#include "texcc/Frontend/Frontend.h"

#include <cctype>
#include <cstdint>

namespace fe = texcc::frontend;

/// The names in Text that look like calls or definitions (an identifier, spaces, '('), or
/// (All) every identifier.
static std::set<std::string> calledNames(const std::string &Text, bool All = false) {
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
    if (All || (J < Text.size() && Text[J] == '('))
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
  const std::set<std::string> Textures = calledNames(Text), Identifiers = calledNames(Text, true);
  for (const std::string &T : Textures)
    Opts.HoistableParams[T] = Identifiers;
  auto Result = fe::runFrontend({Path}, Textures, Opts, llvm::nulls());
  if (!Result) {
    llvm::consumeError(Result.takeError());
    return 0;
  }
  for (const fe::TranslatedSource &S : Result->Sources) {
    (void)S.render();
    // The reachable-only rendering the texcc driver uses, with the hoisted functions (shape).
    std::set<std::string> Hoist;
    for (const auto &[Renamed, Functions] : S.Hoisted)
      Hoist.insert(Renamed);
    for (const auto &[Texture, Reach] : Result->Reachable)
      (void)S.render(Reach, Hoist);
  }
  return 0;
}
