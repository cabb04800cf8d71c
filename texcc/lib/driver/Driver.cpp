// texcc's pipeline: graph.json -> parseGraph -> runFrontend (user code) -> compileGraph ->
// codegen -> OUTDIR. What differs between modes is asked of the mode's backend.
#include "texcc/Driver/Driver.h"

#include "texcc/Frontend/Frontend.h"
#include "texcc/Frontend/Library.h"
#include "texcc/Graph/Compile.h"
#include "texcc/Graph/Graph.h"
#include "texcc/OutOfMemory.h"
#include "texcc/Support/File.h"

#include "llvm/Support/raw_ostream.h"

#include <filesystem>
#include <iostream>

namespace fs = std::filesystem;
namespace cg = texcc::codegen;
namespace fe = texcc::frontend;
namespace gr = texcc::graph;

namespace texcc::driver {

static int fail(const std::string &Message) {
  llvm::errs() << "texcc: error: " << Message << "\n";
  return 1;
}

/// The sources to compile: the command line's, or graph.json's "sources" (relative to it).
static std::vector<std::string> sourceList(const Options &Opts, const gr::Graph &G) {
  if (!Opts.Sources.empty())
    return Opts.Sources;
  std::vector<std::string> List;
  fs::path Dir = fs::path(Opts.GraphPath).parent_path();
  for (const std::string &S : G.Sources)
    List.push_back(fs::path(S).is_absolute() ? S : (Dir / S).lexically_normal().string());
  return List;
}

/// Renders every source with only the user functions that the texture functions Textures
/// reach.
static std::string renderReachableUserCode(const fe::FrontendResult &FR,
                                           const gr::CompiledGraph &CG,
                                           const std::set<std::string> &Textures,
                                           const std::set<std::string> &Hoist) {
  std::set<std::string> Keep;
  for (const std::string &Fn : Textures) {
    Keep.insert(CG.Signatures.at(Fn).RenamedName);
    auto It = FR.Reachable.find(Fn);
    if (It != FR.Reachable.end())
      Keep.insert(It->second.begin(), It->second.end());
  }
  if (Keep.empty())
    Keep.insert("<no live texture>"); // an empty Keep would keep every function
  std::string Code;
  for (const fe::TranslatedSource &S : FR.Sources)
    Code += S.render(Keep, Hoist);
  return Code;
}

/// Per function the graph names: the parameters that every node of it binds to a number or a
/// vector, which hoisted declarations may read (docs/frontend.md, "Hoisting").
static std::map<std::string, std::set<std::string>> constantParameters(const gr::Graph &G) {
  std::map<std::string, std::set<std::string>> Out;
  for (const gr::Node &N : G.Nodes) {
    std::set<std::string> Constant;
    for (const auto &[Name, V] : N.Args)
      if (V.K == gr::ArgValue::Kind::Number || V.K == gr::ArgValue::Kind::Vector)
        Constant.insert(Name);
    auto [It, First] = Out.emplace(N.Fn, Constant);
    if (!First)
      for (auto P = It->second.begin(); P != It->second.end();)
        P = Constant.count(*P) ? std::next(P) : It->second.erase(P);
  }
  return Out;
}

/// graph.json, parsed, with the --bake marks; std::nullopt after reporting an error.
static std::optional<gr::Graph> readGraph(const Options &Opts) {
  std::string GraphText, Why;
  if (!whileAllocating("reading the graph",
                       [&] { return readRegularFile(Opts.GraphPath, GraphText, Why, MaxGraphBytes); })) {
    fail("cannot read graph '" + Opts.GraphPath + "': " + Why);
    return std::nullopt;
  }
  gr::DiagnosticSink GraphDiags;
  std::optional<gr::Graph> G = whileAllocating(
      "parsing the graph", [&] { return gr::parseGraph(Opts.GraphPath, GraphText, GraphDiags); });
  GraphDiags.print(std::cerr);
  if (!G)
    return std::nullopt;
  for (const std::string &B : Opts.Bake) {
    std::string Error;
    if (!gr::markBaked(*G, B, Error)) {
      fail(Error);
      return std::nullopt;
    }
  }
  return G;
}

/// layout.json "compileOptions": the arguments that make the same kernel from an edited graph
/// (--bake values are in the graph the runtime writes; sources given here are made absolute).
static std::vector<std::string> replayArguments(const Options &Opts) {
  std::vector<std::string> A{std::string("--mode=") + cg::modeName(Opts.EvalMode),
                             std::string("--target=") + cg::targetName(Opts.Tgt)};
  for (const std::string &I : Opts.IncludeDirs)
    A.push_back("-I" + fs::absolute(fs::path(I)).lexically_normal().string());
  for (const std::string &D : Opts.Defines)
    A.push_back("-D" + D);
  A.push_back("--stack-limit=" + std::to_string(Opts.StackLimit));
  A.push_back("--max-quickened=" + std::to_string(Opts.Backend.MaxQuickened));
  if (Opts.Backend.NoHoist)
    A.push_back("--no-hoist");
  if (Opts.LoopBudget)
    A.push_back("--loop-budget=" + std::to_string(Opts.LoopBudget));
  if (!Opts.Checks)
    A.push_back("--no-checks");
  for (const std::string &S : Opts.Sources) // given on the command line: they override the graph's
    A.push_back(fs::absolute(fs::path(S)).lexically_normal().string());
  return A;
}

int compile(const Options &Opts) {
  const cg::Backend &B = cg::backendFor(Opts.EvalMode, Opts.Tgt);
  std::optional<gr::Graph> G = readGraph(Opts);
  if (!G)
    return 1;

  std::set<std::string> TextureNames;
  for (const gr::Node &N : G->Nodes)
    TextureNames.insert(N.Fn);
  fe::FrontendOptions FeOpts;
  if (B.hoists(Opts.Backend))
    FeOpts.HoistableParams = constantParameters(*G);
  FeOpts.IncludeDirs = Opts.IncludeDirs;
  FeOpts.Defines = Opts.Defines;
  auto FR = whileAllocating("parsing the texture sources", [&] {
    return fe::runFrontend(sourceList(Opts, *G), TextureNames, FeOpts, llvm::errs());
  });
  if (!FR)
    return fail(llvm::toString(FR.takeError()));

  gr::CompileOptions CompileOpts;
  CompileOpts.StackLimit = Opts.StackLimit;
  for (const fe::TranslatedSource &S : FR->Sources)
    for (const auto &Fn : S.Functions)
      CompileOpts.KnownFunctions.push_back(Fn.first);
  for (const gr::Node &N : G->Nodes)
    if (!FR->Textures.count(N.Fn)) { // unknown or not a texture: the library may define it
      CompileOpts.LibraryFunctions = fe::libraryTextureFiles(fe::libraryDir());
      break;
    }
  CompileOpts.Log = Opts.Log;
  gr::DiagnosticSink CompileDiags;
  std::optional<gr::CompiledGraph> CG =
      gr::compileGraph(*G, FR->Textures, CompileOpts, CompileDiags);
  CompileDiags.print(std::cerr);
  if (!CG)
    return 1;
  whileAllocating("finishing the graph for the backend",
                  [&] { B.finishGraph(*CG, Opts.Backend, Opts.Log); });

  cg::CodegenOptions CO;
  CO.EvalMode = Opts.EvalMode;
  CO.Tgt = Opts.Tgt;
  CO.GraphPath = fs::absolute(fs::path(Opts.GraphPath)).lexically_normal().string();
  CO.LoopBudget = Opts.LoopBudget;
  CO.Checks = Opts.Checks;
  CO.CompileOptions = replayArguments(Opts);
  CO.ParamDocs = fe::parameterDocs(CG->Signatures);
  B.configureCodegen(CO, Opts.Backend);
  B.renderUserCode(CO, *CG, [&](const std::set<std::string> &Textures,
                                const std::set<std::string> &Hoist) {
    return renderReachableUserCode(*FR, *CG, Textures, Hoist);
  });
  std::string Error;
  std::vector<cg::OutputFile> Files =
      whileAllocating("generating the kernel and layout.json",
                      [&] { return cg::generateOutputs(*CG, CO, Opts.DumpGraph); });
  if (!whileAllocating("writing the outputs",
                       [&] { return cg::writeOutputsAtomically(Opts.OutDir, Files, Error); }))
    return fail(Error);
  if (Opts.Log)
    llvm::errs() << "texcc: wrote " << cg::kernelFileName(Opts.Tgt)
                 << ", layout.json, args.bin" << (Opts.DumpGraph ? ", graph.dot" : "") << " to "
                 << Opts.OutDir << "\n";
  return 0;
}

} // namespace texcc::driver
