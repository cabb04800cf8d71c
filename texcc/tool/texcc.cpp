// texcc: the thin driver. Parses options and drives the libraries; the work lives in texcc/lib.
#include "texcc/Config.h"
#include "texcc/Version.h"

#include "llvm/Support/CommandLine.h"
#include "llvm/Support/raw_ostream.h"

using namespace llvm;

static cl::OptionCategory TexccCategory("texcc options");

static cl::list<std::string> Sources(cl::Positional, cl::desc("[texture.cl ...]"),
                                     cl::cat(TexccCategory));
static cl::opt<std::string> GraphPath("graph", cl::desc("Node graph (graph.json)"),
                                      cl::value_desc("graph.json"), cl::cat(TexccCategory));
static cl::opt<std::string> OutDir("o", cl::desc("Output folder"), cl::value_desc("OUTDIR"),
                                   cl::cat(TexccCategory));

static void printVersion(raw_ostream &OS) {
  OS << "texcc version " << texcc::versionString() << " (LLVM " << TEXCC_LLVM_VERSION << ")\n";
}

int main(int argc, char **argv) {
  cl::SetVersionPrinter(printVersion);
  cl::HideUnrelatedOptions(TexccCategory);
  cl::ParseCommandLineOptions(argc, argv,
                              "texcc: compiles procedural textures (OpenCL C) and a node graph "
                              "into an OpenCL kernel\n");
  errs() << "texcc: error: compilation is not built yet\n";
  return 1;
}
