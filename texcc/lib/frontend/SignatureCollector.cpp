#include "Callbacks.h"

#include "clang/Lex/Lexer.h"

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

std::optional<BaseType> SignatureCollector::valueType(QualType T) const {
  // sam2D is a typedef of int: tell them apart by the sugar the user wrote.
  for (QualType Cur = T;;) {
    if (const auto *TD = Cur->getAs<TypedefType>()) {
      if (TD->getDecl()->getName() == "sam2D")
        return BaseType::Sampler;
      Cur = TD->desugar();
      continue;
    }
    break;
  }
  QualType C = T.getCanonicalType();
  if (const auto *V = C->getAs<ExtVectorType>()) {
    if (!V->getElementType()->isSpecificBuiltinType(BuiltinType::Float))
      return std::nullopt;
    switch (V->getNumElements()) {
    case 2: return BaseType::Float2;
    case 3: return BaseType::Float3;
    case 4: return BaseType::Float4;
    default: return std::nullopt;
    }
  }
  if (C->isSpecificBuiltinType(BuiltinType::Float))
    return BaseType::Float;
  if (C->isSpecificBuiltinType(BuiltinType::Int))
    return BaseType::Int;
  return std::nullopt;
}

std::optional<graph::ValueType> SignatureCollector::paramType(QualType T) const {
  if (const auto *P = T->getAs<PointerType>()) {
    QualType Pointee = P->getPointeeType();
    if (Pointee.getAddressSpace() != LangAS::opencl_global || !Pointee.isConstQualified())
      return std::nullopt;
    auto B = valueType(Pointee.getUnqualifiedType());
    if (!B || *B == BaseType::Sampler)
      return std::nullopt;
    return graph::ValueType{*B, true};
  }
  auto B = valueType(T.getUnqualifiedType());
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
    for (const CallSite &C : FC.Calls)
      if (C.Caller == Fn && Seen.insert(C.Callee).second)
        Work.push_back(C.Callee);
  }
  return Seen;
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
    auto Ret = valueType(FD->getReturnType());
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
    if (Ok) {
      Reachable[Name] = std::move(Reach);
      Out[Name] = std::move(Sig);
    }
  }
}

} // namespace texcc::frontend
