// The loop budget (docs/reliability.md "User code"): texcc knows every loop of the user's
// textures, so it bounds each with the work-item's loop budget (texcc_device.h): a charge before
// a loop whose trip count it can compute, a tick per iteration of any other.
#include "Callbacks.h"

#include "clang/AST/Attr.h"
#include "clang/Lex/Lexer.h"

using namespace clang;
using namespace clang::ast_matchers;

namespace texcc::frontend {

/// What every loop condition ends with: one iteration of the work-item's budget.
static const char *const LoopTick = "texcc_loop_continues(texcc_ctx, __LINE__)";

void LoopBudget::registerMatchers(MatchFinder &Finder) {
  Finder.addMatcher(
      stmt(anyOf(forStmt(), whileStmt(), doStmt()), forFunction(functionDecl().bind("fn")))
          .bind("loop"),
      this);
}

/// Charged once before a loop whose trip count the front end knows (constantTripCount).
static const char *const LoopCharge = "texcc_loop_charge(texcc_ctx, ";

/// True when every use of V under S only reads it (an lvalue-to-rvalue conversion): no
/// assignment, increment or address taken.
static bool onlyReads(const Stmt *S, const Stmt *Parent, const VarDecl *V) {
  if (!S)
    return true;
  if (const auto *Ref = dyn_cast<DeclRefExpr>(S); Ref && Ref->getDecl() == V) {
    const auto *Cast = dyn_cast_or_null<ImplicitCastExpr>(Parent);
    return Cast && Cast->getCastKind() == CK_LValueToRValue;
  }
  for (const Stmt *Child : S->children())
    if (!onlyReads(Child, S, V))
      return false;
  return true;
}

/// The number of iterations of `for (int i = A; i OP B; ++i / i++ / --i / i--)` with integer
/// constants A and B, i a signed integer of at least 32 bits that the body only reads and
/// OP one of < <= > >= !=; std::nullopt for any other loop (or one that would not end).
std::optional<uint64_t> constantTripCount(const ForStmt *F, const ASTContext &Ctx) {
  const auto *Init = dyn_cast_or_null<DeclStmt>(F->getInit());
  if (!Init || !Init->isSingleDecl())
    return std::nullopt;
  const auto *V = dyn_cast<VarDecl>(Init->getSingleDecl());
  if (!V || !V->getInit() || !V->getType()->isSignedIntegerType() ||
      Ctx.getTypeSize(V->getType()) < 32 || V->getType().isVolatileQualified())
    return std::nullopt;
  auto constant = [&](const Expr *E) -> std::optional<int64_t> {
    if (!E || E->isValueDependent())
      return std::nullopt;
    Expr::EvalResult R;
    if (!E->EvaluateAsInt(R, Ctx))
      return std::nullopt;
    const llvm::APSInt &I = R.Val.getInt();
    if (I.getMinSignedBits() > 32)
      return std::nullopt;
    return I.getExtValue();
  };
  std::optional<int64_t> Start = constant(V->getInit());
  const auto *Cond = dyn_cast_or_null<BinaryOperator>(F->getCond());
  const auto *Inc = dyn_cast_or_null<UnaryOperator>(F->getInc());
  if (!Start || !Cond || !Inc || !Inc->isIncrementDecrementOp())
    return std::nullopt;
  const auto *IncRef = dyn_cast<DeclRefExpr>(Inc->getSubExpr()->IgnoreParens());
  const auto *CondRef = dyn_cast<DeclRefExpr>(Cond->getLHS()->IgnoreParenImpCasts());
  if (!IncRef || IncRef->getDecl() != V || !CondRef || CondRef->getDecl() != V)
    return std::nullopt;
  std::optional<int64_t> End = constant(Cond->getRHS());
  if (!End || !onlyReads(F->getBody(), F, V) || !onlyReads(Cond->getRHS(), Cond, V))
    return std::nullopt;
  const int64_t A = *Start, B = *End;
  const bool Up = Inc->isIncrementOp();
  switch (Cond->getOpcode()) {
  case BO_LT:
    return Up ? std::optional<uint64_t>(B > A ? B - A : 0) : std::nullopt;
  case BO_LE:
    return Up && B < INT32_MAX ? std::optional<uint64_t>(B >= A ? B - A + 1 : 0) : std::nullopt;
  case BO_GT:
    return !Up ? std::optional<uint64_t>(A > B ? A - B : 0) : std::nullopt;
  case BO_GE:
    return !Up && B > INT32_MIN ? std::optional<uint64_t>(A >= B ? A - B + 1 : 0)
                                : std::nullopt;
  case BO_NE:
    if (Up && A <= B)
      return B - A;
    if (!Up && A >= B)
      return A - B;
    return std::nullopt;
  default:
    return std::nullopt;
  }
}

/// Charged once before a loop whose trip count is a loop-invariant span (invariantTripSpan).
static const char *const LoopChargeSpan = "texcc_loop_charge_span(texcc_ctx, ";
/// The same for such a loop that charges for the constant loops nested in it (perIteration):
/// its span times their iterations per iteration of its own.
static const char *const LoopChargeNest = "texcc_loop_charge_nest(texcc_ctx, ";

/// Whether V's address is taken anywhere under S (then a write through a pointer could change it
/// where no assignment names it).
static bool addressTaken(const Stmt *S, const VarDecl *V) {
  if (!S)
    return false;
  if (const auto *U = dyn_cast<UnaryOperator>(S); U && U->getOpcode() == UO_AddrOf)
    if (const auto *Ref = dyn_cast<DeclRefExpr>(U->getSubExpr()->IgnoreParens());
        Ref && Ref->getDecl() == V)
      return true;
  for (const Stmt *Child : S->children())
    if (addressTaken(Child, V))
      return true;
  return false;
}

/// Whether E is side-effect free and has the same value before the loop F and at every test of
/// it: integer literals, arithmetic, casts, and reads of integer variables that are local,
/// parameters or const, whose address the function never takes, that neither F's body nor its
/// condition nor its increment writes, and that are not Counter.
static bool loopInvariant(const Expr *E, const ForStmt *F, const VarDecl *Counter,
                          const FunctionDecl *Fn) {
  E = E->IgnoreParens();
  if (isa<IntegerLiteral, CharacterLiteral>(E))
    return true;
  if (const auto *C = dyn_cast<CastExpr>(E))
    return (isa<ImplicitCastExpr>(C) || isa<CStyleCastExpr>(C)) &&
           C->getType()->isIntegerType() && loopInvariant(C->getSubExpr(), F, Counter, Fn);
  if (const auto *U = dyn_cast<UnaryOperator>(E))
    return (U->getOpcode() == UO_Minus || U->getOpcode() == UO_Plus ||
            U->getOpcode() == UO_Not) &&
           loopInvariant(U->getSubExpr(), F, Counter, Fn);
  if (const auto *B = dyn_cast<BinaryOperator>(E))
    return !B->isAssignmentOp() && !B->isCommaOp() &&
           loopInvariant(B->getLHS(), F, Counter, Fn) && loopInvariant(B->getRHS(), F, Counter, Fn);
  if (const auto *C = dyn_cast<ConditionalOperator>(E))
    return loopInvariant(C->getCond(), F, Counter, Fn) &&
           loopInvariant(C->getTrueExpr(), F, Counter, Fn) &&
           loopInvariant(C->getFalseExpr(), F, Counter, Fn);
  const auto *Ref = dyn_cast<DeclRefExpr>(E);
  if (!Ref)
    return false;
  if (isa<EnumConstantDecl>(Ref->getDecl()))
    return true;
  const auto *V = dyn_cast<VarDecl>(Ref->getDecl());
  if (!V || V == Counter || !V->getType()->isIntegerType() ||
      V->getType().isVolatileQualified())
    return false;
  if (!V->hasLocalStorage())
    return V->getType().isConstQualified();
  return !addressTaken(Fn->getBody(), V) && onlyReads(F->getBody(), F, V) &&
         onlyReads(F->getCond(), F, V) && onlyReads(F->getInc(), F, V);
}

/// The source text of E if it is spelled in File without macros at its ends.
static std::optional<std::string> spelledText(const Expr *E, const FileContext &FC, FileID File) {
  SourceLocation B = E->getBeginLoc(), End = E->getEndLoc();
  if (B.isInvalid() || End.isInvalid() || !B.isFileID() || !End.isFileID() ||
      FC.SM.getFileID(B) != File || FC.SM.getFileID(End) != File)
    return std::nullopt;
  return Lexer::getSourceText(CharSourceRange::getTokenRange(B, End), FC.SM,
                              FC.Ctx.getLangOpts())
      .str();
}

/// The branch-free charge of a constant `for` (constantForm): 0, or the loop's line when the
/// budget cannot pay for it.
static const char *const LoopChargeOnce = "texcc_loop_charge_once(texcc_ctx, ";

/// How texcc charges a constant `for (T i = A; ...)` of N >= 1 iterations whose start A is an
/// integer literal (with a sign): the charge becomes the loop's first declaration and picks
/// its start, `for (T texcc_bad = texcc_loop_charge_once(texcc_ctx, C, __LINE__), i = texcc_bad ?
/// (LAST) : (A); ...) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else BODY`, LAST
/// being i's value in its last iteration. Without enough budget the loop makes that one
/// iteration, which records the fault and runs nothing of the body (and so none of the loops
/// nested in it); with enough, it runs as written. Unlike `if (!charge) {} else for`, nothing
/// branches before the loop: the start is a select and the loop's first test is always true, so
/// the device compiler needs no guard around it. The guard mattered: before the kernel is
/// inlined into its material, the budget is not known and a guard is a real branch; the code
/// of earlier nodes then stays in front of the loop where the unchecked kernel moves it past
/// (LLVM's IndVarSimplify sinks a loop preheader's unused values into its exit), and the device
/// compiler vectorises it worse: scratches inline took 6.6% longer checked than unchecked with
/// the same instructions (bench/loop-budget.md). The text edits: the counter's name token, the
/// start literal and the head's ')'; std::nullopt leaves the loop to the `if` form.
struct ConstantForm {
  clang::SourceLocation Name, InitBegin, InitEnd;
  std::string NameText, InitText;
  int64_t Last = 0;
};

static std::optional<ConstantForm> constantForm(const ForStmt *F, uint64_t Trips,
                                                const FileContext &FC, FileID File) {
  if (Trips == 0)
    return std::nullopt;
  const auto *Init = dyn_cast_or_null<DeclStmt>(F->getInit());
  const auto *Inc = dyn_cast_or_null<UnaryOperator>(F->getInc());
  if (!Init || !Init->isSingleDecl() || !Inc)
    return std::nullopt;
  const auto *V = dyn_cast<VarDecl>(Init->getSingleDecl());
  if (!V || !V->getInit())
    return std::nullopt;
  // The start: an integer literal, perhaps with a sign (no macro, nothing another edit touches).
  const Expr *Start = V->getInit()->IgnoreParenImpCasts();
  if (const auto *U = dyn_cast<UnaryOperator>(Start);
      U && (U->getOpcode() == UO_Minus || U->getOpcode() == UO_Plus))
    Start = U->getSubExpr()->IgnoreParenImpCasts();
  if (!isa<IntegerLiteral>(Start))
    return std::nullopt;
  Expr::EvalResult R;
  if (!V->getInit()->EvaluateAsInt(R, FC.Ctx))
    return std::nullopt;
  const int64_t A = R.Val.getInt().getExtValue();
  const int64_t Steps = static_cast<int64_t>(Trips - 1);
  ConstantForm Form;
  Form.Last = Inc->isIncrementOp() ? A + Steps : A - Steps;
  Form.Name = V->getLocation();
  Form.InitBegin = V->getInit()->getBeginLoc();
  Form.InitEnd = V->getInit()->getEndLoc();
  for (SourceLocation L : {Form.Name, Form.InitBegin, Form.InitEnd})
    if (L.isInvalid() || !L.isFileID() || FC.SM.getFileID(L) != File)
      return std::nullopt;
  std::optional<std::string> Text = spelledText(V->getInit(), FC, File);
  if (!Text || V->getName().empty())
    return std::nullopt;
  Form.NameText = V->getName().str();
  Form.InitText = *Text;
  return Form;
}

/// For `for (int i = A; i + K < B; ++i)` (K an integer constant, 0 when absent) or
/// `for (int i = A; i + K > B; --i)`, with A and B side-effect free, B loop-invariant
/// (loopInvariant), i a signed integer of at least 32 bits that the body only reads and the
/// comparison signed: the text of the trip count's span, `(long)(B) - (long)(A) - K` (up) or
/// `(long)(A) - (long)(B) + K` (down), which the device clamps at 0 (texcc_loop_charge_span).
/// std::nullopt for any other loop. A loop that leaves early (break, return) is charged its
/// whole span: the budget is an upper bound.
static std::optional<std::string> invariantTripSpan(const ForStmt *F, const FunctionDecl *Fn,
                                                    const FileContext &FC, FileID File) {
  const auto *Init = dyn_cast_or_null<DeclStmt>(F->getInit());
  if (!Init || !Init->isSingleDecl())
    return std::nullopt;
  const auto *V = dyn_cast<VarDecl>(Init->getSingleDecl());
  if (!V || !V->getInit() || !V->getType()->isSignedIntegerType() ||
      FC.Ctx.getTypeSize(V->getType()) < 32 || V->getType().isVolatileQualified())
    return std::nullopt;
  const auto *Cond = dyn_cast_or_null<BinaryOperator>(F->getCond());
  const auto *Inc = dyn_cast_or_null<UnaryOperator>(F->getInc());
  if (!Cond || !Inc || !Inc->isIncrementDecrementOp() ||
      !Cond->getLHS()->getType()->isSignedIntegerType() ||
      FC.Ctx.getTypeSize(Cond->getLHS()->getType()) > 64)
    return std::nullopt;
  const bool Up = Inc->isIncrementOp();
  if (Cond->getOpcode() != (Up ? BO_LT : BO_GT))
    return std::nullopt;
  const auto *IncRef = dyn_cast<DeclRefExpr>(Inc->getSubExpr()->IgnoreParens());
  if (!IncRef || IncRef->getDecl() != V)
    return std::nullopt;
  // The left side: i, or i + K / i - K.
  const Expr *Lhs = Cond->getLHS()->IgnoreParenImpCasts();
  int64_t K = 0;
  if (const auto *Add = dyn_cast<BinaryOperator>(Lhs);
      Add && (Add->getOpcode() == BO_Add || Add->getOpcode() == BO_Sub)) {
    Expr::EvalResult R;
    if (Add->getRHS()->isValueDependent() || !Add->getRHS()->EvaluateAsInt(R, FC.Ctx) ||
        R.Val.getInt().getMinSignedBits() > 32)
      return std::nullopt;
    K = Add->getOpcode() == BO_Add ? R.Val.getInt().getExtValue() : -R.Val.getInt().getExtValue();
    Lhs = Add->getLHS()->IgnoreParenImpCasts();
  }
  const auto *CondRef = dyn_cast<DeclRefExpr>(Lhs);
  if (!CondRef || CondRef->getDecl() != V || !onlyReads(F->getBody(), F, V))
    return std::nullopt;
  const Expr *Start = V->getInit(), *End = Cond->getRHS();
  if (Start->HasSideEffects(FC.Ctx) || !loopInvariant(Start, F, V, Fn) ||
      !loopInvariant(End, F, V, Fn))
    return std::nullopt;
  std::optional<std::string> A = spelledText(Start, FC, File), B = spelledText(End, FC, File);
  if (!A || !B)
    return std::nullopt;
  std::string Span = Up ? "(long)(" + *B + ") - (long)(" + *A + ")"
                        : "(long)(" + *A + ") - (long)(" + *B + ")";
  const int64_t Shift = Up ? -K : K;
  if (Shift > 0)
    Span += " + " + std::to_string(Shift);
  else if (Shift < 0)
    Span += " - " + std::to_string(-Shift);
  return Span;
}

/// The tokens of a loop head, from its '(' to its ')', spelled in one file.
struct LoopHead {
  FileID File;
  std::vector<Token> Tokens; // '(' ... ')'
};

/// Raw-lexes the parenthesised head that starts at the spelled '(' LParen and ends at the
/// spelled ')' RParen; std::nullopt unless both are in the same file, in order.
static std::optional<LoopHead> lexHead(const FileContext &FC, SourceLocation LParen,
                                       SourceLocation RParen) {
  const SourceManager &SM = FC.SM;
  if (LParen.isInvalid() || RParen.isInvalid() || !LParen.isFileID() || !RParen.isFileID())
    return std::nullopt;
  auto [File, Begin] = SM.getDecomposedLoc(LParen);
  auto [EndFile, End] = SM.getDecomposedLoc(RParen);
  if (File != EndFile || End <= Begin || !SM.getFileEntryForID(File))
    return std::nullopt;
  StringRef Buffer = SM.getBufferData(File);
  Lexer Lex(SM.getLocForStartOfFile(File), FC.Ctx.getLangOpts(), Buffer.begin(),
            Buffer.begin() + Begin, Buffer.end());
  LoopHead Head;
  Head.File = File;
  Token T;
  while (!Lex.LexFromRawLexer(T) || T.isNot(tok::eof)) {
    Head.Tokens.push_back(T);
    if (SM.getFileOffset(T.getLocation()) >= End)
      break;
  }
  if (Head.Tokens.size() < 2 || Head.Tokens.front().isNot(tok::l_paren) ||
      SM.getFileOffset(Head.Tokens.back().getLocation()) != End ||
      Head.Tokens.back().isNot(tok::r_paren))
    return std::nullopt;
  return Head;
}

/// How the budget can charge a `for` once before it runs: its constant trip count
/// (constantTripCount), or else the text of its loop-invariant span (invariantTripSpan);
/// std::nullopt for a loop that ticks per iteration (or whose head cannot be rewritten).
struct ForCharge {
  std::optional<uint64_t> Trips;
  std::string Span;
};

static std::optional<ForCharge> forCharge(const ForStmt *F, const FunctionDecl *Fn,
                                          FileContext &FC) {
  std::optional<LoopHead> Head =
      lexHead(FC, FC.spelled(F->getLParenLoc()), FC.spelled(F->getRParenLoc()));
  const SourceLocation ForLoc = F->getForLoc();
  if (!Head || !ForLoc.isFileID() || FC.SM.getFileID(ForLoc) != Head->File)
    return std::nullopt;
  if (std::optional<uint64_t> Trips = constantTripCount(F, FC.Ctx))
    return ForCharge{Trips, ""};
  if (std::optional<std::string> Span = invariantTripSpan(F, Fn, FC, Head->File))
    return ForCharge{std::nullopt, *Span};
  return std::nullopt;
}

/// The `for` whose body holds S, with no other loop between them, or null: S is at the
/// function's top level, inside a `while` or `do` first, or reached through a declaration or a
/// loop's head (a statement expression).
static const ForStmt *enclosingFor(const Stmt *S, ASTContext &Ctx) {
  const Stmt *Child = S;
  while (true) {
    const DynTypedNodeList Parents = Ctx.getParents(*Child);
    if (Parents.size() != 1)
      return nullptr;
    const Stmt *Up = Parents[0].get<Stmt>();
    if (!Up || isa<WhileStmt, DoStmt>(Up))
      return nullptr;
    if (const auto *F = dyn_cast<ForStmt>(Up))
      return F->getBody() == Child ? F : nullptr;
    Child = Up;
  }
}

/// The most a charge may be: the budget's counter is 32 bits.
static constexpr uint64_t MaxCharge = UINT32_MAX;

/// A charged `for` F also charges for the constant loops nested in it (no other loop between):
/// each runs at most once per iteration of F, so F is charged, per iteration of its own, 1 plus
/// each such loop's whole count (its trips times its own per-iteration count), and they carry
/// no charge of their own. Summed this way a perfect constant nest (voronoi's 3x3x3 search:
/// 3 * (1 + 3 * (1 + 3)) = 39) is charged what its loops' separate charges added up to, in one
/// test. A nested loop that does not run (an `if` around it, an early `break`) is charged all
/// the same: the budget is an upper bound. 1 when F charges for none (none there, or the total
/// would pass MaxCharge: then they charge themselves).
uint64_t LoopBudget::perIteration(const ForStmt *F, const FunctionDecl *Fn) {
  if (auto It = PerIterationMemo.find(F); It != PerIterationMemo.end())
    return It->second;
  std::optional<ForCharge> Own = forCharge(F, Fn, FC);
  uint64_t Sum = 1;
  bool Fits = Own.has_value();
  std::vector<const Stmt *> Work{F->getBody()};
  while (Fits && !Work.empty()) {
    const Stmt *S = Work.back();
    Work.pop_back();
    if (!S || isa<WhileStmt, DoStmt>(S))
      continue; // the loops inside a while or do are charged there
    if (const auto *C = dyn_cast<ForStmt>(S)) {
      if (enclosingFor(C, FC.Ctx) != F)
        continue;
      std::optional<ForCharge> Inner = forCharge(C, Fn, FC);
      if (!Inner || !Inner->Trips)
        continue; // charged (its span) or ticking on its own, with what it holds
      const uint64_t Per = perIteration(C, Fn);
      if (*Inner->Trips != 0 && Per > MaxCharge / *Inner->Trips) {
        Fits = false;
        break;
      }
      Sum += *Inner->Trips * Per;
      Fits = Sum <= MaxCharge;
      continue;
    }
    for (const Stmt *Child : S->children())
      Work.push_back(Child);
  }
  if (Fits && Own->Trips && *Own->Trips != 0 && Sum > MaxCharge / *Own->Trips)
    Fits = false;
  const uint64_t Result = Fits ? Sum : 1;
  PerIterationMemo[F] = Result;
  return Result;
}

void LoopBudget::run(const MatchFinder::MatchResult &Result) {
  const auto *Fn = Result.Nodes.getNodeAs<FunctionDecl>("fn");
  const auto *Loop = Result.Nodes.getNodeAs<Stmt>("loop");
  if (!FC.isUserFunction(Fn))
    return;
  SourceLocation LParen, RParen;
  if (const auto *W = dyn_cast<WhileStmt>(Loop)) {
    LParen = FC.spelled(W->getLParenLoc());
    RParen = FC.spelled(W->getRParenLoc());
  } else if (const auto *D = dyn_cast<DoStmt>(Loop)) {
    LParen = FC.lparenAfter(FC.spelled(D->getWhileLoc()));
    RParen = FC.spelled(D->getRParenLoc());
  } else {
    const auto *F = cast<ForStmt>(Loop);
    LParen = FC.spelled(F->getLParenLoc());
    RParen = FC.spelled(F->getRParenLoc());
  }
  std::optional<LoopHead> Head = lexHead(FC, LParen, RParen);
  if (!Head) {
    reportUnbounded(Loop->getBeginLoc());
    return;
  }
  const std::string Tick = LoopTick;
  if (!isa<ForStmt>(Loop)) {
    // while (c) -> while ((c) && tick): the condition first, so that an iteration that the
    // condition ends does not count.
    FC.Edits.replaceToken(LParen, "((");
    FC.Edits.replaceToken(RParen, ") && " + Tick + ")");
    return;
  }
  // A loop of a known trip count N is charged once before it runs, so that its iterations carry
  // no test (and the device compiler can unroll it): for (...) -> if (!charge(N)) {} else
  // for (...), the empty branch first so that an `else` after the loop keeps its `if`. A loop
  // whose bound does not change while it runs (fbm's octaves, a ramp's stop count) is charged
  // its span once in the same way. A constant loop nested in a charged one is charged there
  // (perIteration) and is left as written.
  const auto *For = cast<ForStmt>(Loop);
  const SourceLocation ForLoc = For->getForLoc();
  if (std::optional<ForCharge> Charge = forCharge(For, Fn, FC)) {
    if (const ForStmt *Outer = enclosingFor(For, FC.Ctx);
        Charge->Trips && Outer && perIteration(Outer, Fn) > 1)
      return;
    const uint64_t Per = perIteration(For, Fn);
    if (Charge->Trips) {
      const FileID File = FC.SM.getFileID(ForLoc);
      if (std::optional<ConstantForm> Form = constantForm(For, *Charge->Trips, FC, File)) {
        FC.Edits.replaceToken(Form->Name, "texcc_bad = " + std::string(LoopChargeOnce) +
                                              std::to_string(*Charge->Trips * Per) +
                                              "u, __LINE__), " + Form->NameText);
        FC.Edits.replace(Form->InitBegin,
                         Lexer::getLocForEndOfToken(Form->InitEnd, 0, FC.SM,
                                                    FC.Ctx.getLangOpts()),
                         "texcc_bad ? (" + std::to_string(Form->Last) + ") : (" +
                             Form->InitText + ")");
        FC.Edits.replaceToken(RParen,
                              ") if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else");
        return;
      }
    }
    if (Charge->Trips)
      FC.Edits.replaceToken(ForLoc, "if (!" + std::string(LoopCharge) +
                                        std::to_string(*Charge->Trips * Per) +
                                        "u, __LINE__)) {} else for");
    else if (Per > 1)
      FC.Edits.replaceToken(ForLoc, "if (!" + std::string(LoopChargeNest) + Charge->Span +
                                        ", " + std::to_string(Per) +
                                        "u, __LINE__)) {} else for");
    else
      FC.Edits.replaceToken(ForLoc, "if (!" + std::string(LoopChargeSpan) + Charge->Span +
                                        ", __LINE__)) {} else for");
    return;
  }
  // for (init; c; inc) -> for (init; (c) && tick; inc); for (init;; inc) -> for (init; tick; inc).
  std::vector<size_t> Semis;
  int Depth = 0;
  for (size_t I = 0; I < Head->Tokens.size(); ++I) {
    const Token &T = Head->Tokens[I];
    if (T.isOneOf(tok::l_paren, tok::l_square, tok::l_brace))
      ++Depth;
    else if (T.isOneOf(tok::r_paren, tok::r_square, tok::r_brace))
      --Depth;
    else if (T.is(tok::semi) && Depth == 1)
      Semis.push_back(I);
  }
  if (Semis.size() != 2) {
    reportUnbounded(Loop->getBeginLoc());
    return;
  }
  const Token &First = Head->Tokens[Semis[0]], &Second = Head->Tokens[Semis[1]];
  if (Semis[1] == Semis[0] + 1) {
    FC.Edits.replaceToken(Second.getLocation(), " " + Tick + ";");
    return;
  }
  // Replace the blanks around the condition too, so that it reads `; (c) && tick;`.
  const Token &CondFirst = Head->Tokens[Semis[0] + 1], &CondLast = Head->Tokens[Semis[1] - 1];
  FC.Edits.replace(First.getLocation(), CondFirst.getLocation(), "; (");
  FC.Edits.replace(CondLast.getEndLoc(), Second.getEndLoc(), ") && " + Tick + ";");
}

void LoopBudget::reportUnbounded(SourceLocation Loc) {
  DiagnosticsEngine &DE = FC.Ctx.getDiagnostics();
  unsigned Id = DE.getCustomDiagID(DiagnosticsEngine::Error,
                                   "cannot bound this loop with the loop budget: its parentheses "
                                   "come from different macro expansions; spell the loop's head "
                                   "in one place");
  DE.Report(Loc, Id);
}

} // namespace texcc::frontend
