#ifndef TEXCC_LIB_FRONTEND_EDITSET_H
#define TEXCC_LIB_FRONTEND_EDITSET_H

// The edits the match callbacks ask for, collected and deduplicated (a call spelled inside a
// macro body is matched once per expansion), then turned into tooling::Replacements once.

#include "clang/Basic/SourceManager.h"
#include "clang/Tooling/Core/Replacement.h"

#include <map>
#include <string>
#include <tuple>

namespace texcc::frontend {

class EditSet {
public:
  EditSet(const clang::SourceManager &SM, const clang::LangOptions &LangOpts)
      : SM(SM), LangOpts(LangOpts) {}

  /// Replaces the characters [Begin, End) (file locations) by Text. Newlines in the replaced
  /// text are kept (appended) so that every later line keeps its number.
  void replace(clang::SourceLocation Begin, clang::SourceLocation End, const std::string &Text);
  /// Replaces the token at Loc (a file location).
  void replaceToken(clang::SourceLocation Loc, const std::string &Text);

  /// The replacements for one file; an llvm::Error if two edits overlap.
  llvm::Expected<clang::tooling::Replacements> replacementsFor(clang::FileID File) const;

private:
  const clang::SourceManager &SM;
  const clang::LangOptions &LangOpts;
  // (file, offset, length) -> text
  std::map<std::tuple<clang::FileID, unsigned, unsigned>, std::string> Edits;
};

} // namespace texcc::frontend

#endif
