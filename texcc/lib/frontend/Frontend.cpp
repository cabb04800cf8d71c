// runFrontend: one Clang parse per user source (each is its own translation unit, so two files
// may define the same names), the match callbacks over its AST, the edits applied once.
#include "Callbacks.h"
#include "Hoisting.h"

#include "texcc/Config.h"
#include "texcc/Frontend/Frontend.h"
#include "texcc/Support/File.h"

#include <filesystem>

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
  const std::map<std::string, std::set<std::string>> *HoistableParams = nullptr;
  std::map<std::string, std::string> EarlierTextures; // name -> file
  std::vector<std::pair<std::string, std::string>> Defines;
  TranslatedSource Out;
  graph::SignatureMap Textures;
  std::map<std::string, std::set<std::string>> Reachable;
  bool Done = false;
};

/// Whether Loc lies in a file the user wrote (the source or one of its own headers).
bool isUserFile(const SourceManager &SM, SourceLocation Loc) {
  Loc = SM.getExpansionLoc(Loc);
  return Loc.isValid() && !SM.isInSystemHeader(Loc) && SM.getFileEntryForID(SM.getFileID(Loc));
}

/// A user #include of a user header: the directive's text range, and the file it entered
/// (invalid when the preprocessor skipped it, e.g. for an include guard).
struct IncludeSite {
  FileID Includer;
  unsigned HashOffset = 0, EndOffset = 0, Line = 0;
  FileID Entered;
};

/// Records the macros the user's files define (render() #undef's them) and the user headers
/// they include (spliced into the rendered text, so the kernel needs no include path).
class PreprocessorRecorder : public PPCallbacks {
public:
  PreprocessorRecorder(const SourceManager &SM, std::vector<std::string> &Macros,
                       std::vector<IncludeSite> &Includes)
      : SM(SM), Macros(Macros), Includes(Includes) {}

  void MacroDefined(const Token &Name, const MacroDirective *) override {
    if (!isUserFile(SM, Name.getLocation()))
      return;
    std::string N = Name.getIdentifierInfo()->getName().str();
    if (Seen.insert(N).second)
      Macros.push_back(N);
  }

  void InclusionDirective(SourceLocation HashLoc, const Token &, StringRef, bool,
                          CharSourceRange FilenameRange, Optional<FileEntryRef> File, StringRef,
                          StringRef, const Module *, SrcMgr::CharacteristicKind Kind) override {
    Pending = false;
    if (!File || Kind != SrcMgr::C_User || !isUserFile(SM, HashLoc) || HashLoc.isMacroID())
      return;
    IncludeSite Site;
    Site.Includer = SM.getFileID(HashLoc);
    Site.HashOffset = SM.getFileOffset(HashLoc);
    StringRef Buffer = SM.getBufferData(Site.Includer);
    size_t End = Buffer.find('\n', SM.getFileOffset(FilenameRange.getEnd()));
    Site.EndOffset = End == StringRef::npos ? Buffer.size() : End;
    Site.Line = SM.getSpellingLineNumber(HashLoc);
    Includes.push_back(Site);
    Pending = true;
  }

  void FileChanged(SourceLocation Loc, FileChangeReason Reason, SrcMgr::CharacteristicKind,
                   FileID) override {
    if (Reason != EnterFile || !Pending)
      return;
    Pending = false;
    Includes.back().Entered = SM.getFileID(Loc);
  }

  void FileSkipped(const FileEntryRef &, const Token &, SrcMgr::CharacteristicKind) override {
    Pending = false;
  }

private:
  const SourceManager &SM;
  std::vector<std::string> &Macros;
  std::vector<IncludeSite> &Includes;
  std::set<std::string> Seen; // Macros, for a lookup in O(log n)
  bool Pending = false;
};

