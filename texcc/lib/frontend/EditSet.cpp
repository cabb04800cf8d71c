#include "EditSet.h"

#include "clang/Lex/Lexer.h"

#include <algorithm>

using namespace clang;

namespace texcc::frontend {

void EditSet::replace(SourceLocation Begin, SourceLocation End, const std::string &Text) {
  auto [File, BeginOffset] = SM.getDecomposedLoc(Begin);
  auto [EndFile, EndOffset] = SM.getDecomposedLoc(End);
  if (File != EndFile || EndOffset < BeginOffset)
    return;
  StringRef Old = SM.getBufferData(File).substr(BeginOffset, EndOffset - BeginOffset);
  std::string New = Text + std::string(std::count(Old.begin(), Old.end(), '\n'), '\n');
  Edits[{File, BeginOffset, EndOffset - BeginOffset}] = New;
}

void EditSet::replaceToken(SourceLocation Loc, const std::string &Text) {
  unsigned Length = Lexer::MeasureTokenLength(Loc, SM, LangOpts);
  replace(Loc, Loc.getLocWithOffset(Length), Text);
}

llvm::Expected<tooling::Replacements> EditSet::replacementsFor(FileID File) const {
  tooling::Replacements Result;
  StringRef Path = SM.getFileEntryForID(File) ? SM.getFileEntryForID(File)->getName() : "";
  for (const auto &[Key, Text] : Edits) {
    if (std::get<0>(Key) != File)
      continue;
    if (llvm::Error E =
            Result.add(tooling::Replacement(Path, std::get<1>(Key), std::get<2>(Key), Text)))
      return E;
  }
  return Result;
}

} // namespace texcc::frontend
