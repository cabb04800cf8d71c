// texcc: the thin driver. Parses options and drives the libraries; the work lives in texcc/lib:
// graph.json -> parseGraph -> runFrontend (user code) -> compileGraph -> codegen -> OUTDIR.
#include "texcc/Codegen/Codegen.h"
#include "texcc/Config.h"
#include "texcc/Frontend/Frontend.h"
#include "texcc/Graph/Compile.h"
#include "texcc/Graph/Graph.h"
#include "texcc/OutOfMemory.h"
#include "texcc/StackGuard.h"
#include "texcc/Support/File.h"
#include "texcc/Version.h"

#include "llvm/Support/CommandLine.h"
#include "llvm/Support/ErrorHandling.h"
#include "llvm/Support/raw_ostream.h"

#include <filesystem>
#include <iostream>

using namespace llvm;
namespace fs = std::filesystem;
namespace cg = texcc::codegen;
namespace fe = texcc::frontend;
namespace gr = texcc::graph;

static cl::OptionCategory TexccCategory("texcc options");

static cl::list<std::string> Sources(cl::Positional, cl::desc("[texture.cl ...]"),
                                     cl::cat(TexccCategory));
static cl::opt<std::string> GraphPath("graph", cl::desc("Node graph (graph.json)"),
                                      cl::value_desc("graph.json"), cl::cat(TexccCategory));
static cl::opt<std::string> OutDir("o", cl::desc("Output folder"), cl::value_desc("OUTDIR"),
                                   cl::cat(TexccCategory));
static cl::opt<std::string>
    ModeOpt("mode",
            cl::desc("Evaluation mode: interp (default), inline, wavefront or shape (one body "
                     "per graph shape, plus proctex.interp.cl)"),
            cl::value_desc("interp|inline|wavefront|shape"), cl::init("interp"),
            cl::cat(TexccCategory));
static cl::opt<std::string>
    TargetOpt("target", cl::desc("opencl (default): proctex.cl; host: C++ proctex.cpp"),
              cl::value_desc("opencl|host"), cl::init("opencl"), cl::cat(TexccCategory));
static cl::opt<unsigned> StackLimit(
    "stack-limit",
    cl::desc("Private value-stack cap in float4 slots; beyond it the interpreter spills to "
             "global memory (default 32)"),
    cl::value_desc("N"), cl::init(32), cl::cat(TexccCategory));
static cl::opt<unsigned> LocalStackLimit(
    "local-stack-limit",
    cl::desc("interp: a value stack of at most N float4 slots is a __local array of the "
             "work-group (out of scratch on a GPU; N*1 KiB of local memory per 64 work-items), "
             "a larger one a private array (default 4; 0: always private)"),
    cl::value_desc("N"), cl::init(4), cl::cat(TexccCategory));
static cl::opt<bool> NoHoist(
    "no-hoist",
    cl::desc("shape, interp: compute every declaration of the user's functions per hit, none "
             "once per material (docs/frontend.md, Hoisting), for A/B measurement and debugging"),
    cl::cat(TexccCategory));

static cl::opt<bool> NoSuperinstructions(
    "no-superinstructions",
    cl::desc("interp: no fused pairs of light nodes (one switch case and one value-stack store "
             "per node), for A/B measurement and debugging"),
    cl::cat(TexccCategory));
static cl::opt<unsigned> MaxSuperinstructions(
    "max-superinstructions",
    cl::desc("interp: at most N fused pairs of light functions in the kernel (default 8)"),
    cl::value_desc("N"), cl::init(8), cl::cat(TexccCategory));
static cl::opt<unsigned> MaxQuickened(
    "max-quickened",
    cl::desc("interp: at most N quickened opcodes, cases for the most frequent (function, "
             "argument sources, int values) patterns, fused pairs included, that read their "
             "arguments without decoding and have int constants as literals (default 8; 0: "
             "none)"),
    cl::value_desc("N"), cl::init(8), cl::cat(TexccCategory));
static cl::opt<unsigned> LightCost(
    "light-cost",
    cl::desc("interp: a function may be part of a superinstruction when its cost (layout.json "
             "functions[].cost) is at most N (default 1200)"),
    cl::value_desc("N"), cl::init(1200), cl::Hidden, cl::cat(TexccCategory));
static cl::opt<uint64_t> LoopBudget(
    "loop-budget",
    cl::desc("Loop iterations one hit may run in the user's textures, all loops together; past "
             "it the loops end and texrender reports the node, line and pixel (default "
             "16777216, at most 2147483647)"),
    cl::value_desc("N"), cl::init(0), cl::cat(TexccCategory));
static cl::opt<bool> NoChecks(
    "no-checks",
    cl::desc("Compile the loop budget out of the kernel, for A/B measurement of its cost "
             "(bench/per_hit.py); a texture that loops forever then hangs the renderer"),
    cl::Hidden, cl::cat(TexccCategory));