class TexccConsumer : public ASTConsumer {
public:
  explicit TexccConsumer(SourceJob &Job) : Job(Job) {}
  void HandleTranslationUnit(ASTContext &Ctx) override;
  std::vector<IncludeSite> Includes;

private:
  void buildOutput(FileContext &FC);
  llvm::Expected<tooling::Replacements> replacementsWithIncludes(FileContext &FC, FileID File);
  SourceJob &Job;
};

void TexccConsumer::HandleTranslationUnit(ASTContext &Ctx) {
  FileContext FC(Ctx, Job.Path, Job.Prefix);
  Renaming Rename(FC);
  ApiLowering Lower(FC);
  ContextThreading Thread(FC);
  SignatureCollector Signatures(FC);
  Restrictions Restrict(FC);
  LoopBudget Loops(FC);
  ResourceLimits Limits(FC);
  ArrayBounds Bounds(FC);
  MatchFinder Finder;
  Rename.registerMatchers(Finder);
  Lower.registerMatchers(Finder);
  Thread.registerMatchers(Finder);
  Signatures.registerMatchers(Finder);
  Restrict.registerMatchers(Finder);
  Loops.registerMatchers(Finder);
  Limits.registerMatchers(Finder);
  Bounds.registerMatchers(Finder);
  Finder.matchAST(Ctx);
  Restrict.finish();
  Signatures.finish(*Job.TextureNames, Job.EarlierTextures, Job.Textures, Job.Reachable);
  buildOutput(FC);
}

/// The edits of File plus, for each user header it includes, the header's own rewritten text
/// in place of the #include line, framed by #line directives.
llvm::Expected<tooling::Replacements>
TexccConsumer::replacementsWithIncludes(FileContext &FC, FileID File) {
  auto Repl = FC.Edits.replacementsFor(File);
  if (!Repl)
    return Repl.takeError();
  const SourceManager &SM = FC.SM;
  StringRef Path = SM.getFileEntryForID(File)->getName();
  for (const IncludeSite &Site : Includes) {
    if (Site.Includer != File)
      continue;
    std::string Splice;
    if (Site.Entered.isValid() && SM.getFileEntryForID(Site.Entered)) {
      auto Inner = replacementsWithIncludes(FC, Site.Entered);
      if (!Inner)
        return Inner.takeError();
      auto Text = tooling::applyAllReplacements(SM.getBufferData(Site.Entered), *Inner);
      if (!Text)
        return Text.takeError();
      if (!Text->empty() && Text->back() != '\n')
        *Text += '\n';
      Splice = lineDirective(1, SM.getFileEntryForID(Site.Entered)->getName()) + "\n" + *Text +
               lineDirective(Site.Line + 1, File == SM.getMainFileID() ? FC.Path : Path);
    }
    if (llvm::Error E = Repl->add(tooling::Replacement(
            Path, Site.HashOffset, Site.EndOffset - Site.HashOffset, Splice)))
      return E;
  }
  return Repl;
}

/// Replacements::getShiftedCodePosition and "the text inserted at an offset" in O(log n) each
/// (Replacements walks every replacement per query: quadratic over a file's definitions).
class ShiftIndex {
public:
  explicit ShiftIndex(const tooling::Replacements &Repl) {
    long Delta = 0;
    for (const tooling::Replacement &R : Repl) {
      Entries.push_back({R.getOffset(), R.getLength(),
                         static_cast<unsigned>(R.getReplacementText().size()), Delta});
      Delta += static_cast<long>(R.getReplacementText().size()) - R.getLength();
    }
  }

  /// Exactly tooling::Replacements::getShiftedCodePosition: the replacements are sorted and do
  /// not overlap, so those ending at or before Position are a prefix.
  unsigned shifted(unsigned Position) const {
    auto It = std::partition_point(Entries.begin(), Entries.end(), [&](const Entry &E) {
      return E.Offset + E.Length <= Position;
    });
    long Delta = It == Entries.begin() ? 0 : std::prev(It)->DeltaBefore + prevShift(It);
    if (It != Entries.end() && It->Offset < Position && It->Offset + It->TextSize <= Position) {
      Position = It->Offset + It->TextSize;
      if (It->TextSize)
        --Position;
    }
    return static_cast<unsigned>(static_cast<long>(Position) + Delta);
  }

