#include "Callbacks.h"

using namespace clang;
using namespace clang::ast_matchers;

namespace texcc::frontend {

void Renaming::registerMatchers(MatchFinder &Finder) {
  Finder.addMatcher(functionDecl().bind("decl"), this);
  Finder.addMatcher(declRefExpr(to(functionDecl())).bind("ref"), this);
  // Program-scope variables (__constant tables) clash between files just like functions.
  Finder.addMatcher(varDecl().bind("var"), this);
  Finder.addMatcher(declRefExpr(to(varDecl())).bind("varref"), this);
}

bool Renaming::isUserGlobal(const VarDecl *VD) const {
  if (!VD || !VD->isFileVarDecl() || VD->isImplicit())
    return false;
  SourceLocation Loc = FC.SM.getExpansionLoc(VD->getLocation());
  return Loc.isValid() && !FC.SM.isInSystemHeader(Loc) && FC.SM.getFileEntryForID(FC.SM.getFileID(Loc));
}

void Renaming::run(const MatchFinder::MatchResult &Result) {
  if (const auto *FD = Result.Nodes.getNodeAs<FunctionDecl>("decl")) {
    if (FC.isUserFunction(FD))
      FC.renameAt(FD->getLocation(), FD->getName(), FC.renamed(FD));
    return;
  }
  if (const auto *VD = Result.Nodes.getNodeAs<VarDecl>("var")) {
    if (isUserGlobal(VD))
      FC.renameAt(VD->getLocation(), VD->getName(), FC.Prefix + VD->getName().str());
    return;
  }
  if (const auto *Ref = Result.Nodes.getNodeAs<DeclRefExpr>("varref")) {
    const auto *VD = dyn_cast<VarDecl>(Ref->getDecl());
    if (isUserGlobal(VD))
      FC.renameAt(Ref->getLocation(), VD->getName(), FC.Prefix + VD->getName().str());
    return;
  }
  const auto *Ref = Result.Nodes.getNodeAs<DeclRefExpr>("ref");
  const auto *FD = dyn_cast<FunctionDecl>(Ref->getDecl());
  if (FC.isUserFunction(FD))
    FC.renameAt(Ref->getLocation(), FD->getName(), FC.renamed(FD));
}

} // namespace texcc::frontend
