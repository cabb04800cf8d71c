#include "texcc/Support/Text.h"

#include <cstdio>

namespace texcc {

namespace {

/// The start of the UTF-8 sequence at or before I (I itself when it is not a continuation).
size_t sequenceStart(std::string_view S, size_t I) {
  while (I > 0 && I < S.size() && (static_cast<unsigned char>(S[I]) & 0xC0) == 0x80)
    --I;
  return I;
}

void appendEscaped(std::string &Out, std::string_view S) {
  for (char C : S) {
    const unsigned char U = static_cast<unsigned char>(C);
    if (C == '\n')
      Out += "\\n";
    else if (C == '\t')
      Out += "\\t";
    else if (U < 0x20 || U == 0x7F) {
      char Buf[8];
      std::snprintf(Buf, sizeof Buf, "\\x%02X", U);
      Out += Buf;
    } else
      Out += C;
  }
}

} // namespace

std::string boundedExcerpt(std::string_view Text, size_t Max) {
  std::string Out;
  if (Text.size() <= Max) {
    appendEscaped(Out, Text);
    return Out;
  }
  const size_t Keep = Max > 16 ? Max - 16 : Max; // room for "..." and " (N bytes)"
  const size_t Head = sequenceStart(Text, Keep * 2 / 3);
  const size_t Tail = sequenceStart(Text, Text.size() - (Keep - Keep * 2 / 3));
  appendEscaped(Out, Text.substr(0, Head));
  Out += "...";
  appendEscaped(Out, Text.substr(Tail));
  Out += " (" + std::to_string(Text.size()) + " bytes)";
  return Out;
}

} // namespace texcc
