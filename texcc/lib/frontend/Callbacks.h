#ifndef TEXCC_LIB_FRONTEND_CALLBACKS_H
#define TEXCC_LIB_FRONTEND_CALLBACKS_H

// One MatchFinder callback per concern of the front end. Each registers its matchers, records
// edits in FileContext::Edits (never touching text itself) and facts in the FileContext; the
// front end applies the edits once, after every callback has run.

#include "FileContext.h"

#include "clang/ASTMatchers/ASTMatchFinder.h"

namespace texcc::frontend {

using clang::ast_matchers::MatchFinder;

/// Renames every user function and program-scope variable, at its declarations and at every
/// reference (also where the name is spelled inside a user macro's body or argument), to
/// Prefix + name.
class Renaming : public MatchFinder::MatchCallback {
public:
  explicit Renaming(FileContext &FC) : FC(FC) {}
  void registerMatchers(MatchFinder &Finder);
  void run(const MatchFinder::MatchResult &Result) override;

private:
  bool isUserGlobal(const clang::VarDecl *VD) const;
  FileContext &FC;
};

/// Lowers the embedded API: readAttr("N") -> texcc_attr_N(texcc_ctx), readSetting("N") ->
/// texcc_setting_N(texcc_ctx), tex2D(s, uv) -> texcc_tex2D(texcc_ctx, s, uv); records what each
/// function reads; reports unknown names and non-literal arguments.
class ApiLowering : public MatchFinder::MatchCallback {
public:
  explicit ApiLowering(FileContext &FC) : FC(FC) {}
  void registerMatchers(MatchFinder &Finder);
  void run(const MatchFinder::MatchResult &Result) override;

private:
  void lowerRead(const clang::CallExpr *Call, const clang::FunctionDecl *Callee,
                 const clang::FunctionDecl *Caller);
  FileContext &FC;
};

/// What ContextThreading puts in front of a user function's declaration (texcc_device.h:
/// always_inline on the device, nothing on the host).
inline constexpr const char *InlineMarker = "TEXCC_FN ";

/// Threads the hit context: every user function takes TEXCC_CTX_PARAM first, every call to a
/// user function passes TEXCC_CTX_ARG first; every declaration spelled in a file gets
/// InlineMarker in front of it.
class ContextThreading : public MatchFinder::MatchCallback {
public:
  explicit ContextThreading(FileContext &FC) : FC(FC) {}
  void registerMatchers(MatchFinder &Finder);
  void run(const MatchFinder::MatchResult &Result) override;

private:
  FileContext &FC;
};

/// Records user function definitions and the call graph, then (finish) builds the signatures
/// of the requested textures with the attributes and settings of their whole call trees.
class SignatureCollector : public MatchFinder::MatchCallback {
public:
  explicit SignatureCollector(FileContext &FC) : FC(FC) {}
  void registerMatchers(MatchFinder &Finder);
  void run(const MatchFinder::MatchResult &Result) override;
  /// Other: textures defined by earlier sources (name -> file), to reject a second definition.
  void finish(const std::set<std::string> &TextureNames,
              const std::map<std::string, std::string> &Other, graph::SignatureMap &Out,
              std::map<std::string, std::set<std::string>> &Reachable);

private:
  std::optional<graph::ValueType> paramType(clang::QualType T) const;
  std::set<std::string> reachableFrom(const std::string &Renamed) const;
  /// Signature Cost: the estimated work of one call (statements, times loop trip counts, with
  /// the costs of the user functions it calls).
  unsigned workCost(const clang::FunctionDecl *FD, std::map<std::string, unsigned> &Memo) const;
  std::string writtenType(clang::SourceRange Range, clang::QualType T) const;
  FileContext &FC;
};

/// What a texture may not do: write to __global memory, recurse, call a function the file
/// does not define.
class Restrictions : public MatchFinder::MatchCallback {
public:
  explicit Restrictions(FileContext &FC) : FC(FC) {}
  void registerMatchers(MatchFinder &Finder);
  void run(const MatchFinder::MatchResult &Result) override;
  /// Checks that need the whole file: recursion, undefined callees.
  void finish();

private:
  void reportCycles();
  FileContext &FC;
};

/// The number of iterations of `for (int i = A; i OP B; ++i / i++ / --i / i--)` with integer
/// constants A and B (LoopBudget.cpp); std::nullopt for any other loop. ArrayBounds uses it
/// for the range of such a loop's counter.
std::optional<uint64_t> constantTripCount(const clang::ForStmt *F, const clang::ASTContext &Ctx);

/// Bounds every loop of user code with the work-item's loop budget (LoopBudget.cpp): its
/// condition ends with `&& texcc_loop_continues(texcc_ctx, __LINE__)` (texcc_device.h).
class LoopBudget : public MatchFinder::MatchCallback {
public:
  explicit LoopBudget(FileContext &FC) : FC(FC) {}
  void registerMatchers(MatchFinder &Finder);
  void run(const MatchFinder::MatchResult &Result) override;

private:
  void reportUnbounded(clang::SourceLocation Loc);
  /// Iterations a charged `for` accounts for per iteration of its own: 1 plus the whole count of
  /// every constant loop nested in it that it charges for (LoopBudget.cpp, perIteration); 1 when
  /// it charges for none. Memoized per loop.
  uint64_t perIteration(const clang::ForStmt *F, const clang::FunctionDecl *Fn);
  std::map<const clang::Stmt *, uint64_t> PerIterationMemo;
  FileContext &FC;
};

/// Bounds-checks every read of a __global array parameter of user code (Safety.cpp): each
/// such parameter `p` gets a hidden length parameter `texcc_n_p` right after it, `p[i]`
/// becomes `texcc_read_T(texcc_ctx, p, (i), texcc_n_p, __LINE__)` (texcc_device.h: 0 and a
/// fault when i is out of range), passing `p` to a user function passes its length too, and
/// any other use of `p` (pointer arithmetic, `&p[i]`, `*p`) is an error at the user's line.
class ArrayBounds : public MatchFinder::MatchCallback {
public:
  explicit ArrayBounds(FileContext &FC) : FC(FC) {}
  void registerMatchers(MatchFinder &Finder);
  void run(const MatchFinder::MatchResult &Result) override;

private:
  void checkUse(const clang::DeclRefExpr *Ref, const clang::ParmVarDecl *P,
                clang::ASTContext &Ctx);
  void refuse(clang::SourceLocation Loc, llvm::StringRef Name, llvm::StringRef Why);
  FileContext &FC;
};

/// Refuses, at the user's line, a private array larger than MaxPrivateArrayBytes (the
/// work-item's stack: PoCL's is a few MiB) and an unroll pragma (`#pragma unroll N`,
/// `#pragma clang loop unroll_count(N)`) with N above MaxUnrollCount (the device build).
class ResourceLimits : public MatchFinder::MatchCallback {
public:
  static constexpr uint64_t MaxPrivateArrayBytes = 16 * 1024;
  static constexpr unsigned MaxUnrollCount = 1024;
  explicit ResourceLimits(FileContext &FC) : FC(FC) {}
  void registerMatchers(MatchFinder &Finder);
  void run(const MatchFinder::MatchResult &Result) override;

private:
  FileContext &FC;
};

} // namespace texcc::frontend

#endif
