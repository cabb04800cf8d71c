#include "Callbacks.h"

#include <algorithm>
#include <functional>

using namespace clang;
using namespace clang::ast_matchers;

namespace texcc::frontend {

void Restrictions::registerMatchers(MatchFinder &Finder) {
  Finder.addMatcher(binaryOperator(isAssignmentOperator()).bind("write"), this);
  Finder.addMatcher(unaryOperator(hasAnyOperatorName("++", "--")).bind("write"), this);
  Finder.addMatcher(functionDecl(hasAttr(attr::OpenCLKernel)).bind("kernel"), this);
}

/// The pointer a __global lvalue is reached through, for the message: "__global pointer 'p'".
static std::string describeTarget(const Expr *E) {
  while (true) {
    E = E->IgnoreParenImpCasts();
    if (const auto *A = dyn_cast<ArraySubscriptExpr>(E))
      E = A->getBase();
    else if (const auto *U = dyn_cast<UnaryOperator>(E); U && U->getOpcode() == UO_Deref)
      E = U->getSubExpr();
    else if (const auto *M = dyn_cast<MemberExpr>(E))
      E = M->getBase();
    else if (const auto *V = dyn_cast<ExtVectorElementExpr>(E))
      E = V->getBase();
    else if (const auto *R = dyn_cast<DeclRefExpr>(E))
      return "__global pointer '" + R->getDecl()->getName().str() + "'";
    else
      return "a __global pointer";
  }
}

void Restrictions::run(const MatchFinder::MatchResult &Result) {
  if (const auto *Kernel = Result.Nodes.getNodeAs<FunctionDecl>("kernel")) {
    if (FC.isUserFunction(Kernel))
      FC.report(Kernel->getLocation(), Diag::KernelFunction) << Kernel->getName();
    return;
  }
  const auto *Write = Result.Nodes.getNodeAs<Expr>("write");
  const Expr *Target = nullptr;
  if (const auto *B = dyn_cast<BinaryOperator>(Write))
    Target = B->getLHS();
  else
    Target = cast<UnaryOperator>(Write)->getSubExpr();
  if (Target->getType().getAddressSpace() != LangAS::opencl_global)
    return;
  FC.report(Target->getBeginLoc(), Diag::GlobalWrite)
      << describeTarget(Target) << Target->getSourceRange();
}

void Restrictions::finish() {
  // Not a structured binding: Clang 15 cannot capture one in a lambda (C++20), and the fuzz
  // build compiles this file with clang-15.
  for (const auto &Call : FC.Called) {
    const std::string &Renamed = Call.first;
    clang::SourceLocation Loc = Call.second;
    if (!FC.definesRenamed(Renamed))
      FC.report(Loc, Diag::UndefinedCallee) << Renamed.substr(FC.Prefix.size()) << FC.Path;
  }
  reportCycles();
}

/// Depth-first search over the call graph; every back edge closes a cycle, reported at the call
/// that closes it with the whole cycle spelled out in user names.
void Restrictions::reportCycles() {
  enum class Mark { White, Grey, Black };
  std::map<std::string, Mark> Marks;
  std::vector<std::string> Stack;
  auto UserName = [&](const std::string &R) { return "'" + R.substr(FC.Prefix.size()) + "'"; };
  std::function<void(const std::string &)> Visit = [&](const std::string &Fn) {
    Marks[Fn] = Mark::Grey;
    Stack.push_back(Fn);
    std::set<std::string> Done;
    for (const CallSite *Site : FC.callsFrom(Fn)) {
      const CallSite &C = *Site;
      if (!Done.insert(C.Callee).second)
        continue;
      Mark M = Marks[C.Callee];
      if (M == Mark::Grey) {
        auto From = std::find(Stack.begin(), Stack.end(), C.Callee);
        std::string Cycle;
        for (auto It = From; It != Stack.end(); ++It)
          Cycle += UserName(*It) + " -> ";
        FC.report(C.Loc, Diag::Recursion) << Cycle + UserName(C.Callee);
      } else if (M == Mark::White) {
        Visit(C.Callee);
      }
    }
    Stack.pop_back();
    Marks[Fn] = Mark::Black;
  };
  for (const auto &[Name, FD] : FC.Definitions)
    if (Marks[FC.renamed(FD)] == Mark::White)
      Visit(FC.renamed(FD));
}

} // namespace texcc::frontend
