#ifndef TEXCC_SUPPORT_TEXT_H
#define TEXCC_SUPPORT_TEXT_H

// Quoting user text in a diagnostic: a message names what it refuses, but an input can be a
// 200 MB line (a graph file, an edit, a JSON token), and a message that copies it whole is a
// 200 MB line on stderr (which killed serve.py's log reader). One helper bounds every such
// quote. No LLVM.

#include <cstddef>
#include <string>
#include <string_view>

namespace texcc {

/// Text itself when it has at most Max bytes; otherwise its beginning and end with the middle
/// replaced by "...", followed by " (N bytes)", about Max bytes in all. The cut never splits a
/// UTF-8 sequence; control characters (a newline would end the message's line) are written as
/// \n, \t or \xHH in the excerpt of a long text and in a short one alike.
std::string boundedExcerpt(std::string_view Text, size_t Max = 80);

/// A diagnostic made fit to print: every span in single or double quotes or in square brackets
/// longer than MaxQuote bytes (a name, a key, a token, a JSON pointer the message quotes)
/// becomes its boundedExcerpt, and each line longer
/// than MaxLine bytes after that its boundedExcerpt too. The printers of texcc's graph
/// diagnostics and of texrender's errors pass every message through it.
std::string boundedMessage(std::string_view Msg, size_t MaxQuote = 256, size_t MaxLine = 4096);

} // namespace texcc

#endif
