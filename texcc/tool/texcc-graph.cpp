// texcc-graph: the graph library alone, for developing and testing it without the front end.
//   texcc-graph GRAPH.json --signatures SIGS.json [--stack-limit N] [-v] [-o OUTDIR]
// Validates and compiles the graph against the given signatures; prints diagnostics
// clang-style on stderr (exit 1 on any error); with -o writes OUTDIR/layout.json and
// OUTDIR/args.bin, each atomically (a temporary file, then a rename).

#include "texcc/Graph/Compile.h"
#include "texcc/Support/AtomicWrite.h"
#include "texcc/Support/File.h"
#include "texcc/Version.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace texcc::graph;

namespace {

const char *Usage =
    "usage: texcc-graph GRAPH.json --signatures SIGS.json [--stack-limit N] [-v] [-o OUTDIR]\n";

struct Options {
  std::string Graph, Signatures, OutDir;
  unsigned StackLimit = 32;
  bool Verbose = false;
};

bool parseUnsigned(const std::string &S, unsigned &Out) {
  if (S.empty() || S.find_first_not_of("0123456789") != std::string::npos || S.size() > 9)
    return false;
  Out = static_cast<unsigned>(std::stoul(S));
  return true;
}

/// Returns 0 to go on, or an exit code.
int parseOptions(int Argc, char **Argv, Options &O) {
  for (int I = 1; I < Argc; ++I) {
    std::string A = Argv[I];
    auto Value = [&](const std::string &Flag, std::string &Out) {
      if (A == Flag) {
        if (I + 1 >= Argc)
          return false;
        Out = Argv[++I];
        return true;
      }
      Out = A.substr(Flag.size() + 1);
      return true;
    };
    auto Is = [&](const std::string &Flag) {
      return A == Flag || A.rfind(Flag + "=", 0) == 0;
    };
    std::string V;
    if (A == "-h" || A == "--help") {
      std::cout << Usage;
      return -1;
    } else if (A == "--version") {
      std::cout << "texcc-graph " << texcc::versionString() << "\n";
      return -1;
    } else if (A == "-v") {
      O.Verbose = true;
    } else if (Is("--signatures")) {
      if (!Value("--signatures", O.Signatures))
        return 1;
    } else if (Is("--stack-limit")) {
      if (!Value("--stack-limit", V) || !parseUnsigned(V, O.StackLimit)) {
        std::cerr << "texcc-graph: error: --stack-limit expects a non-negative integer\n";
        return 1;
      }
    } else if (A == "-o") {
      if (!Value("-o", O.OutDir))
        return 1;
    } else if (!A.empty() && A[0] == '-') {
      std::cerr << "texcc-graph: error: unknown option '" << A << "'\n" << Usage;
      return 1;
    } else if (O.Graph.empty()) {
      O.Graph = A;
    } else {
      std::cerr << "texcc-graph: error: more than one graph given ('" << O.Graph << "', '"
                << A << "')\n";
      return 1;
    }
  }
  if (O.Graph.empty() || O.Signatures.empty()) {
    std::cerr << "texcc-graph: error: a graph and --signatures are required\n" << Usage;
    return 1;
  }
  return 0;
}

int writeOutputs(const CompiledGraph &CG, const std::string &OutDir) {
  std::error_code EC;
  fs::create_directories(OutDir, EC);
  const std::pair<std::string, std::string> Files[] = {
      {"layout.json", layoutJson(CG)},
      {"args.bin", std::string(CG.ArgsBin.begin(), CG.ArgsBin.end())}};
  for (const auto &[Name, Contents] : Files) {
    const std::string Path = (fs::path(OutDir) / Name).string();
    std::string Why;
    if (!texcc::writeFileAtomically(Path, Contents, Why)) {
      std::cerr << "texcc-graph: error: cannot write '" << Path << "': " << Why << "\n";
      return 1;
    }
  }
  return 0;
}

} // namespace

int main(int Argc, char **Argv) {
  Options O;
  if (int RC = parseOptions(Argc, Argv, O))
    return RC < 0 ? 0 : RC;
  std::string GraphText, SigText, Why;
  if (!texcc::readRegularFile(O.Graph, GraphText, Why)) {
    std::cerr << "texcc-graph: error: cannot read '" << O.Graph << "': " << Why << "\n";
    return 1;
  }
  if (!texcc::readRegularFile(O.Signatures, SigText, Why)) {
    std::cerr << "texcc-graph: error: cannot read '" << O.Signatures << "': " << Why << "\n";
    return 1;
  }
  DiagnosticSink Diags;
  SignatureMap Sigs;
  CompileOptions Opts;
  Opts.StackLimit = O.StackLimit;
  Opts.Log = O.Verbose ? &std::cerr : nullptr;
  std::optional<CompiledGraph> CG;
  if (readSignaturesJson(O.Signatures, SigText, Sigs, Diags)) {
    for (const auto &KV : Sigs)
      Opts.KnownFunctions.push_back(KV.first);
    if (std::optional<Graph> G = parseGraph(O.Graph, GraphText, Diags))
      CG = compileGraph(*G, Sigs, Opts, Diags);
  }
  Diags.print(std::cerr);
  if (!CG)
    return 1;
  return O.OutDir.empty() ? 0 : writeOutputs(*CG, O.OutDir);
}
