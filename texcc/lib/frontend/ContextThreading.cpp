#include "Callbacks.h"

#include "clang/Lex/Lexer.h"

using namespace clang;
using namespace clang::ast_matchers;

namespace texcc::frontend {

void ContextThreading::registerMatchers(MatchFinder &Finder) {
  Finder.addMatcher(functionDecl().bind("decl"), this);
  Finder.addMatcher(callExpr(callee(functionDecl())).bind("call"), this);
}

void ContextThreading::run(const MatchFinder::MatchResult &Result) {
  if (const auto *FD = Result.Nodes.getNodeAs<FunctionDecl>("decl")) {
    if (!FC.isUserFunction(FD))
      return;
    FunctionTypeLoc TL = FD->getFunctionTypeLoc();
    if (!TL)
      return;
    // TEXCC_FN (always_inline, texcc_device.h) in front of every declaration the user spelled
    // in a file; one made by a macro, or marked noinline, is left as it is.
    SourceLocation Begin = FD->getBeginLoc();
    if (Begin.isFileID() && !FD->hasAttr<NoInlineAttr>())
      FC.Edits.replace(Begin, Begin, InlineMarker);
    SourceLocation LParen = FC.spelled(TL.getLParenLoc());
    if (FD->param_empty()) {
      // `f()` and `f(void)` both become `f(TEXCC_CTX_PARAM)`.
      SourceLocation RParen = FC.spelled(TL.getRParenLoc());
      FC.Edits.replace(LParen, RParen.getLocWithOffset(1), "(TEXCC_CTX_PARAM)");
    } else {
      FC.Edits.replaceToken(LParen, "(TEXCC_CTX_PARAM, ");
    }
    return;
  }
  const auto *Call = Result.Nodes.getNodeAs<CallExpr>("call");
  const auto *FD = Call->getDirectCallee();
  const auto *Ref = dyn_cast<DeclRefExpr>(Call->getCallee()->IgnoreParenImpCasts());
  if (!FC.isUserFunction(FD) || !Ref)
    return;
  SourceLocation LParen = FC.lparenAfter(FC.spelled(Ref->getLocation()));
  if (LParen.isInvalid()) {
    FC.report(Ref->getLocation(), Diag::MacroSplitCall) << FD->getName();
    return;
  }
  FC.Edits.replaceToken(LParen, Call->getNumArgs() ? "(TEXCC_CTX_ARG, " : "(TEXCC_CTX_ARG");
}

} // namespace texcc::frontend
