#include "FileContext.h"

#include "clang/Lex/Lexer.h"

using namespace clang;

namespace texcc::frontend {

FileContext::FileContext(ASTContext &Ctx, std::string Path, std::string Prefix)
    : Ctx(Ctx), SM(Ctx.getSourceManager()), Path(std::move(Path)), Prefix(std::move(Prefix)),
      Edits(Ctx.getSourceManager(), Ctx.getLangOpts()) {}

std::optional<graph::BaseType> textureValueType(QualType T) {
  // sam2D is a typedef of int: tell them apart by the sugar the user wrote.
  for (QualType Cur = T;;) {
    if (const auto *TD = Cur->getAs<TypedefType>()) {
      if (TD->getDecl()->getName() == "sam2D")
        return graph::BaseType::Sampler;
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
    case 2: return graph::BaseType::Float2;
    case 3: return graph::BaseType::Float3;
    case 4: return graph::BaseType::Float4;
    default: return std::nullopt;
    }
  }
  if (C->isSpecificBuiltinType(BuiltinType::Float))
    return graph::BaseType::Float;
  if (C->isSpecificBuiltinType(BuiltinType::Int))
    return graph::BaseType::Int;
  return std::nullopt;
}

std::string lineDirective(unsigned Line, llvm::StringRef Path) {
  std::string Out = "#line " + std::to_string(Line) + " \"";
  for (char C : Path) {
    if (C == '"' || C == '\\')
      Out += '\\';
    Out += C;
  }
  return Out + "\"";
}

bool FileContext::isUserFunction(const FunctionDecl *FD) const {
  if (!FD || FD->isImplicit() || FD->getBuiltinID() != 0)
    return false;
  SourceLocation Loc = SM.getExpansionLoc(FD->getLocation());
  return Loc.isValid() && !SM.isInSystemHeader(Loc) && !SM.isWrittenInBuiltinFile(Loc) &&
         !SM.isWrittenInCommandLineFile(Loc);
}

bool FileContext::isApiFunction(const FunctionDecl *FD, llvm::StringRef Name) const {
  if (!FD || FD->getName() != Name)
    return false;
  SourceLocation Loc = SM.getExpansionLoc(FD->getLocation());
  return SM.getFilename(Loc).endswith("texcc_prelude.h");
}

std::string FileContext::renamed(const FunctionDecl *FD) const {
  return Prefix + FD->getName().str();
}

const std::vector<const CallSite *> &FileContext::callsFrom(const std::string &Caller) const {
  if (IndexedCalls != Calls.size() || CallsByCaller.empty()) {
    CallsByCaller.clear();
    for (const CallSite &C : Calls)
      CallsByCaller[C.Caller].push_back(&C);
    IndexedCalls = Calls.size();
  }
  static const std::vector<const CallSite *> None;
  auto It = CallsByCaller.find(Caller);
  return It == CallsByCaller.end() ? None : It->second;
}

bool FileContext::definesRenamed(const std::string &Renamed) const {
  return llvm::StringRef(Renamed).startswith(Prefix) &&
         Definitions.count(Renamed.substr(Prefix.size()));
}

SourceLocation FileContext::spelled(SourceLocation Loc) const {
  return SM.getSpellingLoc(Loc);
}

void FileContext::renameAt(SourceLocation Loc, StringRef Name, const std::string &NewName) {
  SourceLocation Spelled = spelled(Loc);
  if (!SM.getFileEntryForID(SM.getFileID(Spelled))) {
    report(Loc, Diag::PastedName) << Name;
    return;
  }
  Edits.replaceToken(Spelled, NewName);
}

SourceLocation FileContext::lparenAfter(SourceLocation Loc) const {
  llvm::Optional<Token> Next = Lexer::findNextToken(Loc, SM, Ctx.getLangOpts());
  if (!Next || Next->isNot(tok::l_paren))
    return {};
  return Next->getLocation();
}

DiagnosticBuilder FileContext::report(SourceLocation Loc, Diag Kind) {
  DiagnosticsEngine &DE = Ctx.getDiagnostics();
  unsigned &Id = DiagIds[Kind];
  if (!Id) {
    constexpr auto E = DiagnosticsEngine::Error;
    switch (Kind) {
    case Diag::UnknownAttribute:
      Id = DE.getCustomDiagID(E, "unknown attribute '%0'; expected one of %1");
      break;
    case Diag::UnknownSetting:
      Id = DE.getCustomDiagID(E, "unknown setting '%0'; expected one of %1");
      break;
    case Diag::NonLiteralArgument:
      Id = DE.getCustomDiagID(E, "argument to '%0' must be a string literal");
      break;
    case Diag::Recursion:
      Id = DE.getCustomDiagID(E, "recursion is not allowed in texture code: %0");
      break;
    case Diag::GlobalWrite:
      Id = DE.getCustomDiagID(
          E, "cannot write through %0: __global memory is read-only in texture code");
      break;
    case Diag::BadReturnType:
      Id = DE.getCustomDiagID(E, "texture '%0' returns unsupported type '%1'; a texture "
                                 "returns float, float2, float3 or float4");
      break;
    case Diag::BadParamType:
      Id = DE.getCustomDiagID(E, "parameter '%0' of texture '%1' has unsupported type '%2'; "
                                 "allowed: float, float2, float3, float4, int, sam2D, "
                                 "__global const T* (T: float, float2, float3, float4, int)");
      break;
    case Diag::UndefinedCallee:
      Id = DE.getCustomDiagID(E, "function '%0' is called but not defined in '%1'; every "
                                 "texture file must define the functions it calls");
      break;
    case Diag::MacroSplitCall:
      Id = DE.getCustomDiagID(E, "cannot pass the hit context to '%0': its name and its '(' "
                                 "come from different macro expansions");
      break;
    case Diag::DuplicateTexture:
      Id = DE.getCustomDiagID(E, "texture '%0' is also defined in '%1'; a texture name must "
                                 "be defined by one source only");
      break;
    case Diag::PastedName:
      Id = DE.getCustomDiagID(E, "cannot rename '%0': its name is made by token pasting; spell "
                                 "the name in the source");
      break;
    case Diag::KernelFunction:
      Id = DE.getCustomDiagID(E, "texture files may not define kernels ('%0'); texcc generates "
                                 "the kernel");
      break;
    case Diag::InternalRewrite:
      Id = DE.getCustomDiagID(E, "texcc cannot rewrite this file: %0");
      break;
    }
  }
  return DE.Report(Loc, Id);
}

} // namespace texcc::frontend
