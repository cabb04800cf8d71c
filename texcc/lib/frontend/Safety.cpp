// Safety of user code (docs/reliability.md "User code"): texcc refuses what would take the
// device compiler or the work-item's stack down (huge private arrays, huge unroll counts) and
// bounds-checks every read of a __global array parameter. The loop budget is LoopBudget.cpp.
#include "Callbacks.h"

#include "clang/AST/Attr.h"
#include "clang/Lex/Lexer.h"

using namespace clang;
using namespace clang::ast_matchers;

namespace texcc::frontend {

/// Whether P is a `__global T *` parameter (the arrays a texture gets from the fake stack).
static bool isGlobalPointer(const ParmVarDecl *P) {
  QualType T = P->getType();
  return T->isPointerType() && T->getPointeeType().getAddressSpace() == LangAS::opencl_global;
}

/// The suffix of the checked read of P's elements (texcc_read_<suffix>, texcc_device.h), or ""
/// for an element type that has none.
static std::string elementName(const ParmVarDecl *P) {
  QualType E = P->getType()->getPointeeType().getUnqualifiedType().getCanonicalType();
  unsigned N = 1;
  if (const auto *V = E->getAs<ExtVectorType>()) {
    N = V->getNumElements();
    E = V->getElementType().getCanonicalType();
    if (N < 2 || N > 4)
      return "";
  }
  std::string Base;
  if (E->isSpecificBuiltinType(BuiltinType::Float))
    Base = "float";
  else if (E->isSpecificBuiltinType(BuiltinType::Int))
    Base = "int";
  else if (E->isSpecificBuiltinType(BuiltinType::UInt))
    Base = "uint";
  else
    return "";
  return N == 1 ? Base : Base + std::to_string(N);
}

static std::string lengthName(StringRef Param) { return "texcc_n_" + Param.str(); }

void ArrayBounds::registerMatchers(MatchFinder &Finder) {
  Finder.addMatcher(functionDecl().bind("fn"), this);
  Finder.addMatcher(declRefExpr(to(parmVarDecl().bind("param"))).bind("ref"), this);
  Finder.addMatcher(
      arraySubscriptExpr(forFunction(functionDecl().bind("subscriptFn"))).bind("subscript"), this);
}

/// The values the counter V of a constant `for` (constantTripCount) takes in its body, when S is
/// in that body: [first, last]; std::nullopt when S is not in the body of such a loop of V.
static std::optional<std::pair<int64_t, int64_t>> counterRange(const Stmt *S, const VarDecl *V,
                                                                ASTContext &Ctx) {
  const Stmt *Child = S;
  for (;;) {
    auto Parents = Ctx.getParents(*Child);
    if (Parents.empty())
      return std::nullopt;
    const Stmt *P = Parents[0].get<Stmt>();
    if (!P)
      return std::nullopt;
    if (const auto *F = dyn_cast<ForStmt>(P)) {
      const auto *Init = dyn_cast_or_null<DeclStmt>(F->getInit());
      if (Init && Init->isSingleDecl() && Init->getSingleDecl() == V) {
        if (F->getBody() != Child)
          return std::nullopt;
        std::optional<uint64_t> N = constantTripCount(F, Ctx);
        Expr::EvalResult R;
        if (!N || !V->getInit() || !V->getInit()->EvaluateAsInt(R, Ctx))
          return std::nullopt;
        const int64_t A = R.Val.getInt().getExtValue();
        if (*N == 0)
          return std::make_pair(int64_t(0), int64_t(0)); // the body never runs
        const auto *Inc = cast<UnaryOperator>(F->getInc());
        return Inc->isIncrementOp() ? std::make_pair(A, A + int64_t(*N) - 1)
                                    : std::make_pair(A - int64_t(*N) + 1, A);
      }
    }
    Child = P;
  }
}

/// Whether the index I of an array of N elements is within bounds at compile time: a constant,
/// or the counter of a constant `for` around it whose values all are.
static bool provenInRange(const Expr *I, uint64_t N, const ArraySubscriptExpr *E,
                          ASTContext &Ctx) {
  Expr::EvalResult R;
  if (!I->isValueDependent() && I->EvaluateAsInt(R, Ctx)) {
    const llvm::APSInt &V = R.Val.getInt();
    return V.isNonNegative() && V.getActiveBits() <= 63 && uint64_t(V.getExtValue()) < N;
  }
  const auto *Ref = dyn_cast<DeclRefExpr>(I->IgnoreParenImpCasts());
  const auto *V = Ref ? dyn_cast<VarDecl>(Ref->getDecl()) : nullptr;
  if (!V)
    return false;
  std::optional<std::pair<int64_t, int64_t>> Range = counterRange(E, V, Ctx);
  return Range && Range->first >= 0 && uint64_t(Range->second) < N;
}

/// A subscript of a private (or __constant) array of N elements, `a[i]`, whose index is not
/// proven in range becomes `a[texcc_index(texcc_ctx, (i), N, __LINE__)]` (texcc_device.h): an
/// index out of range is 0 and a fault, reported as a __global read's is. Reads and writes alike
/// (an out-of-range private write was a SIGSEGV or a silent overwrite of another variable).
static void checkArraySubscript(const ArraySubscriptExpr *E, FileContext &FC, ASTContext &Ctx) {
  const Expr *Base = E->getBase()->IgnoreParenImpCasts();
  const auto *Array = Ctx.getAsConstantArrayType(Base->getType());
  if (!Array || E->getBase() != E->getLHS())
    return; // a pointer (the __global arrays: ArrayBounds::checkUse) or `i[a]`
  const uint64_t N = Array->getSize().getZExtValue();
  if (provenInRange(E->getIdx(), N, E, Ctx))
    return;
  DiagnosticsEngine &DE = Ctx.getDiagnostics();
  const SourceLocation RSquare = E->getRBracketLoc();
  const SourceLocation BaseEnd = E->getBase()->getEndLoc();
  const LangOptions &LO = Ctx.getLangOpts();
  llvm::Optional<Token> LSquare =
      BaseEnd.isFileID() ? Lexer::findNextToken(BaseEnd, FC.SM, LO) : llvm::None;
  if (!LSquare || LSquare->isNot(tok::l_square) || !RSquare.isFileID() ||
      FC.SM.getFileID(RSquare) != FC.SM.getFileID(LSquare->getLocation())) {
    unsigned Id = DE.getCustomDiagID(DiagnosticsEngine::Error,
                                     "cannot bounds-check this index of a %0-element array: its "
                                     "brackets come from a macro; write the subscript in one "
                                     "place, or index with a constant");
    DE.Report(E->getExprLoc(), Id) << std::to_string(N);
    return;
  }
  FC.Edits.replaceToken(LSquare->getLocation(), "[texcc_index(texcc_ctx, (");
  FC.Edits.replaceToken(RSquare, "), " + std::to_string(N) + "u, __LINE__)]");
}

void ArrayBounds::refuse(SourceLocation Loc, StringRef Name, StringRef Why) {
  DiagnosticsEngine &DE = FC.Ctx.getDiagnostics();
  unsigned Id = DE.getCustomDiagID(DiagnosticsEngine::Error,
                                   "cannot bounds-check __global array '%0' here: %1");
  DE.Report(Loc, Id) << Name << Why;
}

void ArrayBounds::run(const MatchFinder::MatchResult &Result) {
  if (const auto *E = Result.Nodes.getNodeAs<ArraySubscriptExpr>("subscript")) {
    if (FC.isUserFunction(Result.Nodes.getNodeAs<FunctionDecl>("subscriptFn")))
      checkArraySubscript(E, FC, *Result.Context);
    return;
  }
  if (const auto *Ref = Result.Nodes.getNodeAs<DeclRefExpr>("ref")) {
    const auto *P = Result.Nodes.getNodeAs<ParmVarDecl>("param");
    const auto *Fn = dyn_cast_or_null<FunctionDecl>(P->getDeclContext());
    if (Fn && FC.isUserFunction(Fn) && isGlobalPointer(P))
      checkUse(Ref, P, *Result.Context);
    return;
  }
  const auto *Fn = Result.Nodes.getNodeAs<FunctionDecl>("fn");
  if (!FC.isUserFunction(Fn))
    return;
  // Each __global pointer parameter takes its length along: `p` -> `p, uint texcc_n_p`.
  for (const ParmVarDecl *P : Fn->parameters()) {
    if (!isGlobalPointer(P))
      continue;
    if (elementName(P).empty()) {
      refuse(P->getLocation(), P->getName(),
             "its elements are " + P->getType()->getPointeeType().getAsString() +
                 "; only float, int, uint and their vectors are checked");
      continue;
    }
    if (!P->getName().empty()) {
      if (!P->getLocation().isFileID()) {
        refuse(P->getLocation(), P->getName(), "the parameter is declared by a macro");
        continue;
      }
      FC.Edits.replaceToken(P->getLocation(),
                            P->getName().str() + ", uint " + lengthName(P->getName()));
      continue;
    }
    SourceLocation End = P->getEndLoc();
    if (End.isInvalid() || !End.isFileID()) {
      refuse(Fn->getLocation(), "(unnamed)", "the parameter is declared by a macro");
      continue;
    }
    const LangOptions &LO = FC.Ctx.getLangOpts();
    StringRef Text = Lexer::getSourceText(CharSourceRange::getTokenRange(End), FC.SM, LO);
    FC.Edits.replaceToken(End, Text.str() + ", uint");
  }
}

/// The parent of E, through implicit casts; null at the top.
static const Stmt *parentOf(const Stmt *E, ASTContext &Ctx, const Stmt *&Child) {
  Child = E;
  while (true) {
    auto Parents = Ctx.getParents(*Child);
    if (Parents.empty())
      return nullptr;
    const Stmt *S = Parents[0].get<Stmt>();
    if (!S)
      return nullptr;
    if (!isa<ImplicitCastExpr>(S))
      return S;
    Child = S;
  }
}

void ArrayBounds::checkUse(const DeclRefExpr *Ref, const ParmVarDecl *P, ASTContext &Ctx) {
  const StringRef Name = P->getName();
  const SourceLocation Loc = Ref->getLocation();
  if (!Loc.isFileID()) {
    refuse(Loc, Name, "the array is used inside a macro; write the read outside the macro");
    return;
  }
  const Stmt *Child = nullptr;
  const Stmt *Parent = parentOf(Ref, Ctx, Child);
  if (const auto *Index = dyn_cast_or_null<ArraySubscriptExpr>(Parent)) {
    if (Index->getBase() != Child || Index->getLHS() != Child) {
      refuse(Loc, Name, "write the read as " + Name.str() + "[i]");
      return;
    }
    const Stmt *IndexChild = nullptr;
    const Stmt *Above = parentOf(Index, Ctx, IndexChild);
    while (Above && isa<ParenExpr>(Above))
      Above = parentOf(Above, Ctx, IndexChild);
    if (const auto *U = dyn_cast_or_null<UnaryOperator>(Above);
        U && U->getOpcode() == UO_AddrOf) {
      refuse(Loc, Name, "its elements' addresses may not be taken; read them as " + Name.str() +
                            "[i]");
      return;
    }
    const LangOptions &LO = Ctx.getLangOpts();
    llvm::Optional<Token> LSquare = Lexer::findNextToken(Loc, FC.SM, LO);
    const SourceLocation RSquare = Index->getRBracketLoc();
    if (!LSquare || LSquare->isNot(tok::l_square) || !RSquare.isFileID() ||
        FC.SM.getFileID(RSquare) != FC.SM.getFileID(Loc)) {
      refuse(Loc, Name, "the read's brackets come from a macro; write " + Name.str() +
                            "[i] in one place");
      return;
    }
    FC.Edits.replace(Loc, LSquare->getEndLoc(),
                     "texcc_read_" + elementName(P) + "(texcc_ctx, " + Name.str() + ", (");
    FC.Edits.replaceToken(RSquare, "), " + lengthName(Name) + ", __LINE__)");
    return;
  }
  if (const auto *Call = dyn_cast_or_null<CallExpr>(Parent)) {
    const FunctionDecl *Callee = Call->getDirectCallee();
    if (Callee && FC.isUserFunction(Callee)) {
      for (unsigned I = 0; I < Call->getNumArgs() && I < Callee->getNumParams(); ++I)
        if (Call->getArg(I) == Child && isGlobalPointer(Callee->getParamDecl(I))) {
          FC.Edits.replaceToken(Loc, Name.str() + ", " + lengthName(Name));
          return;
        }
    }
    refuse(Loc, Name,
           "it may be passed whole only to a user function's __global array parameter; read "
           "its elements as " +
               Name.str() + "[i]");
    return;
  }
  refuse(Loc, Name,
         "pointer arithmetic and other uses escape the check; read its elements as " +
             Name.str() + "[i]");
}

void ResourceLimits::registerMatchers(MatchFinder &Finder) {
  Finder.addMatcher(varDecl(hasType(constantArrayType())).bind("array"), this);
  // Clang 15 has no attributedStmt() matcher: a loop's parent holds its pragmas.
  Finder.addMatcher(stmt(anyOf(forStmt(), whileStmt(), doStmt()),
                         hasParent(stmt().bind("attributed")),
                         forFunction(functionDecl().bind("fn"))),
                    this);
  Finder.addMatcher(stmt(anyOf(gotoStmt(), addrLabelExpr()),
                         forFunction(functionDecl().bind("fn")))
                        .bind("goto"),
                    this);
}

void ResourceLimits::run(const MatchFinder::MatchResult &Result) {
  const auto *Array = Result.Nodes.getNodeAs<VarDecl>("array");
  const auto *Fn = Array ? dyn_cast_or_null<FunctionDecl>(Array->getParentFunctionOrMethod())
                         : Result.Nodes.getNodeAs<FunctionDecl>("fn");
  if (!FC.isUserFunction(Fn))
    return;
  DiagnosticsEngine &DE = FC.Ctx.getDiagnostics();
  if (const auto *Goto = Result.Nodes.getNodeAs<Stmt>("goto")) {
    unsigned Id = DE.getCustomDiagID(DiagnosticsEngine::Error,
                                     "goto is not supported in texture code: a backward goto is a "
                                     "loop that the loop budget cannot bound; write it as a for, "
                                     "while or do loop");
    DE.Report(Goto->getBeginLoc(), Id);
    return;
  }
  if (Array) {
    if (Array->getType().getAddressSpace() != LangAS::opencl_private &&
        Array->getType().getAddressSpace() != LangAS::Default)
      return;
    const uint64_t Bytes = FC.Ctx.getTypeSizeInChars(Array->getType()).getQuantity();
    if (Bytes <= MaxPrivateArrayBytes)
      return;
    unsigned Id = DE.getCustomDiagID(DiagnosticsEngine::Error,
                                     "private array '%0' takes %1 bytes; texture code may use at "
                                     "most %2 bytes per private array (the work-item's stack)");
    DE.Report(Array->getLocation(), Id)
        << Array->getName() << std::to_string(Bytes) << std::to_string(MaxPrivateArrayBytes);
    return;
  }
  const auto *Attributed = dyn_cast<AttributedStmt>(Result.Nodes.getNodeAs<Stmt>("attributed"));
  if (!Attributed)
    return;
  for (const Attr *A : Attributed->getAttrs()) {
    const auto *Hint = dyn_cast<LoopHintAttr>(A);
    if (!Hint || Hint->getOption() != LoopHintAttr::UnrollCount || !Hint->getValue())
      continue;
    Expr::EvalResult Value;
    if (!Hint->getValue()->EvaluateAsInt(Value, FC.Ctx))
      continue;
    const llvm::APSInt &N = Value.Val.getInt();
    if (N.getExtValue() <= int64_t(MaxUnrollCount))
      continue;
    unsigned Id = DE.getCustomDiagID(DiagnosticsEngine::Error,
                                     "unroll count %0 is too large; texture code may unroll a "
                                     "loop at most %1 times (the device build's time and memory)");
    DE.Report(Hint->getLocation(), Id) << toString(N, 10) << std::to_string(MaxUnrollCount);
  }
}

} // namespace texcc::frontend
