#include "ApiTables.h"
#include "Callbacks.h"

#include "clang/Lex/Lexer.h"

using namespace clang;
using namespace clang::ast_matchers;

namespace texcc::frontend {

void ApiLowering::registerMatchers(MatchFinder &Finder) {
  auto Api = functionDecl(hasAnyName("readAttr", "readSetting", "tex2D", "tex2DFiltered")).bind("callee");
  Finder.addMatcher(
      callExpr(callee(Api), optionally(forFunction(functionDecl().bind("caller")))).bind("call"),
      this);
}

void ApiLowering::run(const MatchFinder::MatchResult &Result) {
  const auto *Call = Result.Nodes.getNodeAs<CallExpr>("call");
  const auto *Callee = Result.Nodes.getNodeAs<FunctionDecl>("callee");
  const auto *Caller = Result.Nodes.getNodeAs<FunctionDecl>("caller");
  const llvm::StringRef Fn = Callee->getName();
  if (Fn != "tex2D" && Fn != "tex2DFiltered") {
    if (FC.isApiFunction(Callee, Fn))
      lowerRead(Call, Callee, Caller);
    return;
  }
  const auto *Ref = dyn_cast<DeclRefExpr>(Call->getCallee()->IgnoreParenImpCasts());
  if (!FC.isApiFunction(Callee, Fn) || !Ref)
    return;
  SourceLocation Name = FC.spelled(Ref->getLocation());
  SourceLocation LParen = FC.lparenAfter(Name);
  if (LParen.isInvalid()) {
    FC.report(Ref->getLocation(), Diag::MacroSplitCall) << Fn;
    return;
  }
  FC.Edits.replaceToken(Name, ("texcc_" + Fn).str());
  FC.Edits.replaceToken(LParen, "(texcc_ctx, ");
}

/// The file range of a whole call: where it is spelled when the call lies inside one macro
/// body or argument, else its expansion.
static CharSourceRange callRange(const CallExpr *Call, const SourceManager &SM,
                                 const LangOptions &LO) {
  SourceLocation B = SM.getSpellingLoc(Call->getBeginLoc());
  SourceLocation E = SM.getSpellingLoc(Call->getEndLoc());
  if (SM.getFileID(B) == SM.getFileID(E) && !SM.isBeforeInTranslationUnit(E, B) &&
      SM.getFileEntryForID(SM.getFileID(B)))
    return CharSourceRange::getCharRange(B, Lexer::getLocForEndOfToken(E, 0, SM, LO));
  return Lexer::makeFileCharRange(CharSourceRange::getTokenRange(Call->getSourceRange()), SM, LO);
}

void ApiLowering::lowerRead(const CallExpr *Call, const FunctionDecl *Callee,
                            const FunctionDecl *Caller) {
  bool IsAttr = Callee->getName() == "readAttr";
  if (Call->getNumArgs() != 1)
    return;
  const Expr *Arg = Call->getArg(0)->IgnoreParenImpCasts();
  const auto *Literal = dyn_cast<StringLiteral>(Arg);
  if (!Literal) {
    FC.report(Arg->getExprLoc(), Diag::NonLiteralArgument) << Callee->getName();
    return;
  }
  std::string Name = Literal->getString().str();
  if (!Callee->hasAttr<EnableIfAttr>()) {
    FC.report(Arg->getExprLoc(), IsAttr ? Diag::UnknownAttribute : Diag::UnknownSetting)
        << Name << sortedNames(IsAttr ? graph::attributeTable() : graph::settingTable());
    return;
  }
  if (Caller && FC.isUserFunction(Caller))
    (IsAttr ? FC.AttributesRead : FC.SettingsRead)[FC.renamed(Caller)].insert(Name);
  CharSourceRange Range = callRange(Call, FC.SM, FC.Ctx.getLangOpts());
  if (Range.isInvalid()) {
    FC.report(Call->getBeginLoc(), Diag::MacroSplitCall) << Callee->getName();
    return;
  }
  FC.Edits.replace(Range.getBegin(), Range.getEnd(),
                   (IsAttr ? "texcc_attr_" : "texcc_setting_") + Name + "(texcc_ctx)");
}

} // namespace texcc::frontend
