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

std::string TranslatedSource::render(const std::set<std::string> &Keep,
                                     const std::set<std::string> &Hoist) const {
  std::string Out;
  for (const auto &[Name, Value] : Predefined)
    Out += "#define " + Name + " " + Value + "\n";
  Out += "#line 1 " + quoted(Path) + "\n";
  // Omitted definitions, and the hoisted functions after their definitions, in text order.
  struct Piece {
    size_t Begin, End;
    const Range *R;
    const std::string *Insert;
  };
  std::vector<Piece> Pieces;
  for (const auto &[Name, R] : Definitions) {
    if (!Keep.empty() && !Keep.count(Name)) {
      Pieces.push_back({R.Begin, R.End, &R, nullptr});
      continue;
    }
    auto It = Hoisted.find(Name);
    if (Hoist.count(Name) && It != Hoisted.end())
      Pieces.push_back({R.End, R.End, &R, &It->second});
  }
  std::sort(Pieces.begin(), Pieces.end(),
            [](const Piece &A, const Piece &B) { return A.Begin < B.Begin; });
  size_t Pos = 0;
  for (const Piece &P : Pieces) {
    if (P.Begin < Pos || P.End > Text.size())
      continue;
    Out.append(Text, Pos, P.Begin - Pos);
    if (P.Insert)
      Out += "\n" + *P.Insert;
    // The rest of the definition's last line continues as user line LineAfter.
    Out += "\n#line " + std::to_string(P.R->LineAfter) + " " + quoted(Path) + "\n";
    Pos = P.End;
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
