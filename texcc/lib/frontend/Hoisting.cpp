// Hoisting: which declarations of a texture function depend on constant parameters only, and
// the text of the functions shape code calls for them (Hoisting.h, docs/frontend.md).
#include "Hoisting.h"

#include "clang/AST/RecursiveASTVisitor.h"
#include "clang/Lex/Lexer.h"

#include <algorithm>
#include <optional>

using namespace clang;

namespace texcc::frontend {

namespace {

/// float, float2..4 or int; not sam2D (an image index), not a pointer.
std::optional<graph::BaseType> hoistableType(QualType T) {
  std::optional<graph::BaseType> B = textureValueType(T.getUnqualifiedType());
  return B == graph::BaseType::Sampler ? std::nullopt : B;
}

/// The variable an lvalue expression names (`p`, `p.x`, `p->x`, `a[i]`: p and a), or null.
const VarDecl *rootVariable(const Expr *E) {
  for (;;) {
    E = E->IgnoreParenImpCasts();
    if (const auto *V = dyn_cast<ExtVectorElementExpr>(E))
      E = V->getBase();
    else if (const auto *M = dyn_cast<MemberExpr>(E))
      E = M->getBase();
    else if (const auto *A = dyn_cast<ArraySubscriptExpr>(E))
      E = A->getBase();
    else
      break;
  }
  const auto *D = dyn_cast<DeclRefExpr>(E);
  return D ? dyn_cast<VarDecl>(D->getDecl()) : nullptr;
}

/// The variables a body assigns, increments or decrements, or takes the address of.
class WrittenVariables : public RecursiveASTVisitor<WrittenVariables> {
public:
  std::set<const VarDecl *> Vars;
  bool VisitBinaryOperator(BinaryOperator *B) {
    if (B->isAssignmentOp())
      add(B->getLHS());
    return true;
  }
  bool VisitUnaryOperator(UnaryOperator *U) {
    if (U->isIncrementDecrementOp() || U->getOpcode() == UO_AddrOf)
      add(U->getSubExpr());
    return true;
  }

private:
  void add(const Expr *E) {
    if (const VarDecl *V = rootVariable(E))
      Vars.insert(V);
  }
};

/// Work-item, synchronization, memory and output builtins: not values of the parameters.
bool isImpureBuiltin(StringRef Name) {
  for (const char *Prefix : {"get_", "barrier", "mem_fence", "read_mem_fence", "write_mem_fence",
                             "atom", "vload", "vstore", "read_image", "write_image", "printf",
                             "async_", "wait_group", "prefetch"})
    if (Name.startswith(Prefix))
      return true;
  return false;
}

/// Whether an initializer depends on constant parameters only (planHoisting's rules).
class UniformInitializer : public RecursiveASTVisitor<UniformInitializer> {
public:
  UniformInitializer(const FileContext &FC, const FunctionDecl *FD,
                     const std::set<std::string> &Constant,
                     const std::set<const VarDecl *> &Hoisted,
                     const std::set<const VarDecl *> &Written)
      : FC(FC), FD(FD), Constant(Constant), Hoisted(Hoisted), Written(Written) {}

  bool Ok = true;
  unsigned BuiltinCalls = 0;
  std::set<unsigned> Params;
  bool ReadsHoisted = false;

