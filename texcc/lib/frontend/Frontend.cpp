// runFrontend: one Clang parse per user source (each is its own translation unit, so two files
// may define the same names), the match callbacks over its AST, the edits applied once.
#include "Callbacks.h"

#include "texcc/Config.h"
#include "texcc/Frontend/Frontend.h"

#include "clang/Basic/DiagnosticSema.h"
#include "clang/Frontend/CompilerInstance.h"
#include "clang/Frontend/FrontendActions.h"
#include "clang/Frontend/TextDiagnosticPrinter.h"
#include "clang/Lex/Lexer.h"
#include "clang/Lex/PPCallbacks.h"
#include "clang/Lex/Preprocessor.h"
#include "clang/Tooling/Tooling.h"
#include "llvm/Support/MemoryBuffer.h"
#include "llvm/Support/Path.h"

using namespace clang;

namespace texcc::frontend {

namespace {

const char *const PreludePath = "/texcc-virtual/texcc_prelude.h";

/// What one parse produces, and what it needs from the sources parsed before it.
struct SourceJob {
  std::string Path, Prefix;
  const std::set<std::string> *TextureNames = nullptr;
  std::map<std::string, std::string> EarlierTextures; // name -> file
  std::vector<std::pair<std::string, std::string>> Defines;
  TranslatedSource Out;
  graph::SignatureMap Textures;
  std::map<std::string, std::set<std::string>> Reachable;
  bool Done = false;
};

/// Records the macros the user's file defines, so that render() can #undef them.
class MacroRecorder : public PPCallbacks {
public:
  MacroRecorder(const SourceManager &SM, std::vector<std::string> &Names) : SM(SM), Names(Names) {}
  void MacroDefined(const Token &Name, const MacroDirective *) override {
    if (SM.getFileID(SM.getExpansionLoc(Name.getLocation())) != SM.getMainFileID())
      return;
    std::string N = Name.getIdentifierInfo()->getName().str();
    if (std::find(Names.begin(), Names.end(), N) == Names.end())
      Names.push_back(N);
  }

private:
  const SourceManager &SM;
  std::vector<std::string> &Names;
};

class TexccConsumer : public ASTConsumer {
public:
  explicit TexccConsumer(SourceJob &Job) : Job(Job) {}
  void HandleTranslationUnit(ASTContext &Ctx) override;

private:
  void buildOutput(FileContext &FC);
  SourceJob &Job;
};

void TexccConsumer::HandleTranslationUnit(ASTContext &Ctx) {
  FileContext FC(Ctx, Job.Path, Job.Prefix);
  Renaming Rename(FC);
  ApiLowering Lower(FC);
  ContextThreading Thread(FC);
  SignatureCollector Signatures(FC);
  Restrictions Restrict(FC);
  MatchFinder Finder;
  Rename.registerMatchers(Finder);
  Lower.registerMatchers(Finder);
  Thread.registerMatchers(Finder);
  Signatures.registerMatchers(Finder);
  Restrict.registerMatchers(Finder);
  Finder.matchAST(Ctx);
  Restrict.finish();
  Signatures.finish(*Job.TextureNames, Job.EarlierTextures, Job.Textures, Job.Reachable);
  buildOutput(FC);
}

void TexccConsumer::buildOutput(FileContext &FC) {
  const SourceManager &SM = FC.SM;
  FileID Main = SM.getMainFileID();
  auto Repl = FC.Edits.replacementsFor(Main);
  if (!Repl) {
    FC.report(SM.getLocForStartOfFile(Main), Diag::MacroSplitCall)
        << llvm::toString(Repl.takeError());
    return;
  }
  StringRef Code = SM.getBufferData(Main);
  auto Text = tooling::applyAllReplacements(Code, *Repl);
  if (!Text) {
    llvm::consumeError(Text.takeError());
    return;
  }
  TranslatedSource &Out = Job.Out;
  Out.Text = std::move(*Text);
  for (const auto &[Name, FD] : FC.Definitions) {
    std::string Renamed = FC.renamed(FD);
    Out.Functions[Name] = Renamed;
    Out.Calls[Renamed];
    SourceLocation B = SM.getExpansionLoc(FD->getBeginLoc());
    SourceLocation E = SM.getExpansionRange(FD->getEndLoc()).getEnd();
    E = Lexer::getLocForEndOfToken(E, 0, SM, FC.Ctx.getLangOpts());
    if (SM.getFileID(B) != Main || SM.getFileID(E) != Main)
      continue;
    TranslatedSource::Range R;
    R.Begin = Repl->getShiftedCodePosition(SM.getFileOffset(B));
    R.End = Repl->getShiftedCodePosition(SM.getFileOffset(E));
    R.FirstLine = SM.getExpansionLineNumber(B);
    R.LineAfter = SM.getExpansionLineNumber(E);
    Out.Definitions[Renamed] = R;
  }
  for (const CallSite &C : FC.Calls)
    Out.Calls[C.Caller].insert(C.Callee);
  Job.Done = true;
}

class TexccAction : public ASTFrontendAction {
public:
  explicit TexccAction(SourceJob &Job) : Job(Job) {}

protected:
  std::unique_ptr<ASTConsumer> CreateASTConsumer(CompilerInstance &CI, StringRef) override {
    // Without fp64, Clang reads `0.5` as a float and warns about each; that is what textures
    // mean, so say nothing.
    CI.getDiagnostics().setSeverity(diag::warn_double_const_requires_fp64,
                                    diag::Severity::Ignored, SourceLocation());
    CI.getPreprocessor().addPPCallbacks(
        std::make_unique<MacroRecorder>(CI.getSourceManager(), Job.Out.DefinedMacros));
    return std::make_unique<TexccConsumer>(Job);
  }

private:
  SourceJob &Job;
};

/// Runs TexccAction in a CompilerInstance of our own, so that the "N errors generated." line
/// goes to the caller's stream with the diagnostics.
class TexccToolAction : public tooling::ToolAction {
public:
  TexccToolAction(SourceJob &Job, llvm::raw_ostream &OS) : Job(Job), OS(OS) {}
  bool runInvocation(std::shared_ptr<CompilerInvocation> Invocation, FileManager *Files,
                     std::shared_ptr<PCHContainerOperations> PCH,
                     DiagnosticConsumer *Consumer) override {
    CompilerInstance CI(std::move(PCH));
    CI.setInvocation(std::move(Invocation));
    CI.setFileManager(Files);
    CI.createDiagnostics(Consumer, /*ShouldOwnClient=*/false);
    if (!CI.hasDiagnostics())
      return false;
    CI.createSourceManager(*Files);
    CI.setVerboseOutputStream(OS);
    TexccAction Action(Job);
    bool Ok = CI.ExecuteAction(Action);
    Files->clearStatCache();
    return Ok;
  }

private:
  SourceJob &Job;
  llvm::raw_ostream &OS;
};

std::string sanitizedStem(const std::string &Path) {
  std::string Stem = llvm::sys::path::stem(Path).str();
  for (char &C : Stem)
    if (!isalnum(static_cast<unsigned char>(C)) && C != '_')
      C = '_';
  if (Stem.empty() || isdigit(static_cast<unsigned char>(Stem[0])))
    Stem = "_" + Stem;
  return Stem;
}

/// noise.cl -> "noise_"; a second noise.cl (another folder) -> "noise2_".
std::vector<std::string> uniquePrefixes(const std::vector<std::string> &Sources) {
  std::vector<std::string> Prefixes;
  std::set<std::string> Used;
  for (const std::string &S : Sources) {
    std::string Stem = sanitizedStem(S), P = Stem + "_";
    for (unsigned N = 2; !Used.insert(P).second; ++N)
      P = Stem + std::to_string(N) + "_";
    Prefixes.push_back(P);
  }
  return Prefixes;
}

std::vector<std::pair<std::string, std::string>> parseDefines(const FrontendOptions &Opts) {
  std::vector<std::pair<std::string, std::string>> Out;
  for (const std::string &D : Opts.Defines) {
    size_t Eq = D.find('=');
    if (Eq == std::string::npos)
      Out.push_back({D, "1"});
    else
      Out.push_back({D.substr(0, Eq), D.substr(Eq + 1)});
  }
  return Out;
}

std::vector<std::string> clangArgs(const std::string &Path, const FrontendOptions &Opts) {
  std::vector<std::string> Args = {"texcc",
                                   "-fsyntax-only",
                                   "-target",
                                   "spir64-unknown-unknown",
                                   "-x",
                                   "cl",
                                   "-cl-std=CL1.2",
                                   "-Xclang",
                                   "-finclude-default-header",
                                   "-Xclang",
                                   "-fdeclare-opencl-builtins",
                                   "-Xclang",
                                   "-cl-ext=-cl_khr_fp64",
                                   "-resource-dir",
                                   TEXCC_CLANG_RESOURCE_DIR,
                                   "-fno-color-diagnostics",
                                   "-include",
                                   PreludePath};
  for (const std::string &I : Opts.IncludeDirs)
    Args.push_back("-I" + I);
  for (const std::string &D : Opts.Defines)
    Args.push_back("-D" + D);
  Args.push_back(Path);
  return Args;
}

/// Parses one source; returns its number of errors.
unsigned runOne(SourceJob &Job, const FrontendOptions &Opts, llvm::raw_ostream &Diags) {
  auto Overlay = llvm::makeIntrusiveRefCnt<llvm::vfs::OverlayFileSystem>(
      llvm::vfs::getRealFileSystem());
  auto Memory = llvm::makeIntrusiveRefCnt<llvm::vfs::InMemoryFileSystem>();
  Overlay->pushOverlay(Memory);
  if (auto CWD = llvm::vfs::getRealFileSystem()->getCurrentWorkingDirectory())
    Memory->setCurrentWorkingDirectory(*CWD);
  Memory->addFile(PreludePath, 0, llvm::MemoryBuffer::getMemBuffer(parsePrelude()));
  for (const auto &[Path, Text] : Opts.VirtualFiles)
    Memory->addFile(Path, 0, llvm::MemoryBuffer::getMemBufferCopy(Text, Path));
  auto Files = llvm::makeIntrusiveRefCnt<FileManager>(FileSystemOptions(), Overlay);

  auto DiagOpts = llvm::makeIntrusiveRefCnt<DiagnosticOptions>();
  DiagOpts->ShowColors = false;
  TextDiagnosticPrinter Printer(Diags, DiagOpts.get());
  TexccToolAction Action(Job, Diags);
  tooling::ToolInvocation Invocation(clangArgs(Job.Path, Opts), &Action, Files.get(),
                                    std::make_shared<PCHContainerOperations>());
  Invocation.setDiagnosticConsumer(&Printer);
  bool Ok = Invocation.run();
  unsigned Errors = Printer.getNumErrors();
  return Errors ? Errors : (Ok && Job.Done ? 0 : 1);
}

} // namespace

llvm::Expected<FrontendResult> runFrontend(const std::vector<std::string> &Sources,
                                           const std::set<std::string> &TextureNames,
                                           const FrontendOptions &Opts,
                                           llvm::raw_ostream &Diags) {
  for (const std::string &S : Sources)
    if (!Opts.VirtualFiles.count(S) && !llvm::sys::fs::exists(S))
      return llvm::createStringError(std::errc::no_such_file_or_directory,
                                     "cannot open '%s': no such file", S.c_str());
  std::vector<std::string> Prefixes = uniquePrefixes(Sources);
  FrontendResult Result;
  std::map<std::string, std::string> TextureFiles;
  unsigned Errors = 0;
  for (size_t I = 0; I < Sources.size(); ++I) {
    SourceJob Job;
    Job.Path = Sources[I];
    Job.Prefix = Prefixes[I];
    Job.TextureNames = &TextureNames;
    Job.EarlierTextures = TextureFiles;
    Errors += runOne(Job, Opts, Diags);
    Job.Out.Path = Job.Path;
    Job.Out.Prefix = Job.Prefix;
    Job.Out.Predefined = parseDefines(Opts);
    for (const auto &[Name, Sig] : Job.Textures) {
      TextureFiles[Name] = Job.Path;
      Result.Textures[Name] = Sig;
    }
    for (auto &[Name, Reach] : Job.Reachable)
      Result.Reachable[Name] = std::move(Reach);
    Result.Sources.push_back(std::move(Job.Out));
  }
  if (Errors)
    return llvm::createStringError(std::errc::invalid_argument, "%u error%s in texture sources",
                                   Errors, Errors == 1 ? "" : "s");
  return Result;
}

} // namespace texcc::frontend
