// texcc: the thin driver. Parses the command line into driver::Options and calls
// driver::compile (texcc/lib/driver), where the pipeline and every mode's policy live.
#include "texcc/Config.h"
#include "texcc/Driver/Driver.h"
#include "texcc/Frontend/Library.h"
#include "texcc/OutOfMemory.h"
#include "texcc/StackGuard.h"
#include "texcc/Version.h"

#include "llvm/Support/CommandLine.h"
#include "llvm/Support/ErrorHandling.h"
#include "llvm/Support/raw_ostream.h"

#include <iostream>

using namespace llvm;
namespace cg = texcc::codegen;

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
// Accepted and ignored: interp's value stack in local memory was removed in 2026-12 (it did not
// pay: bench/refactor-20.md); layout.json "compileOptions" written before replay this option when
// a live edit regenerates the kernel.
static cl::opt<unsigned> LocalStackLimitIgnored("local-stack-limit", cl::Hidden,
                                                cl::desc("Ignored (removed in 2026-12)"),
                                                cl::cat(TexccCategory));
static cl::opt<bool> NoHoist(
    "no-hoist",
    cl::desc("shape, interp: compute every declaration of the user's functions per hit, none "
             "once per material (docs/frontend.md, Hoisting), for A/B measurement and debugging"),
    cl::cat(TexccCategory));

static cl::opt<unsigned> MaxQuickened(
    "max-quickened",
    cl::desc("interp: at most N quickened opcodes, cases for the most frequent (function, "
             "argument sources, int values) patterns, that read their arguments without "
             "decoding and have int constants as literals (default 8; 0: none)"),
    cl::value_desc("N"), cl::init(8), cl::cat(TexccCategory));
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
static cl::opt<bool> ListNodes(
    "list-nodes",
    cl::desc("Print every texture function of the library (textures/), or of the given files, "
             "with its parameters' types and defaults, and exit"),
    cl::cat(TexccCategory));

static cl::opt<bool> ListNodesJson(
    "json",
    cl::desc("With --list-nodes: one JSON object with each parameter's type, default, range "
             "and meaning from the file's parameter table"),
    cl::cat(TexccCategory));

static void printVersion(raw_ostream &OS) {
  OS << "texcc version " << texcc::versionString() << " (LLVM " << TEXCC_LLVM_VERSION << ")\n";
}

static int fail(const std::string &Message) {
  errs() << "texcc: error: " << Message << "\n";
  return 1;
}

static int run() {
  if (ListNodes)
    return texcc::frontend::listNodesCommand({Sources.begin(), Sources.end()}, ListNodesJson);
  if (ListNodesJson)
    return fail("--json goes with --list-nodes");
  if (GraphPath.empty())
    return fail("no graph given (--graph graph.json)");
  texcc::driver::Options Opts;
  std::optional<cg::Mode> Mode = cg::parseMode(ModeOpt);
  if (!Mode)
    return fail("unknown mode '" + ModeOpt + "' (expected " + cg::modeNameList() + ")");
  std::optional<cg::Target> Target = cg::parseTarget(TargetOpt);
  if (!Target)
    return fail("unknown target '" + TargetOpt + "' (expected opencl or host)");
  for (const std::string &D : Dump)
    if (D != "graph")
      return fail("unknown --dump value '" + D + "' (expected graph)");
  if (LoopBudget.getNumOccurrences() && (LoopBudget < 1 || LoopBudget > 2147483647))
    return fail("--loop-budget " + std::to_string(LoopBudget) +
                " is out of range (expected 1 to 2147483647)");
  if (OutDir.empty())
    return fail("no output folder given (-o OUTDIR)");
  Opts.GraphPath = GraphPath;
  Opts.Sources.assign(Sources.begin(), Sources.end());
  Opts.OutDir = OutDir;
  Opts.EvalMode = *Mode;
  Opts.Tgt = *Target;
  Opts.Backend.NoHoist = NoHoist;
  Opts.Backend.MaxQuickened = MaxQuickened;
  Opts.StackLimit = StackLimit;
  Opts.LoopBudget = static_cast<uint32_t>(LoopBudget);
  Opts.Checks = !NoChecks;
  Opts.IncludeDirs.assign(IncludeDirs.begin(), IncludeDirs.end());
  Opts.Defines.assign(Defines.begin(), Defines.end());
  Opts.Bake.assign(Bake.begin(), Bake.end());
  Opts.DumpGraph = !Dump.empty();
  Opts.Log = Verbose ? &std::cerr : nullptr;
  return texcc::driver::compile(Opts);
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