static cl::list<std::string> IncludeDirs("I", cl::Prefix, cl::desc("Add an include directory"),
                                         cl::value_desc("DIR"), cl::cat(TexccCategory));
static cl::list<std::string> Defines("D", cl::Prefix, cl::desc("Define a macro for the sources"),
                                     cl::value_desc("NAME[=V]"), cl::cat(TexccCategory));
static cl::list<std::string>
    Bake("bake",
         cl::desc("Bake constant argument ARG of node NODE into shape code as a literal, part of "
                  "the shape (repeatable; graph.json: {\"value\": v, \"bake\": true})"),
         cl::value_desc("NODE.ARG"), cl::cat(TexccCategory));
static cl::opt<bool> Verbose("v", cl::desc("Log what every graph pass does (stderr)"),
                             cl::cat(TexccCategory));
static cl::list<std::string> Dump("dump",
                                  cl::desc("Also write OUTDIR/graph.dot (Graphviz) for 'graph'"),
                                  cl::value_desc("graph"), cl::CommaSeparated,
                                  cl::cat(TexccCategory));
static cl::opt<std::string>
    Emit("emit", cl::desc("user-code: run only the front end, print the rendered user code"),
         cl::value_desc("user-code"), cl::Hidden, cl::cat(TexccCategory));

static void printVersion(raw_ostream &OS) {
  OS << "texcc version " << texcc::versionString() << " (LLVM " << TEXCC_LLVM_VERSION << ")\n";
}

static int fail(const std::string &Message) {
  errs() << "texcc: error: " << Message << "\n";
  return 1;
}

/// The sources to compile: the command line's, or graph.json's "sources" (relative to it).
static std::vector<std::string> sourceList(const gr::Graph &G) {
  if (!Sources.empty())
    return {Sources.begin(), Sources.end()};
  std::vector<std::string> List;
  fs::path Dir = fs::path(GraphPath.getValue()).parent_path();
  for (const std::string &S : G.Sources)
    List.push_back(fs::path(S).is_absolute() ? S : (Dir / S).lexically_normal().string());
  return List;
}

