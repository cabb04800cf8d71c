// Clang-style diagnostics: "file:line:col: error: message".

#include "texcc/Graph/Diagnostics.h"
#include "texcc/Support/Text.h"

namespace texcc::graph {

void DiagnosticSink::error(const SourceLoc &L, std::string Msg) {
  Diags.push_back({Diagnostic::Severity::Error, L, texcc::boundedMessage(Msg)});
  ++NumErrors;
}

void DiagnosticSink::warning(const SourceLoc &L, std::string Msg) {
  Diags.push_back({Diagnostic::Severity::Warning, L, texcc::boundedMessage(Msg)});
}

void DiagnosticSink::note(const SourceLoc &L, std::string Msg) {
  Diags.push_back({Diagnostic::Severity::Note, L, texcc::boundedMessage(Msg)});
}

static const char *severityName(Diagnostic::Severity S) {
  switch (S) {
  case Diagnostic::Severity::Error:
    return "error";
  case Diagnostic::Severity::Warning:
    return "warning";
  case Diagnostic::Severity::Note:
    return "note";
  }
  return "error";
}

void DiagnosticSink::print(std::ostream &OS) const {
  for (const Diagnostic &D : Diags) {
    if (!D.Loc.File.empty())
      OS << D.Loc.File;
    if (D.Loc.Line != 0) {
      OS << ':' << D.Loc.Line;
      if (D.Loc.Col != 0)
        OS << ':' << D.Loc.Col;
    }
    if (!D.Loc.File.empty() || D.Loc.Line != 0)
      OS << ": ";
    OS << severityName(D.Level) << ": " << D.Message << '\n';
  }
}

} // namespace texcc::graph
