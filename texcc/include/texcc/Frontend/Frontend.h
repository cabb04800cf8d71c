#ifndef TEXCC_FRONTEND_FRONTEND_H
#define TEXCC_FRONTEND_FRONTEND_H

// The front end: parses user textures (OpenCL C 1.2 plus the texcc prelude, held in memory)
// with Clang LibTooling, renames every user function with a per-file prefix, lowers the embedded
// API (readAttr, readSetting, tex2D, sam2D) to the accessors of kernels/common/texcc_device.h,
// threads the hit context through user functions, collects texture signatures, and rejects what
// a texture may not do. Diagnostics about user code go through Clang's DiagnosticsEngine
// (file:line:col, source line, caret) to the given stream.

#include "texcc/Graph/Signature.h"

#include "llvm/Support/Error.h"
#include "llvm/Support/raw_ostream.h"

#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace texcc::frontend {

struct FrontendOptions {
  std::vector<std::string> IncludeDirs;  // -I
  std::vector<std::string> Defines;      // -D NAME[=V]
  /// In-memory file contents by path (unit tests); files not listed are read from disk.
  std::map<std::string, std::string> VirtualFiles;
  /// Hoisting (shape mode): per texture function, the parameters that every node of the graph
  /// binds to a constant; only declarations that read nothing else are hoisted. A function not
  /// listed hoists nothing.
  std::map<std::string, std::set<std::string>> HoistableParams;
};

/// One user source after rewriting.
struct TranslatedSource {
  std::string Path;     // as given
  std::string Prefix;   // its rename prefix, e.g. "noise_" (unique among the sources)
  /// Every user function defined here: user name -> renamed name.
  std::map<std::string, std::string> Functions;
  /// Renamed names of the user functions each function calls (directly).
  std::map<std::string, std::set<std::string>> Calls;

  /// The rewritten text: `#line` directives map every line back to Path; macros the file
  /// defines are #undef'd at the end (hygiene). Function definitions whose renamed name is not
  /// in Keep are left out (their lines are skipped with #line); an empty Keep keeps everything.
  /// After each kept definition whose renamed name is in Hoist come its Hoisted functions.
  std::string render(const std::set<std::string> &Keep = {},
                     const std::set<std::string> &Hoist = {}) const;

  /// Texture functions with declarations that shape code computes once per material (their
  /// signatures' Hoisted): renamed name -> the text of texcc_uniform_<renamed> and
  /// texcc_hoisted_<renamed> (docs/frontend.md, "Hoisting").
  std::map<std::string, std::string> Hoisted;

  // Implementation detail of render(): the rewritten text and, for each defined function,
  // the byte range of its definition in it.
  std::string Text;
  struct Range {
    size_t Begin = 0, End = 0;
    unsigned FirstLine = 0, LineAfter = 0;  // user lines, for #line after a skipped body
  };
  std::map<std::string, Range> Definitions;  // renamed name -> range in Text
  std::vector<std::string> DefinedMacros;
  /// The -D macros (name, value) the file was parsed with: render() defines them before the
  /// file and #undef's them after it, so the kernel sees what the front end saw.
  std::vector<std::pair<std::string, std::string>> Predefined;
};

struct FrontendResult {
  std::vector<TranslatedSource> Sources;
  /// Signatures of the requested texture functions (key: user name).
  graph::SignatureMap Textures;
  /// The renamed names of all user functions reachable from each requested texture.
  std::map<std::string, std::set<std::string>> Reachable;
};

/// Parses and rewrites Sources. TextureNames are the functions graph.json names as "fn"; names
/// no source defines are simply absent from Textures (the graph library reports them at their
/// graph.json line with a "did you mean" over every defined function). On any error in user code the
/// diagnostics are printed to Diags and an llvm::Error saying how many errors is returned.
llvm::Expected<FrontendResult> runFrontend(const std::vector<std::string> &Sources,
                                           const std::set<std::string> &TextureNames,
                                           const FrontendOptions &Opts,
                                           llvm::raw_ostream &Diags);

/// The parse-time prelude (declares the embedded API so that readAttr("Normal") has type
/// float3 exactly, and so on).
const std::string &parsePrelude();

} // namespace texcc::frontend

#endif
