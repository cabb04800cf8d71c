#include "Callbacks.h"

using namespace clang;
using namespace clang::ast_matchers;

namespace texcc::frontend {

void Renaming::registerMatchers(MatchFinder &Finder) {
  Finder.addMatcher(functionDecl().bind("decl"), this);
  Finder.addMatcher(declRefExpr(to(functionDecl())).bind("ref"), this);
}

void Renaming::run(const MatchFinder::MatchResult &Result) {
  if (const auto *FD = Result.Nodes.getNodeAs<FunctionDecl>("decl")) {
    if (FC.isUserFunction(FD))
      FC.Edits.replaceToken(FC.spelled(FD->getLocation()), FC.renamed(FD));
    return;
  }
  const auto *Ref = Result.Nodes.getNodeAs<DeclRefExpr>("ref");
  const auto *FD = dyn_cast<FunctionDecl>(Ref->getDecl());
  if (FC.isUserFunction(FD))
    FC.Edits.replaceToken(FC.spelled(Ref->getLocation()), FC.renamed(FD));
}

} // namespace texcc::frontend