  /// The length of the text inserted (replacing nothing) at Offset.
  unsigned insertedAt(unsigned Offset) const {
    unsigned Size = 0;
    auto It = std::partition_point(Entries.begin(), Entries.end(),
                                   [&](const Entry &E) { return E.Offset < Offset; });
    for (; It != Entries.end() && It->Offset == Offset; ++It)
      if (It->Length == 0)
        Size += It->TextSize;
    return Size;
  }

private:
  struct Entry {
    unsigned Offset, Length, TextSize;
    long DeltaBefore; // the shift of all replacements before this one
  };
  static long prevShift(std::vector<Entry>::const_iterator It) {
    const Entry &P = *std::prev(It);
    return static_cast<long>(P.TextSize) - P.Length;
  }
  std::vector<Entry> Entries;
};

void TexccConsumer::buildOutput(FileContext &FC) {
  const SourceManager &SM = FC.SM;
  FileID Main = SM.getMainFileID();
  auto Repl = replacementsWithIncludes(FC, Main);
  if (!Repl) {
    FC.report(SM.getLocForStartOfFile(Main), Diag::InternalRewrite)
        << llvm::toString(Repl.takeError());
    return;
  }
  StringRef Code = SM.getBufferData(Main);
  auto Text = tooling::applyAllReplacements(Code, *Repl);
  if (!Text) {
    FC.report(SM.getLocForStartOfFile(Main), Diag::InternalRewrite)
        << llvm::toString(Text.takeError());
    return;
  }
  TranslatedSource &Out = Job.Out;
  Out.Text = std::move(*Text);
  const ShiftIndex Shift(*Repl);
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
    const unsigned BeginOffset = SM.getFileOffset(B);
    R.Begin = Shift.shifted(BeginOffset);
    // Text inserted at the definition's first character (the inline marker) is part of it:
    // the shifted position counts it, the range starts before it.
    R.Begin -= Shift.insertedAt(BeginOffset);
    R.End = Shift.shifted(SM.getFileOffset(E));
    R.FirstLine = SM.getExpansionLineNumber(B);
    R.LineAfter = SM.getExpansionLineNumber(E);
    Out.Definitions[Renamed] = R;
    // A texture function of this file: what shape code may compute once per material.
    auto Sig = Job.Textures.find(Name);
    if (Sig == Job.Textures.end() || Sig->second.RenamedName != Renamed)
      continue;
    auto Params = Job.HoistableParams->find(Name);
    if (Params == Job.HoistableParams->end())
      continue;
    HoistPlan Plan = planHoisting(FC, FD, Params->second);
    if (Plan.Decls.empty())
      continue;
    std::string Functions = hoistedFunctions(FC, FD, Plan, *Repl, Out.Text, R.Begin, R.End, Renamed);
    if (Functions.empty())
      continue;
    Out.Hoisted[Renamed] = std::move(Functions);
    Sig->second.Hoisted = Plan.Values;
    Sig->second.HoistedFrom = Plan.From;
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
    auto Consumer = std::make_unique<TexccConsumer>(Job);
    CI.getPreprocessor().addPPCallbacks(std::make_unique<PreprocessorRecorder>(
        CI.getSourceManager(), Job.Out.DefinedMacros, Consumer->Includes));
    return Consumer;
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

/// Why a FIFO, a device or a socket cannot be read, in texcc::checkRegularFile's words; an
/// error_category of its own so that clang prints the reason at the #include.
class SpecialFileCategory : public std::error_category {
public:
  static constexpr int TooLarge = 1000; // not a file_type
  const char *name() const noexcept override { return "texcc-special-file"; }
  std::string message(int Type) const override {
    if (Type == TooLarge)
      return "it is larger than " + std::to_string(texcc::MaxSourceBytes >> 20) +
             " MiB, the most texcc reads of a texture source";
    switch (static_cast<llvm::sys::fs::file_type>(Type)) {
    case llvm::sys::fs::file_type::fifo_file: return "it is a FIFO, not a regular file";
    case llvm::sys::fs::file_type::socket_file: return "it is a socket, not a regular file";
    default: return "it is a device, not a regular file";
    }
  }
};

bool isSpecialFile(llvm::sys::fs::file_type T) {
  using llvm::sys::fs::file_type;
  return T == file_type::fifo_file || T == file_type::character_file ||
         T == file_type::block_file || T == file_type::socket_file;
}

/// The real file system without FIFOs, devices and sockets. Clang opens an #include'd file with
/// a blocking open(): a FIFO with no writer never returns, /dev/zero never ends. Here both are
/// "cannot open file 'x.h': it is a FIFO, not a regular file" at the #include's line:col.
class RegularFilesOnly : public llvm::vfs::ProxyFileSystem {
public:
  explicit RegularFilesOnly(llvm::IntrusiveRefCntPtr<llvm::vfs::FileSystem> FS)
      : ProxyFileSystem(std::move(FS)) {}

  llvm::ErrorOr<llvm::vfs::Status> status(const llvm::Twine &Path) override {
    llvm::ErrorOr<llvm::vfs::Status> S = ProxyFileSystem::status(Path);
    static const SpecialFileCategory Category;
    if (S && isSpecialFile(S->getType()))
      return std::error_code(static_cast<int>(S->getType()), Category);
    // An #include'd file past the size limit (a source itself is checked by runFrontend).
    if (S && S->getType() == llvm::sys::fs::file_type::regular_file &&
        S->getSize() > texcc::MaxSourceBytes)
      return std::error_code(SpecialFileCategory::TooLarge, Category);
    return S;
  }

  llvm::ErrorOr<std::unique_ptr<llvm::vfs::File>>
  openFileForRead(const llvm::Twine &Path) override {
    // stat() first: it does not block where open() would.
    if (llvm::ErrorOr<llvm::vfs::Status> S = status(Path); !S)
      return S.getError();
    return ProxyFileSystem::openFileForRead(Path);
  }
};

/// Parses one source; returns its number of errors.
unsigned runOne(SourceJob &Job, const FrontendOptions &Opts, llvm::raw_ostream &Diags) {
  auto Overlay = llvm::makeIntrusiveRefCnt<llvm::vfs::OverlayFileSystem>(
      llvm::makeIntrusiveRefCnt<RegularFilesOnly>(llvm::vfs::getRealFileSystem()));
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
  // A FIFO would block clang's open(): every source must be a regular file.
  for (const std::string &S : Sources) {
    std::string Why;
    if (!Opts.VirtualFiles.count(S) && !texcc::checkRegularFile(S, Why))
      return llvm::createStringError(std::errc::invalid_argument, "cannot open '%s': %s",
                                     S.c_str(), Why.c_str());
    // Refused before clang reads it: a 50 MB source took over 60 s (0.5 s per MB).
    std::error_code EC;
    const uint64_t Size = Opts.VirtualFiles.count(S) ? Opts.VirtualFiles.at(S).size()
                                                      : uint64_t(std::filesystem::file_size(S, EC));
    if (!EC && Size > texcc::MaxSourceBytes)
      return llvm::createStringError(
          std::errc::invalid_argument, "cannot read texture source '%s': %s (a source file "
          "takes the front end about 0.5 s per MB)", S.c_str(),
          texcc::tooLarge(Size, texcc::MaxSourceBytes).c_str());
  }
  std::vector<std::string> Prefixes = uniquePrefixes(Sources);
  FrontendResult Result;
  std::map<std::string, std::string> TextureFiles;
  unsigned Errors = 0;
  for (size_t I = 0; I < Sources.size(); ++I) {
    SourceJob Job;
    Job.Path = Sources[I];
    Job.Prefix = Prefixes[I];
    Job.TextureNames = &TextureNames;
    Job.HoistableParams = &Opts.HoistableParams;
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
