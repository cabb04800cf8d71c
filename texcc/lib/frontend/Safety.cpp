// Safety of user code (docs/reliability.md "User code"): texcc knows every loop of the user's
// textures, so it bounds them with the work-item's loop budget (texcc_device.h), and refuses
// what would take the device compiler or the work-item's stack down: huge private arrays and
// huge unroll counts.
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

void ResourceLimits::registerMatchers(MatchFinder &Finder) {
  Finder.addMatcher(varDecl(hasType(constantArrayType())).bind("array"), this);
  // Clang 15 has no attributedStmt() matcher: a loop's parent holds its pragmas.
  Finder.addMatcher(stmt(anyOf(forStmt(), whileStmt(), doStmt()),
                         hasParent(stmt().bind("attributed")),
                         forFunction(functionDecl().bind("fn"))),
                    this);
}

void ResourceLimits::run(const MatchFinder::MatchResult &Result) {
  const auto *Array = Result.Nodes.getNodeAs<VarDecl>("array");
  const auto *Fn = Array ? dyn_cast_or_null<FunctionDecl>(Array->getParentFunctionOrMethod())
                         : Result.Nodes.getNodeAs<FunctionDecl>("fn");
  if (!FC.isUserFunction(Fn))
    return;
  DiagnosticsEngine &DE = FC.Ctx.getDiagnostics();
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
