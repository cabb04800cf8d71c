#ifndef TEXCC_LIB_FRONTEND_FILECONTEXT_H
#define TEXCC_LIB_FRONTEND_FILECONTEXT_H

// What the match callbacks of one user source share: the AST, the rename prefix, the edit set,
// the facts they collect (calls, API reads), and texcc's diagnostics, which go through Clang's
// DiagnosticsEngine so that they get file:line:col, the source line and a caret.

#include "EditSet.h"

#include "texcc/Frontend/Frontend.h"

#include "clang/AST/ASTContext.h"
#include "clang/AST/Decl.h"
#include "clang/Basic/Diagnostic.h"

#include <map>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace texcc::frontend {

/// The texcc diagnostics about user code (custom Clang diagnostic ids).
enum class Diag {
  UnknownAttribute,   // %0 name, %1 list
  UnknownSetting,     // %0 name, %1 list
  NonLiteralArgument, // %0 callee
  Recursion,          // %0 cycle
  GlobalWrite,        // %0 what
  BadReturnType,      // %0 texture, %1 type
  BadParamType,       // %0 param, %1 texture, %2 type
  UndefinedCallee,    // %0 function, %1 file
  MacroSplitCall,     // %0 function
  DuplicateTexture,   // %0 texture, %1 other file
  InternalRewrite,    // %0 why the edits could not be applied
  PastedName,         // %0 name
  KernelFunction,     // %0 name
};

struct CallSite {
  std::string Caller, Callee; // renamed names
  clang::SourceLocation Loc;  // the callee token
};

/// The graph type of a value type a texture may use: float, float2..4, int, or sam2D (a typedef
/// of int, told apart by the sugar the user wrote); std::nullopt for anything else.
std::optional<graph::BaseType> textureValueType(clang::QualType T);

/// `#line Line "Path"` (no newline), the path escaped as a C string.
std::string lineDirective(unsigned Line, llvm::StringRef Path);

class FileContext {
public:
  FileContext(clang::ASTContext &Ctx, std::string Path, std::string Prefix);

  clang::ASTContext &Ctx;
  clang::SourceManager &SM;
  const std::string Path, Prefix;
  EditSet Edits;

  /// A function the user wrote (not a builtin, not in the prelude or a system header).
  bool isUserFunction(const clang::FunctionDecl *FD) const;
  /// A function of the embedded API declared by the prelude.
  bool isApiFunction(const clang::FunctionDecl *FD, llvm::StringRef Name) const;
  std::string renamed(const clang::FunctionDecl *FD) const;
  /// The file location where the token at Loc is spelled (inside a macro body or argument
  /// when Loc comes from a macro expansion).
  clang::SourceLocation spelled(clang::SourceLocation Loc) const;
  /// Renames the token at Loc (a use or declaration of Name) to NewName where it is spelled;
  /// reports a name that is not spelled in a file (made by ## token pasting).
  void renameAt(clang::SourceLocation Loc, llvm::StringRef Name, const std::string &NewName);
  /// The '(' after the token at Loc (a spelled file location), or an invalid location.
  clang::SourceLocation lparenAfter(clang::SourceLocation Loc) const;

  clang::DiagnosticBuilder report(clang::SourceLocation Loc, Diag Kind);

  // Facts collected by the callbacks.
  std::map<std::string, const clang::FunctionDecl *> Definitions; // user name -> definition
  std::vector<CallSite> Calls;
  std::map<std::string, std::set<std::string>> AttributesRead, SettingsRead; // by renamed fn
  /// User functions called somewhere (renamed name -> a call site), to check they are defined.
  std::map<std::string, clang::SourceLocation> Called;

  /// The calls made by Caller (a renamed name), in source order: an index over Calls, built on
  /// first use after matching, so that walks of the call graph are linear in its size.
  const std::vector<const CallSite *> &callsFrom(const std::string &Caller) const;
  /// Whether Renamed names a function this file defines.
  bool definesRenamed(const std::string &Renamed) const;

private:
  std::map<Diag, unsigned> DiagIds;
  mutable std::map<std::string, std::vector<const CallSite *>> CallsByCaller;
  mutable size_t IndexedCalls = 0; // Calls.size() when CallsByCaller was built
};

} // namespace texcc::frontend

#endif
