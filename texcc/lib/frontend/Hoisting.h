#ifndef TEXCC_LIB_FRONTEND_HOISTING_H
#define TEXCC_LIB_FRONTEND_HOISTING_H

// Hoisting (docs/frontend.md): the declarations of a texture function that depend on constant
// parameters only, which shape code computes once per material instead of once per hit, and
// the two functions that shape code calls for them, as text:
//   texcc_uniform_<renamed>(<the parameters they read>, float *texcc_out_<v>, ...)
//       the declarations, verbatim, then each value stored through its pointer;
//   texcc_hoisted_<renamed>(<every parameter>, <type> <v>, ...)
//       the function itself with those declarations left out: their values come in as
//       parameters of the same names.

#include "FileContext.h"

#include "clang/Tooling/Core/Replacement.h"

namespace texcc::frontend {

struct HoistPlan {
  std::vector<const clang::DeclStmt *> Decls;  // top-level statements of the body, in order
  std::vector<graph::HoistedValue> Values;     // the variables they declare, in order
  std::vector<unsigned> From;                  // the parameter indices they read, ascending
};

/// The declarations of FD that qualify: at the top level of the body, spelled in the main file
/// (no part from a macro expansion), every variable a local float, float2..4 or int with an
/// initializer that reads only parameters (of those types, named in Params, never changed in
/// the body) and
/// variables of earlier qualifying declarations, calls at least one OpenCL builtin and nothing
/// else (no user function, no embedded API, no work-item function, no pointer argument), and
/// neither assigns, takes an address nor divides integers (the body may guard a division that
/// the once-per-material code would run unguarded). Empty when nothing qualifies.
/// Params: the names of the parameters the declarations may read (the ones every node of the
/// graph binds to a constant).
HoistPlan planHoisting(const FileContext &FC, const clang::FunctionDecl *FD,
                       const std::set<std::string> &Params);

/// The text of texcc_uniform_<Renamed> and texcc_hoisted_<Renamed> (framed by #line
/// directives to the user's file), cut from Text, the file's rewritten text, with Repl, the
/// edits that made it. Empty when an edit falls inside a hoisted declaration (then nothing is
/// hoisted).
std::string hoistedFunctions(const FileContext &FC, const clang::FunctionDecl *FD,
                             const HoistPlan &Plan, const clang::tooling::Replacements &Repl,
                             const std::string &Text, size_t DefBegin, size_t DefEnd,
                             const std::string &Renamed);

} // namespace texcc::frontend

#endif
