#include "texcc/Support/Text.h"

#include <algorithm>
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
  // At most Max bytes in all (control characters aside, which take 2 to 4 each), so that an
  // excerpt quoted again is left as it is.
  const std::string Suffix = " (" + std::to_string(Text.size()) + " bytes)";
  const size_t Keep = Max > Suffix.size() + 3 + 8 ? Max - Suffix.size() - 3 : 8;
  const size_t Head = sequenceStart(Text, Keep * 2 / 3);
  const size_t Tail = sequenceStart(Text, Text.size() - (Keep - Keep * 2 / 3));
  appendEscaped(Out, Text.substr(0, Head));
  Out += "...";
  appendEscaped(Out, Text.substr(Tail));
  Out += Suffix;
  return Out;
}

std::string boundedMessage(std::string_view Msg, size_t MaxQuote, size_t MaxLine) {
  if (Msg.size() <= MaxQuote)
    return std::string(Msg);
  std::string Quoted;
  Quoted.reserve(std::min(Msg.size(), MaxLine * 2));
  size_t I = 0;
  while (I < Msg.size()) {
    // The next quoted span: 'name', "string", [/json/pointer].
    const size_t Open = Msg.find_first_of("'\"[", I);
    const char Closer = Open == std::string_view::npos ? 0 : Msg[Open] == '[' ? ']' : Msg[Open];
    const size_t Close = Open == std::string_view::npos ? Open : Msg.find(Closer, Open + 1);
    if (Close == std::string_view::npos) {
      Quoted.append(Msg.substr(I));
      break;
    }
    Quoted.append(Msg.substr(I, Open + 1 - I));
    const std::string_view Inside = Msg.substr(Open + 1, Close - Open - 1);
    if (Inside.size() > MaxQuote && Inside.find('\n') == std::string_view::npos)
      Quoted += boundedExcerpt(Inside, MaxQuote);
    else
      Quoted.append(Inside);
    Quoted += Closer;
    I = Close + 1;
  }
  std::string Out;
  for (size_t L = 0; L <= Quoted.size();) {
    size_t End = Quoted.find('\n', L);
    if (End == std::string::npos)
      End = Quoted.size();
    const std::string_view Line(Quoted.data() + L, End - L);
    if (Line.size() > MaxLine)
      Out += boundedExcerpt(Line, MaxLine);
    else
      Out.append(Line);
    if (End < Quoted.size())
      Out += '\n';
    L = End + 1;
  }
  return Out;
}

} // namespace texcc
