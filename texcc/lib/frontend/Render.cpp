// TranslatedSource::render: the rewritten file, framed so that it can be pasted into a kernel
// next to other sources: #line directives back to the user's file, its macros undefined after it.
#include "texcc/Frontend/Frontend.h"

#include <algorithm>

namespace texcc::frontend {

static std::string quoted(const std::string &Path) {
  std::string Out = "\"";
  for (char C : Path) {
    if (C == '"' || C == '\\')
      Out += '\\';
    Out += C;
  }
  return Out + "\"";
}

std::string TranslatedSource::render(const std::set<std::string> &Keep) const {
  std::string Out;
  for (const auto &[Name, Value] : Predefined)
    Out += "#define " + Name + " " + Value + "\n";
  Out += "#line 1 " + quoted(Path) + "\n";
  // Omitted definitions, in text order.
  std::vector<const Range *> Skipped;
  if (!Keep.empty())
    for (const auto &[Name, R] : Definitions)
      if (!Keep.count(Name))
        Skipped.push_back(&R);
  std::sort(Skipped.begin(), Skipped.end(),
            [](const Range *A, const Range *B) { return A->Begin < B->Begin; });
  size_t Pos = 0;
  for (const Range *R : Skipped) {
    if (R->Begin < Pos || R->End > Text.size())
      continue;
    Out.append(Text, Pos, R->Begin - Pos);
    // The rest of the definition's last line continues as user line LineAfter.
    Out += "\n#line " + std::to_string(R->LineAfter) + " " + quoted(Path) + "\n";
    Pos = R->End;
  }
  Out.append(Text, Pos, std::string::npos);
  if (!Out.empty() && Out.back() != '\n')
    Out += '\n';
  for (const std::string &M : DefinedMacros)
    Out += "#undef " + M + "\n";
  for (const auto &[Name, Value] : Predefined)
    if (std::find(DefinedMacros.begin(), DefinedMacros.end(), Name) == DefinedMacros.end())
      Out += "#undef " + Name + "\n";
  return Out;
}

} // namespace texcc::frontend