  bool VisitDeclRefExpr(DeclRefExpr *E) {
    const ValueDecl *D = E->getDecl();
    if (isa<FunctionDecl>(D) || isa<EnumConstantDecl>(D))
      return true; // callees are checked by VisitCallExpr
    if (const auto *P = dyn_cast<ParmVarDecl>(D)) {
      if (P->getDeclContext() != FD || Written.count(P) || !hoistableType(P->getType()) ||
          !Constant.count(P->getName().str()))
        return fail();
      Params.insert(P->getFunctionScopeIndex());
      return true;
    }
    const auto *V = dyn_cast<VarDecl>(D);
    if (!V || !Hoisted.count(V))
      return fail();
    ReadsHoisted = true;
    return true;
  }
  bool VisitCallExpr(CallExpr *C) {
    const FunctionDecl *Callee = C->getDirectCallee();
    if (!Callee || FC.isUserFunction(Callee) || isImpureBuiltin(Callee->getName()) ||
        FC.SM.getFilename(FC.SM.getExpansionLoc(Callee->getLocation())).endswith(
            "texcc_prelude.h"))
      return fail();
    for (const Expr *A : C->arguments())
      if (A->getType()->isPointerType())
        return fail();
    ++BuiltinCalls;
    return true;
  }
  bool VisitBinaryOperator(BinaryOperator *B) {
    // An integer division the body guards (`if (n == 0) return ...;` before it) would run
    // unguarded once per material, and trap on a CPU.
    const bool IntDivision = (B->getOpcode() == BO_Div || B->getOpcode() == BO_Rem) &&
                             B->getType()->isIntegerType();
    return B->isAssignmentOp() || B->getOpcode() == BO_Comma || IntDivision ? fail() : true;
  }
  bool VisitUnaryOperator(UnaryOperator *U) {
    return U->isIncrementDecrementOp() || U->getOpcode() == UO_AddrOf ||
                   U->getOpcode() == UO_Deref
               ? fail()
               : true;
  }
  bool VisitStmtExpr(StmtExpr *) { return fail(); }
  bool VisitArraySubscriptExpr(ArraySubscriptExpr *) { return fail(); }
  bool VisitMemberExpr(MemberExpr *) { return fail(); }

private:
  bool fail() {
    Ok = false;
    return false;
  }
  const FileContext &FC;
  const FunctionDecl *FD;
  const std::set<std::string> &Constant;
  const std::set<const VarDecl *> &Hoisted;
  const std::set<const VarDecl *> &Written;
};

} // namespace

HoistPlan planHoisting(const FileContext &FC, const FunctionDecl *FD,
                       const std::set<std::string> &ConstantParams) {
  HoistPlan Plan;
  const SourceManager &SM = FC.SM;
  const auto *Body = dyn_cast_or_null<CompoundStmt>(FD->getBody());
  const FileID Main = SM.getMainFileID();
  if (!Body || FD->getNumParams() == 0 || !FD->getLocation().isFileID() ||
      SM.getFileID(FD->getLocation()) != Main)
    return Plan;
  WrittenVariables Written;
  Written.TraverseStmt(const_cast<CompoundStmt *>(Body));
  std::set<const VarDecl *> Hoisted;
  std::set<unsigned> From;
  for (const Stmt *S : Body->body()) {
    const auto *DS = dyn_cast<DeclStmt>(S);
    if (!DS || !DS->getBeginLoc().isFileID() || !DS->getEndLoc().isFileID() ||
        SM.getFileID(DS->getBeginLoc()) != Main)
      continue;
    // Later declarators of one statement may read earlier ones: `float c = cos(a), s = sin(a);`.
    std::set<const VarDecl *> Candidates = Hoisted;
    std::set<unsigned> Params;
    std::vector<graph::HoistedValue> Values;
    unsigned Calls = 0;
    bool Ok = true, ReadsHoisted = false;
    for (const Decl *D : DS->decls()) {
      const auto *VD = dyn_cast<VarDecl>(D);
      std::optional<graph::BaseType> T = VD ? hoistableType(VD->getType()) : std::nullopt;
      if (!T || !VD->isLocalVarDecl() || VD->isStaticLocal() || !VD->getInit()) {
        Ok = false;
        break;
      }
      UniformInitializer U(FC, FD, ConstantParams, Candidates, Written.Vars);
      U.TraverseStmt(const_cast<Expr *>(VD->getInit()));
      if (!U.Ok) {
        Ok = false;
        break;
      }
      Calls += U.BuiltinCalls;
      ReadsHoisted = ReadsHoisted || U.ReadsHoisted;
      Params.insert(U.Params.begin(), U.Params.end());
      Values.push_back({VD->getName().str(), *T});
      Candidates.insert(VD);
    }
    // Nothing to gain from a declaration without a call, or one that reads neither a
    // parameter nor a hoisted variable (the compiler folds it).
    if (!Ok || Calls == 0 || (Params.empty() && !ReadsHoisted))
      continue;
    Hoisted = std::move(Candidates);
    From.insert(Params.begin(), Params.end());
    Plan.Decls.push_back(DS);
    Plan.Values.insert(Plan.Values.end(), Values.begin(), Values.end());
  }
  Plan.From.assign(From.begin(), From.end());
  return Plan;
}

std::string hoistedFunctions(const FileContext &FC, const FunctionDecl *FD,
                             const HoistPlan &Plan, const tooling::Replacements &Repl,
                             const std::string &Text, size_t DefBegin, size_t DefEnd,
                             const std::string &Renamed) {
  const SourceManager &SM = FC.SM;
  const LangOptions &LO = FC.Ctx.getLangOpts();
  auto shifted = [&](SourceLocation L) { return Repl.getShiftedCodePosition(SM.getFileOffset(L)); };
  // Each declaration's bytes in Text. No edit may touch one: its text is copied as it is.
  struct Cut {
    size_t Begin, End;
    unsigned Line;
  };
  std::vector<Cut> Cuts;
  for (const DeclStmt *DS : Plan.Decls) {
    SourceLocation B = DS->getBeginLoc();
    SourceLocation E = Lexer::getLocForEndOfToken(DS->getEndLoc(), 0, SM, LO);
    const unsigned BO = SM.getFileOffset(B), EO = SM.getFileOffset(E);
    for (const tooling::Replacement &R : Repl)
      if (R.getOffset() <= EO && R.getOffset() + R.getLength() >= BO)
        return "";
    Cuts.push_back({shifted(B), shifted(E), SM.getExpansionLineNumber(B)});
  }
  SourceLocation RParen = FD->getFunctionTypeLoc().getRParenLoc();
  if (Cuts.empty() || RParen.isInvalid() || !RParen.isFileID())
    return "";
  const size_t NameAt = shifted(FD->getLocation()), ParamsEnd = shifted(RParen);
  if (!(DefBegin <= NameAt && NameAt <= ParamsEnd && ParamsEnd <= Cuts.front().Begin &&
        Cuts.back().End <= DefEnd && DefEnd <= Text.size()))
    return "";
  const unsigned FirstLine = SM.getExpansionLineNumber(SM.getExpansionLoc(FD->getBeginLoc()));
  const std::string Path = FC.Path;

  // texcc_uniform_<Renamed>: the declarations, then their values through the pointers.
  std::string U = lineDirective(FirstLine, Path) + "\n" +
                  "TEXCC_FN static inline void texcc_uniform_" + Renamed + "(";
  for (size_t I = 0; I < Plan.From.size(); ++I) {
    const ParmVarDecl *P = FD->getParamDecl(Plan.From[I]);
    U += (I ? ", " : "") + graph::spelling(*hoistableType(P->getType())) + " " +
         P->getName().str();
  }
  for (const graph::HoistedValue &V : Plan.Values)
    U += ", " + graph::spelling(V.Type) + " *texcc_out_" + V.Name;
  U += ") {\n";
  for (const Cut &C : Cuts)
    U += lineDirective(C.Line, Path) + "\n  " + Text.substr(C.Begin, C.End - C.Begin) + "\n";
  for (const graph::HoistedValue &V : Plan.Values)
    U += "  *texcc_out_" + V.Name + " = " + V.Name + ";\n";
  U += "}\n";

  // texcc_hoisted_<Renamed>: the function without the declarations, their values parameters.
  std::string H = lineDirective(FirstLine, Path) + "\n";
  H.append(Text, DefBegin, NameAt - DefBegin);
  H += "texcc_hoisted_";
  H.append(Text, NameAt, ParamsEnd - NameAt);
  for (const graph::HoistedValue &V : Plan.Values)
    H += ", " + graph::spelling(V.Type) + " " + V.Name;
  size_t Pos = ParamsEnd;
  for (const Cut &C : Cuts) {
    H.append(Text, Pos, C.Begin - Pos);
    H += "/* hoisted: texcc_uniform_" + Renamed + " */";
    // Keep the line count, so that the lines after it map back to the user's lines.
    H.append(static_cast<size_t>(std::count(Text.begin() + C.Begin, Text.begin() + C.End, '\n')),
             '\n');
    Pos = C.End;
  }
  H.append(Text, Pos, DefEnd - Pos);
  return U + H + "\n";
}

} // namespace texcc::frontend
