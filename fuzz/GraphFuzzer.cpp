// fuzz-graph: graph.json text through the whole graph library: parseGraph, then
// compileGraph (validation, passes, stack slots, argument layout, args.bin), layoutJson and
// readLayoutSignatures (the runtime's live-edit path), which must accept what layoutJson wrote.
// Quickened opcodes are on (the interp backend's choice, texcc_codegen), and the live editor's
// invariant is checked: compiling again with the table read back from layout.json gives the
// same args.bin.
// Validation needs function signatures; a fixed set (the graph tests' sigs.json: the rust
// example's functions plus helpers of every parameter kind) lets inputs that name them get
// past validation into the passes. Diagnostics are printed to exercise their line:col code.
#include "texcc/Codegen/Backend.h"
#include "texcc/Graph/Compile.h"
#include "texcc/Graph/Graph.h"

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <sstream>

namespace gr = texcc::graph;

static const gr::SignatureMap &signatures() {
  static const gr::SignatureMap Sigs = [] {
    const char *Path = TEXCC_SOURCE_DIR "/testsuite/Inputs/graph/sigs.json";
    std::ifstream In(Path);
    std::stringstream SS;
    SS << In.rdbuf();
    gr::SignatureMap Map;
    gr::DiagnosticSink Diags;
    if (!gr::readSignaturesJson(Path, SS.str(), Map, Diags) || Map.empty()) {
      Diags.print(std::cerr);
      std::fprintf(stderr, "fuzz-graph: cannot read the signatures in %s\n", Path);
      std::abort();
    }
    return Map;
  }();
  return Sigs;
}

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *Data, size_t Size) {
  const std::string Text(reinterpret_cast<const char *>(Data), Size);
  gr::DiagnosticSink Diags;
  std::optional<gr::Graph> G = gr::parseGraph("fuzz.json", Text, Diags);
  std::ostringstream Sink;
  if (G) {
    gr::CompileOptions Opts;
    // A small cap so that spilling to the global slice is reached too.
    Opts.StackLimit = 4;
    for (const auto &[Name, Sig] : signatures())
      Opts.KnownFunctions.push_back(Name);
    if (std::optional<gr::CompiledGraph> CG = gr::compileGraph(*G, signatures(), Opts, Diags)) {
      texcc::codegen::BackendOptions Interp; // 8 quickened opcodes, as texcc's default
      texcc::codegen::backendFor(texcc::codegen::Mode::Interp, texcc::codegen::Target::OpenCL)
          .finishGraph(*CG, Interp, nullptr);
      // The runtime reads the signatures back from layout.json for live edits.
      const std::string Layout = gr::layoutJson(*CG);
      gr::SignatureMap Back;
      std::map<std::string, unsigned> FnIds;
      std::string Error;
      if (!gr::readLayoutSignatures(Layout, Back, FnIds, Error)) {
        std::fprintf(stderr, "fuzz-graph: layout.json does not read back: %s\n", Error.c_str());
        std::abort();
      }
      // A live edit compiles with the kernel's table: unedited, it must encode the same bytes.
      gr::CompileOptions Edit = Opts;
      if (!gr::readLayoutQuickened(Layout, Edit.Quickened, Error) ||
          Edit.Quickened != CG->Quickened) {
        std::fprintf(stderr, "fuzz-graph: the quickened opcodes do not read back: %s\n",
                     Error.c_str());
        std::abort();
      }
      gr::DiagnosticSink Again;
      std::optional<gr::CompiledGraph> Re = gr::compileGraph(*G, signatures(), Edit, Again);
      if (!Re || Re->ArgsBin != CG->ArgsBin) {
        std::fprintf(stderr, "fuzz-graph: the kernel's table encodes another args.bin\n");
        std::abort();
      }
    }
  }
  Diags.print(Sink);
  return 0;
}
