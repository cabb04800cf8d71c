#ifndef TEXCC_FRONTEND_LIBRARY_H
#define TEXCC_FRONTEND_LIBRARY_H

// The texture library as the driver sees it: `texcc --list-nodes [FILE...]` and the "defined in"
// hint of an unknown function. A library file documents its texture functions in the comment
// block it opens with (STYLE.md): a function of the file is a texture function of the library
// when that block names it and the front end accepts its signature; the block's parameter
// table (| name | type | default | ...) gives the defaults.

#include "texcc/Graph/Signature.h"
#include "texcc/Kernel/Manifest.h"

#include "llvm/Support/raw_ostream.h"

#include <map>
#include <string>
#include <vector>

namespace texcc::frontend {

/// The library folder: $TEXCC_LIBRARY_DIR, else the source tree's textures/ (fixed at
/// configure time).
std::string libraryDir();

/// textures/*.cl then textures/blender/*.cl (every subfolder's *.cl), each sorted by name.
std::vector<std::string> libraryFiles(const std::string &Dir);

/// Prints, per file, every texture function with its return type and parameters (name, type
/// and, where the file's parameter table gives one, the default). Json: one JSON object,
/// {"files": [{"file", "functions": [{"name", "return", "params": [{"name", "type", "default",
/// "defaultText", "range", "min", "max", "text"}]}]}]} (a parameter's row fields where the
/// table has them; "default" is the default read for the type). Diagnostics of files that do
/// not parse go to Diags; returns false then.
bool listNodes(const std::vector<std::string> &Files, llvm::raw_ostream &OS,
               llvm::raw_ostream &Diags, bool Json = false);

/// `texcc --list-nodes [--json] [FILE...]`: lists Files, or the library's files when none are
/// given, on stdout; the exit status (1 when a file does not parse or the library has no file).
int listNodesCommand(const std::vector<std::string> &Files, bool Json = false);

/// Texture function name -> its parameters' rows of the parameter table in the opening comment
/// of its file (Sig.File), in parameter order, each default read for the parameter's type
/// (layout.json's functions[].params[].doc). A file that cannot be read gives empty rows.
std::map<std::string, std::vector<kernel::ParamDoc>>
parameterDocs(const graph::SignatureMap &Sigs);

/// Texture function name -> the library file (relative to the library folder's parent, e.g.
/// "textures/blender/noise.cl") whose opening comment documents it. Parses the library with
/// the front end; an unreadable library gives an empty map.
std::map<std::string, std::string> libraryTextureFiles(const std::string &Dir);

} // namespace texcc::frontend

#endif
