#ifndef TEXCC_GRAPH_DIAGNOSTICS_H
#define TEXCC_GRAPH_DIAGNOSTICS_H

// Diagnostics of the graph library, printed clang-style:
//   rust.json:12:9: error: node 'ramp': argument 'stops' expects __global const float4* ...
// Line/Col are 1-based; 0 means unknown (then only "file: error: ..." is printed).

#include <ostream>
#include <string>
#include <vector>

namespace texcc::graph {

struct SourceLoc {
  std::string File;
  unsigned Line = 0;
  unsigned Col = 0;
};

struct Diagnostic {
  enum class Severity { Error, Warning, Note };
  Severity Level = Severity::Error;
  SourceLoc Loc;
  std::string Message;
};

class DiagnosticSink {
public:
  void error(const SourceLoc &L, std::string Msg);
  void warning(const SourceLoc &L, std::string Msg);
  void note(const SourceLoc &L, std::string Msg);
  bool hasErrors() const { return NumErrors > 0; }
  const std::vector<Diagnostic> &diagnostics() const { return Diags; }
  /// Prints every diagnostic in order, one per line, clang-style.
  void print(std::ostream &OS) const;

private:
  std::vector<Diagnostic> Diags;
  unsigned NumErrors = 0;
};

} // namespace texcc::graph

#endif
