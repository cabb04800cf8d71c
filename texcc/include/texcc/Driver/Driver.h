#ifndef TEXCC_DRIVER_DRIVER_H
#define TEXCC_DRIVER_DRIVER_H

// texcc's one library entry point: graph.json and the user's textures to OUTDIR (the kernel,
// layout.json, args.bin), every step and its policy here, the mode's in its backend
// (texcc/Codegen/Backend.h). The texcc tool only parses its command line into Options.

#include "texcc/Codegen/Backend.h"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace texcc::driver {

struct Options {
  std::string GraphPath;
  /// The texture sources; empty: graph.json's "sources", relative to it.
  std::vector<std::string> Sources;
  std::string OutDir;
  codegen::Mode EvalMode = codegen::Mode::Interp;
  codegen::Target Tgt = codegen::Target::OpenCL;
  codegen::BackendOptions Backend;
  unsigned StackLimit = 32;
  /// 0: the kernel's default loop budget.
  uint32_t LoopBudget = 0;
  bool Checks = true;
  std::vector<std::string> IncludeDirs, Defines;
  /// --bake NODE.ARG, in order.
  std::vector<std::string> Bake;
  /// Also write OUTDIR/graph.dot.
  bool DumpGraph = false;
  /// Where the graph passes log what they do (texcc -v), and the closing line; null: silence.
  std::ostream *Log = nullptr;
};

/// Compiles and writes the outputs atomically. Diagnostics go to stderr (clang's shape, and
/// "texcc: error: ..." for the others). Returns texcc's exit status: 0, or 1 on any error.
int compile(const Options &Opts);

} // namespace texcc::driver

#endif