/// Renders every source with only the user functions that the texture functions Textures
/// reach.
static std::string renderReachableUserCode(const fe::FrontendResult &FR,
                                           const gr::CompiledGraph &CG,
                                           const std::set<std::string> &Textures,
                                           const std::set<std::string> &Hoist = {}) {
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

static int run() {
  if (GraphPath.empty())
    return fail("no graph given (--graph graph.json)");
  std::optional<cg::Mode> Mode = cg::parseMode(ModeOpt);
  if (!Mode)
    return fail("unknown mode '" + ModeOpt + "' (expected interp, inline, wavefront or shape)");
  std::optional<cg::Target> Target = cg::parseTarget(TargetOpt);
  if (!Target)
    return fail("unknown target '" + TargetOpt + "' (expected opencl or host)");
  for (const std::string &D : Dump)
    if (D != "graph")
      return fail("unknown --dump value '" + D + "' (expected graph)");
  const bool EmitUserCode = Emit == "user-code";
  if (!Emit.empty() && !EmitUserCode)
    return fail("unknown --emit value '" + Emit + "' (expected user-code)");
  if (LoopBudget.getNumOccurrences() && (LoopBudget < 1 || LoopBudget > 2147483647))
    return fail("--loop-budget " + std::to_string(LoopBudget) +
                " is out of range (expected 1 to 2147483647)");
  if (OutDir.empty() && !EmitUserCode)
    return fail("no output folder given (-o OUTDIR)");

  std::string GraphText, Why;
  if (!texcc::whileAllocating("reading the graph",
                              [&] { return texcc::readRegularFile(GraphPath, GraphText, Why); }))
    return fail("cannot read graph '" + GraphPath + "': " + Why);
  gr::DiagnosticSink GraphDiags;
  std::optional<gr::Graph> G = texcc::whileAllocating(
      "parsing the graph", [&] { return gr::parseGraph(GraphPath, GraphText, GraphDiags); });
  GraphDiags.print(std::cerr);
  if (!G)
    return 1;
  for (const std::string &B : Bake) {
    std::string Error;
    if (!gr::markBaked(*G, B, Error))
      return fail(Error);
  }

  std::set<std::string> TextureNames;
  for (const gr::Node &N : G->Nodes)
    TextureNames.insert(N.Fn);
  fe::FrontendOptions FeOpts;
  // Shape code and the interp kernel compute hoisted values once per material (inline and
  // wavefront code would only give them room in the parameter blocks; shape mode's interp
  // fallback does not use them).
  const bool Shape = *Mode == cg::Mode::Shape && *Target == cg::Target::OpenCL;
  const bool InterpHoists =
      *Mode == cg::Mode::Interp && *Target == cg::Target::OpenCL && !NoHoist;
  if ((Shape && !NoHoist) || InterpHoists)
    FeOpts.HoistableParams = constantParameters(*G);
  FeOpts.IncludeDirs.assign(IncludeDirs.begin(), IncludeDirs.end());
  FeOpts.Defines.assign(Defines.begin(), Defines.end());
  auto FR = texcc::whileAllocating("parsing the texture sources", [&] {
    return fe::runFrontend(sourceList(*G), TextureNames, FeOpts, errs());
  });
  if (!FR)
    return fail(toString(FR.takeError()));
  if (EmitUserCode) {
    for (const fe::TranslatedSource &S : FR->Sources)
      outs() << S.render();
    return 0;
  }

  gr::CompileOptions CompileOpts;
  CompileOpts.StackLimit = StackLimit;
  CompileOpts.LocalStackLimit = LocalStackLimit;
  // Superinstructions are cases of the interp kernel (shape mode's fallback included); the
  // other modes never read a program's opcodes.
  if ((*Mode == cg::Mode::Interp || *Mode == cg::Mode::Shape) && *Target == cg::Target::OpenCL &&
      !NoSuperinstructions)
    CompileOpts.MaxSuperinstructions = MaxSuperinstructions;
  if (*Mode == cg::Mode::Interp && *Target == cg::Target::OpenCL)
    CompileOpts.MaxQuickened = MaxQuickened;
  CompileOpts.LightCost = LightCost;
  for (const fe::TranslatedSource &S : FR->Sources)
    for (const auto &Fn : S.Functions)
      CompileOpts.KnownFunctions.push_back(Fn.first);
  if (Verbose)
    CompileOpts.Log = &std::cerr;
  gr::DiagnosticSink CompileDiags;
  std::optional<gr::CompiledGraph> CG =
      gr::compileGraph(*G, FR->Textures, CompileOpts, CompileDiags);
  CompileDiags.print(std::cerr);
  if (!CG)
    return 1;

  cg::CodegenOptions Opts;
  Opts.EvalMode = *Mode;
  Opts.Tgt = *Target;
  Opts.GraphPath = fs::absolute(fs::path(GraphPath.getValue())).lexically_normal().string();
  Opts.InterpHoists = InterpHoists;
  Opts.LoopBudget = static_cast<uint32_t>(LoopBudget);
  Opts.Checks = !NoChecks;
  Opts.UserCode = renderReachableUserCode(*FR, *CG, CG->liveFunctions(),
                                          Shape ? cg::hoistingFunctions(*CG) : std::set<std::string>{});
  // The interp kernel (interp mode, shape mode's fallback) calls the functions of dead nodes
  // too (CompiledGraph::Signatures): a rewiring onto one is then an upload, not a rebuild.
  // (With no live node no edit can wire one in: materials are not edited.)
  if (*Target == cg::Target::OpenCL && (*Mode == cg::Mode::Interp || *Mode == cg::Mode::Shape) &&
      !CG->Nodes.empty()) {
    std::set<std::string> All;
    for (const auto &KV : CG->Signatures)
      All.insert(KV.first);
    Opts.InterpUserCode = renderReachableUserCode(
        *FR, *CG, All,
        InterpHoists ? cg::interpHoistingFunctions(*CG) : std::set<std::string>{});
  }
  std::string Error;
  std::vector<cg::OutputFile> Files = texcc::whileAllocating(
      "generating the kernel and layout.json", [&] { return cg::generateOutputs(*CG, Opts, !Dump.empty()); });
  if (!texcc::whileAllocating("writing the outputs",
                              [&] { return cg::writeOutputsAtomically(OutDir, Files, Error); }))
    return fail(Error);
  if (Verbose)
    errs() << "texcc: wrote " << cg::kernelFileName(*Target) << ", layout.json, args.bin"
           << (Dump.empty() ? "" : ", graph.dot") << " to " << OutDir << "\n";
  return 0;
}

int main(int argc, char **argv) {
  cl::SetVersionPrinter(printVersion);
  cl::HideUnrelatedOptions(TexccCategory);
  cl::ParseCommandLineOptions(argc, argv,
                              "texcc: compiles procedural textures (OpenCL C) and a node graph "
                              "into an OpenCL kernel\n");
  // Out of memory is one line and exit status 1 (texcc/OutOfMemory.h), from operator new and
  // from LLVM's own allocators (whose default is a message and abort()).
  texcc::installOutOfMemoryHandler("texcc");
  llvm::install_bad_alloc_error_handler(
      [](void *, const char *, bool) { texcc::exitOutOfMemory(); });
  return texcc::runWithLargeStack(
      [] {
        try {
          return run();
        } catch (const std::bad_alloc &E) {
          texcc::reportOutOfMemory("texcc", E);
          return 1;
        }
      },
      "texcc");
}
