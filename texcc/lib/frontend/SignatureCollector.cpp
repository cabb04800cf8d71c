#include "Callbacks.h"

#include "clang/Lex/Lexer.h"

#include <cstdlib>

using namespace clang;
using namespace clang::ast_matchers;

namespace texcc::frontend {

using graph::BaseType;

void SignatureCollector::registerMatchers(MatchFinder &Finder) {
  Finder.addMatcher(functionDecl(isDefinition()).bind("def"), this);
  Finder.addMatcher(callExpr(callee(functionDecl().bind("callee")),
                             forFunction(functionDecl().bind("caller")))
                        .bind("call"),
                    this);
}

void SignatureCollector::run(const MatchFinder::MatchResult &Result) {
  if (const auto *FD = Result.Nodes.getNodeAs<FunctionDecl>("def")) {
    if (FC.isUserFunction(FD))
      FC.Definitions.emplace(FD->getName().str(), FD);
    return;
  }
  const auto *Call = Result.Nodes.getNodeAs<CallExpr>("call");
  const auto *Callee = Result.Nodes.getNodeAs<FunctionDecl>("callee");
  const auto *Caller = Result.Nodes.getNodeAs<FunctionDecl>("caller");
  if (!FC.isUserFunction(Callee) || !FC.isUserFunction(Caller))
    return;
  SourceLocation Loc = Call->getCallee()->getExprLoc();
  FC.Calls.push_back({FC.renamed(Caller), FC.renamed(Callee), Loc});
  FC.Called.emplace(FC.renamed(Callee), Loc);
}

std::optional<graph::ValueType> SignatureCollector::paramType(QualType T) const {
  if (const auto *P = T->getAs<PointerType>()) {
    QualType Pointee = P->getPointeeType();
    if (Pointee.getAddressSpace() != LangAS::opencl_global || !Pointee.isConstQualified())
      return std::nullopt;
    auto B = textureValueType(Pointee.getUnqualifiedType());
    if (!B || *B == BaseType::Sampler)
      return std::nullopt;
    return graph::ValueType{*B, true};
  }
  auto B = textureValueType(T.getUnqualifiedType());
  if (!B)
    return std::nullopt;
  return graph::ValueType{*B, false};
}

/// The type as the user wrote it ("float3 *"), else as Clang prints it.
std::string SignatureCollector::writtenType(SourceRange Range, QualType T) const {
  CharSourceRange R = Lexer::makeFileCharRange(CharSourceRange::getTokenRange(Range), FC.SM,
                                               FC.Ctx.getLangOpts());
  if (R.isValid()) {
    StringRef Text = Lexer::getSourceText(R, FC.SM, FC.Ctx.getLangOpts());
    if (!Text.empty() && !Text.contains('\n'))
      return Text.str();
  }
  return T.getAsString();
}

std::set<std::string> SignatureCollector::reachableFrom(const std::string &Renamed) const {
  std::set<std::string> Seen{Renamed};
  std::vector<std::string> Work{Renamed};
  while (!Work.empty()) {
    std::string Fn = Work.back();
    Work.pop_back();
    for (const CallSite *C : FC.callsFrom(Fn))
      if (Seen.insert(C->Callee).second)
        Work.push_back(C->Callee);
  }
  return Seen;
}

/// For the cost estimate: the number of times a for loop runs when that is plain from its
/// text: `for (int i = A; i < B; ++i)` with integer constants A and B (also <=, >, >=, i++,
/// --i, i--, i += C, i -= C); otherwise std::nullopt. The loop budget's own count, which also
/// requires that the body only reads the counter, is LoopBudget.cpp's constantTripCount.
static std::optional<uint64_t> estimatedTripCount(const ForStmt *F, const ASTContext &Ctx) {
  const auto *Init = dyn_cast_or_null<DeclStmt>(F->getInit());
  const auto *Cond = dyn_cast_or_null<BinaryOperator>(F->getCond());
  if (!Init || !Init->isSingleDecl() || !Cond)
    return std::nullopt;
  const auto *Var = dyn_cast<VarDecl>(Init->getSingleDecl());
  if (!Var || !Var->getInit())
    return std::nullopt;
  const auto *CondVar = dyn_cast<DeclRefExpr>(Cond->getLHS()->IgnoreParenImpCasts());
  auto From = Var->getInit()->getIntegerConstantExpr(Ctx);
  auto To = Cond->getRHS()->getIntegerConstantExpr(Ctx);
  if (!CondVar || CondVar->getDecl() != Var || !From || !To)
    return std::nullopt;
  int64_t Step = 0;
  const Expr *Inc = F->getInc() ? F->getInc()->IgnoreParenImpCasts() : nullptr;
  if (const auto *U = dyn_cast_or_null<UnaryOperator>(Inc)) {
    if (U->isIncrementOp())
      Step = 1;
    else if (U->isDecrementOp())
      Step = -1;
  } else if (const auto *C = dyn_cast_or_null<CompoundAssignOperator>(Inc)) {
    auto By = C->getRHS()->getIntegerConstantExpr(Ctx);
    if (By && C->getOpcode() == BO_AddAssign)
      Step = By->getExtValue();
    else if (By && C->getOpcode() == BO_SubAssign)
      Step = -By->getExtValue();
  }
  const int64_t A = From->getExtValue(), B = To->getExtValue();
  int64_t Span = 0; // how far the variable goes, in the step's direction
  switch (Cond->getOpcode()) {
  case BO_LT: Span = B - A; break;
  case BO_LE: Span = B - A + 1; break;
  case BO_GT: Span = A - B; break;
  case BO_GE: Span = A - B + 1; break;
  default: return std::nullopt;
  }
  const bool Up = Cond->getOpcode() == BO_LT || Cond->getOpcode() == BO_LE;
  if (Step == 0 || (Step > 0) != Up || std::abs(A) > (1 << 20) || std::abs(B) > (1 << 20))
    return std::nullopt;
  const int64_t By = Step > 0 ? Step : -Step;
  return Span <= 0 ? 0 : static_cast<uint64_t>((Span + By - 1) / By);
}

/// Signature Cost, an estimate of the work of one call: every statement and expression of the
/// body counts 1 (implicit casts and parentheses 0), times the trip counts of the loops around
/// it (a for loop with constant bounds: its count; any other loop: UnknownTrips); a call of a
/// user function counts that function's cost. Saturates at 2^30. Memo (by user name) also
/// breaks call cycles, which Restrictions reports as errors.
unsigned SignatureCollector::workCost(const FunctionDecl *FD,
                                      std::map<std::string, unsigned> &Memo) const {
  constexpr uint64_t Cap = 1u << 30, UnknownTrips = 8;
  const std::string Name = FD->getName().str();
  if (auto It = Memo.find(Name); It != Memo.end())
    return It->second;
  Memo[Name] = static_cast<unsigned>(Cap);
  uint64_t Cost = 0;
  // An explicit worklist: user expressions may nest very deeply.
  std::vector<std::pair<const Stmt *, uint64_t>> Work{{FD->getBody(), 1}};
  while (!Work.empty() && Cost < Cap) {
    auto [S, Times] = Work.back();
    Work.pop_back();
    if (!S)
      continue;
    if (!isa<ImplicitCastExpr>(S) && !isa<ParenExpr>(S))
      Cost += Times;
    uint64_t Inner = Times; // for the loop body, the condition and the increment
    if (const auto *F = dyn_cast<ForStmt>(S)) {
      Inner = std::min(Cap, Times * estimatedTripCount(F, FC.Ctx).value_or(UnknownTrips));
      Work.push_back({F->getInit(), Times});
      for (const Stmt *C : std::initializer_list<const Stmt *>{F->getCond(), F->getInc(), F->getBody()})
        Work.push_back({C, Inner});
      continue;
    }
    if (isa<WhileStmt>(S) || isa<DoStmt>(S))
      Inner = std::min(Cap, Times * UnknownTrips);
    if (const auto *Call = dyn_cast<CallExpr>(S))
      if (const FunctionDecl *Callee = Call->getDirectCallee(); Callee && FC.isUserFunction(Callee))
        if (auto Def = FC.Definitions.find(Callee->getName().str()); Def != FC.Definitions.end())
          Cost += std::min(Cap, Times * workCost(Def->second, Memo));
    for (const Stmt *C : S->children())
      Work.push_back({C, Inner});
  }
  Memo[Name] = static_cast<unsigned>(std::min(Cost, Cap));
  return Memo[Name];
}

void SignatureCollector::finish(const std::set<std::string> &TextureNames,
                                const std::map<std::string, std::string> &Other,
                                graph::SignatureMap &Out,
                                std::map<std::string, std::set<std::string>> &Reachable) {
  for (const std::string &Name : TextureNames) {
    auto It = FC.Definitions.find(Name);
    if (It == FC.Definitions.end())
      continue;
    const FunctionDecl *FD = It->second;
    if (auto O = Other.find(Name); O != Other.end()) {
      FC.report(FD->getLocation(), Diag::DuplicateTexture) << Name << O->second;
      continue;
    }
    graph::FunctionSignature Sig;
    Sig.Name = Name;
    Sig.RenamedName = FC.renamed(FD);
    Sig.File = FC.Path;
    bool Ok = true;
    auto Ret = textureValueType(FD->getReturnType());
    if (!Ret || *Ret == BaseType::Int || *Ret == BaseType::Sampler) {
      SourceLocation Loc = FD->getReturnTypeSourceRange().getBegin();
      FC.report(Loc.isValid() ? Loc : FD->getLocation(), Diag::BadReturnType)
          << Name << writtenType(FD->getReturnTypeSourceRange(), FD->getReturnType());
      Ok = false;
    } else {
      Sig.Return = *Ret;
    }
    for (const ParmVarDecl *P : FD->parameters()) {
      auto T = paramType(P->getType());
      if (!T) {
        FC.report(P->getBeginLoc(), Diag::BadParamType)
            << P->getName() << Name
            << writtenType({P->getBeginLoc(), P->getTypeSourceInfo()->getTypeLoc().getEndLoc()},
                           P->getType());
        Ok = false;
        continue;
      }
      Sig.Params.push_back({P->getName().str(), *T});
    }
    std::set<std::string> Reach = reachableFrom(Sig.RenamedName);
    std::set<std::string> Attrs, Settings;
    for (const std::string &Fn : Reach) {
      if (auto A = FC.AttributesRead.find(Fn); A != FC.AttributesRead.end())
        Attrs.insert(A->second.begin(), A->second.end());
      if (auto S = FC.SettingsRead.find(Fn); S != FC.SettingsRead.end())
        Settings.insert(S->second.begin(), S->second.end());
    }
    Sig.Attributes.assign(Attrs.begin(), Attrs.end());
    Sig.Settings.assign(Settings.begin(), Settings.end());
    std::map<std::string, unsigned> Memo;
    Sig.Cost = std::max(1u, workCost(FD, Memo));
    if (Ok) {
      Reachable[Name] = std::move(Reach);
      Out[Name] = std::move(Sig);
    }
  }
}

} // namespace texcc::frontend
