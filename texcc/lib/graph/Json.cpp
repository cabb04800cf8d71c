// The position-keeping JSON reader (see Json.h).

#include "Json.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <unordered_set>

namespace texcc::graph::json {

const Member *Value::getMember(const std::string &Key) const {
  for (const Member &M : Members)
    if (M.Key == Key)
      return &M;
  return nullptr;
}

const Value *Value::get(const std::string &Key) const {
  const Member *M = getMember(Key);
  return M ? M->Val.get() : nullptr;
}

namespace {

/// Calls Visit(index, line, col, spelling) for each number of a packed array's text, which
/// starts at Line:Col (just after its '['). A packed array's text holds only numbers, commas
/// and blanks: the reader checked it.
template <typename F>
void scanPacked(const std::string &Text, unsigned Line, unsigned Col, F Visit) {
  size_t Index = 0;
  for (size_t I = 0; I < Text.size();) {
    const char C = Text[I];
    if (C == '\n') {
      ++Line;
      Col = 1;
      ++I;
      continue;
    }
    if (C == ' ' || C == '\t' || C == '\r' || C == ',') {
      ++Col;
      ++I;
      continue;
    }
    size_t End = I;
    while (End < Text.size() && Text[End] != '\0' && std::strchr("+-.0123456789eE", Text[End]))
      ++End;
    if (!Visit(Index++, Line, Col, Text.substr(I, End - I)))
      return;
    Col += static_cast<unsigned>(End - I);
    I = End;
  }
}

} // namespace

const std::vector<Value> &Value::elements() const {
  if (!IsPacked)
    return Elements;
  if (Unpacked.size() != Numbers.size()) {
    Unpacked.clear();
    Unpacked.reserve(Numbers.size());
    scanPacked(Packed, Loc.Line, Loc.Col + 1,
               [&](size_t I, unsigned Line, unsigned Col, std::string Spelling) {
                 Value E;
                 E.K = Kind::Number;
                 E.Number = Numbers[I];
                 E.IsInteger = Integers[I];
                 E.Text = std::move(Spelling);
                 E.Loc = {Loc.File, Line, Col};
                 Unpacked.push_back(std::move(E));
                 return true;
               });
  }
  return Unpacked;
}

SourceLoc Value::elementLoc(size_t Index) const {
  SourceLoc Found = Loc;
  scanPacked(Packed, Loc.Line, Loc.Col + 1,
             [&](size_t I, unsigned Line, unsigned Col, const std::string &) {
               if (I != Index)
                 return true;
               Found = {Loc.File, Line, Col};
               return false;
             });
  return Found;
}

std::string Value::elementText(size_t Index) const {
  std::string Found;
  scanPacked(Packed, Loc.Line, Loc.Col + 1,
             [&](size_t I, unsigned, unsigned, std::string Spelling) {
               if (I != Index)
                 return true;
               Found = std::move(Spelling);
               return false;
             });
  return Found;
}

std::string describeKind(const Value &V) {
  switch (V.K) {
  case Value::Kind::Null:
    return "null";
  case Value::Kind::Bool:
    return V.Bool ? "true" : "false";
  case Value::Kind::Number:
    return "a number";
  case Value::Kind::String:
    return "a string";
  case Value::Kind::Array:
    return "an array";
  case Value::Kind::Object:
    return "an object";
  }
  return "a value";
}

namespace {

class Reader {
public:
  Reader(const std::string &File, const std::string &Text, DiagnosticSink &Diags)
      : File(File), Text(Text), Diags(Diags) {}

  std::optional<Value> run() {
    Value V;
    // A UTF-8 byte-order mark (some editors write one) is skipped, as RFC 8259 allows;
    // columns on line 1 still count its bytes.
    if (Text.compare(0, 3, "\xEF\xBB\xBF") == 0)
      for (int I = 0; I < 3; ++I)
        advance();
    skipSpace();
    if (Failed)
      return std::nullopt;
    if (Pos >= Text.size()) {
      fail(here(), "expected a JSON value, got an empty file");
      return std::nullopt;
    }
    if (!parseValue(V, 0))
      return std::nullopt;
    skipSpace();
    if (Failed)
      return std::nullopt;
    if (Pos < Text.size()) {
      fail(here(), "unexpected " + describeHere() + " after the top-level value");
      return std::nullopt;
    }
    return V;
  }

private:
  static constexpr unsigned MaxDepth = 256;

  SourceLoc here() const { return {File, Line, Col}; }
  bool atEnd() const { return Pos >= Text.size(); }
  char peek() const { return atEnd() ? '\0' : Text[Pos]; }

  void advance() {
    if (atEnd())
      return;
    if (Text[Pos] == '\n') {
      ++Line;
      Col = 1;
    } else {
      ++Col;
    }
    ++Pos;
  }

  bool fail(const SourceLoc &L, const std::string &Msg) {
    if (!Failed)
      Diags.error(L, Msg);
    Failed = true;
    return false;
  }

  std::string describeHere() const {
    if (atEnd())
      return "end of file";
    unsigned char C = Text[Pos];
    if (C < 0x20 || C >= 0x7f) {
      char Buf[16];
      std::snprintf(Buf, sizeof Buf, "byte 0x%02x", C);
      return Buf;
    }
    return std::string("'") + static_cast<char>(C) + "'";
  }

  void skipSpace() {
    while (!atEnd()) {
      char C = peek();
      if (C == ' ' || C == '\t' || C == '\n' || C == '\r') {
        advance();
      } else if (C == '/' && Pos + 1 < Text.size() &&
                 (Text[Pos + 1] == '/' || Text[Pos + 1] == '*')) {
        fail(here(), "comments are not allowed in JSON");
        return;
      } else {
        return;
      }
    }
  }

  bool parseValue(Value &V, unsigned Depth) {
    if (Depth > MaxDepth)
      return fail(here(), "nesting deeper than 256 levels");
    V.Loc = here();
    char C = peek();
    if (C == '{')
      return parseObject(V, Depth);
    if (C == '[')
      return parseArray(V, Depth);
    if (C == '"')
      return parseString(V.Text) && (V.K = Value::Kind::String, true);
    if (C == '-' || (C >= '0' && C <= '9'))
      return parseNumber(V);
    if (std::isalpha(static_cast<unsigned char>(C)) || C == '\'')
      return parseWord(V);
    return fail(here(), "expected a JSON value, got " + describeHere());
  }

  /// A bare word; a number's sign may come before it (Sign, at SignLoc), so that "-Infinity"
  /// is quoted whole, where it starts.
  bool parseWord(Value &V, const std::string &Sign = "", std::optional<SourceLoc> SignLoc = {}) {
    if (peek() == '\'')
      return fail(here(), "strings must use double quotes");
    size_t Start = Pos;
    SourceLoc L = SignLoc ? *SignLoc : here();
    while (!atEnd() && (std::isalnum(static_cast<unsigned char>(peek())) || peek() == '_'))
      advance();
    std::string Word = Text.substr(Start, Pos - Start);
    if (!Sign.empty())
      Word = Sign + Word;
    if (Word == "true" || Word == "false") {
      V.K = Value::Kind::Bool;
      V.Bool = Word == "true";
      return true;
    }
    if (Word == "null") {
      V.K = Value::Kind::Null;
      return true;
    }
    std::string Unsigned = Sign.empty() ? Word : Word.substr(Sign.size());
    if (Unsigned == "NaN" || Unsigned == "nan" || Unsigned == "Infinity" || Unsigned == "inf" ||
        Unsigned == "infinity")
      return fail(L, "'" + Word + "' is not a number: graph values must be finite");
    return fail(L, "unexpected '" + Word + "'; expected a JSON value");
  }

  bool parseNumber(Value &V) {
    size_t Start = Pos;
    SourceLoc L = here();
    bool Integer = true;
    if (peek() == '-')
      advance();
    if (std::isalpha(static_cast<unsigned char>(peek()))) {
      Value Dummy;
      return parseWord(Dummy, "-", L) && fail(L, "invalid number");
    }
    if (peek() == '0') {
      advance();
      if (std::isdigit(static_cast<unsigned char>(peek())))
        return fail(L, "invalid number: leading zeros are not allowed");
    } else if (std::isdigit(static_cast<unsigned char>(peek()))) {
      while (std::isdigit(static_cast<unsigned char>(peek())))
        advance();
    } else {
      return fail(here(), "invalid number: expected a digit, got " + describeHere());
    }
    if (peek() == '.') {
      Integer = false;
      advance();
      if (!std::isdigit(static_cast<unsigned char>(peek())))
        return fail(here(), "invalid number: expected a digit after '.', got " +
                                describeHere());
      while (std::isdigit(static_cast<unsigned char>(peek())))
        advance();
    }
    if (peek() == 'e' || peek() == 'E') {
      Integer = false;
      advance();
      if (peek() == '+' || peek() == '-')
        advance();
      if (!std::isdigit(static_cast<unsigned char>(peek())))
        return fail(here(), "invalid number: expected a digit in the exponent, got " +
                                describeHere());
      while (std::isdigit(static_cast<unsigned char>(peek())))
        advance();
    }
    V.K = Value::Kind::Number;
    V.Text = Text.substr(Start, Pos - Start);
    V.IsInteger = Integer;
    V.Number = std::strtod(V.Text.c_str(), nullptr);
    if (!std::isfinite(V.Number))
      return fail(L, "number " + quotedNumber(V.Text) + " is out of range");
    return true;
  }

  /// A number as written, or for a very long one its ends and its length: a diagnostic stays
  /// one readable line.
  static std::string quotedNumber(const std::string &Number) {
    if (Number.size() <= 40)
      return "'" + Number + "'";
    return "'" + Number.substr(0, 16) + "..." + Number.substr(Number.size() - 8) + "' (" +
           std::to_string(Number.size()) + " characters)";
  }

  static void appendUtf8(std::string &Out, unsigned CP) {
    if (CP < 0x80) {
      Out += static_cast<char>(CP);
    } else if (CP < 0x800) {
      Out += static_cast<char>(0xC0 | (CP >> 6));
      Out += static_cast<char>(0x80 | (CP & 0x3F));
    } else if (CP < 0x10000) {
      Out += static_cast<char>(0xE0 | (CP >> 12));
      Out += static_cast<char>(0x80 | ((CP >> 6) & 0x3F));
      Out += static_cast<char>(0x80 | (CP & 0x3F));
    } else {
      Out += static_cast<char>(0xF0 | (CP >> 18));
      Out += static_cast<char>(0x80 | ((CP >> 12) & 0x3F));
      Out += static_cast<char>(0x80 | ((CP >> 6) & 0x3F));
      Out += static_cast<char>(0x80 | (CP & 0x3F));
    }
  }

  bool parseHex4(unsigned &CP) {
    CP = 0;
    for (int I = 0; I < 4; ++I) {
      char C = peek();
      if (!std::isxdigit(static_cast<unsigned char>(C)))
        return fail(here(), "invalid \\u escape: expected a hex digit, got " + describeHere());
      CP = CP * 16 + (std::isdigit(static_cast<unsigned char>(C))
                          ? C - '0'
                          : (std::tolower(static_cast<unsigned char>(C)) - 'a' + 10));
      advance();
    }
    return true;
  }

  bool parseEscape(std::string &Out) {
    SourceLoc L = here();
    advance(); // backslash
    char C = peek();
    const char *Simple = "\"\\/bfnrt";
    const char *Mapped = "\"\\/\b\f\n\r\t";
    if (C != '\0' && std::strchr(Simple, C)) {
      Out += Mapped[std::strchr(Simple, C) - Simple];
      advance();
      return true;
    }
    if (C != 'u')
      return fail(L, "invalid escape sequence in string");
    advance();
    unsigned CP;
    if (!parseHex4(CP))
      return false;
    if (CP >= 0xD800 && CP < 0xDC00 && peek() == '\\' && Pos + 1 < Text.size() &&
        Text[Pos + 1] == 'u') {
      advance();
      advance();
      unsigned Low;
      if (!parseHex4(Low))
        return false;
      if (Low >= 0xDC00 && Low < 0xE000)
        CP = 0x10000 + ((CP - 0xD800) << 10) + (Low - 0xDC00);
    }
    // A surrogate left over has no UTF-8 form.
    if (CP >= 0xD800 && CP < 0xE000)
      return fail(L, "invalid \\u escape: unpaired UTF-16 surrogate");
    appendUtf8(Out, CP);
    return true;
  }

  bool parseString(std::string &Out) {
    SourceLoc Start = here();
    advance(); // opening quote
    while (true) {
      if (atEnd())
        return fail(Start, "unterminated string");
      char C = peek();
      if (C == '"') {
        advance();
        return true;
      }
      if (C == '\\') {
        if (!parseEscape(Out))
          return false;
        continue;
      }
      if (static_cast<unsigned char>(C) < 0x20)
        return fail(here(), C == '\n' ? "unterminated string (a newline inside a string)"
                                      : "control character inside a string");
      if (static_cast<unsigned char>(C) >= 0x80) {
        if (!takeUtf8Sequence(Out))
          return false;
        continue;
      }
      Out += C;
      advance();
    }
  }

  /// Copies one multi-byte UTF-8 sequence into Out. JSON text is UTF-8 (RFC 8259), and what a
  /// string holds ends up in layout.json, whose writer rejects invalid UTF-8: reject it here,
  /// where the diagnostic can point at the byte.
  bool takeUtf8Sequence(std::string &Out) {
    auto Byte = [&](size_t I) -> unsigned {
      return Pos + I < Text.size() ? static_cast<unsigned char>(Text[Pos + I]) : 0;
    };
    unsigned Lead = Byte(0);
    unsigned Length = Lead >= 0xC2 && Lead <= 0xDF ? 2
                      : Lead >= 0xE0 && Lead <= 0xEF ? 3
                      : Lead >= 0xF0 && Lead <= 0xF4 ? 4
                                                     : 0;
    // The second byte's range excludes overlong forms, UTF-16 surrogates and code points past
    // U+10FFFF (RFC 3629, section 4).
    unsigned Low = Lead == 0xE0 ? 0xA0 : Lead == 0xF0 ? 0x90 : 0x80;
    unsigned High = Lead == 0xED ? 0x9F : Lead == 0xF4 ? 0x8F : 0xBF;
    bool Valid = Length != 0 && Byte(1) >= Low && Byte(1) <= High;
    for (unsigned I = 2; Valid && I < Length; ++I)
      Valid = Byte(I) >= 0x80 && Byte(I) <= 0xBF;
    if (!Valid)
      return fail(here(), "invalid UTF-8 in string (" + describeHere() + ")");
    for (unsigned I = 0; I < Length; ++I) {
      Out += Text[Pos];
      advance();
    }
    return true;
  }

  /// Numbers are kept packed (Value::IsPacked) for as long as the array holds nothing else; the
  /// first element that is not a number turns the numbers before it into Elements.
  bool parseArray(Value &V, unsigned Depth) {
    V.K = Value::Kind::Array;
    const size_t Open = Pos;
    advance();
    skipSpace();
    if (peek() == ']') {
      advance();
      return true;
    }
    bool Packing = true;
    while (true) {
      skipSpace();
      if (Failed)
        return false;
      if (atEnd())
        return fail(here(), "expected a value or ']', got end of file");
      if (peek() == ']')
        return fail(here(), "trailing comma before ']'");
      const char C = peek();
      if (Packing && (C == '-' || (C >= '0' && C <= '9'))) {
        Number.Text.clear();
        if (!parseNumber(Number))
          return false;
        V.Numbers.push_back(Number.Number);
        V.Integers.push_back(Number.IsInteger);
      } else {
        if (Packing && !V.Numbers.empty())
          unpack(V, Open);
        Packing = false;
        V.Elements.emplace_back();
        if (!parseValue(V.Elements.back(), Depth + 1))
          return false;
      }
      skipSpace();
      if (Failed)
        return false;
      if (peek() == ',') {
        advance();
        continue;
      }
      if (peek() == ']') {
        if (Packing) {
          V.Packed = Text.substr(Open + 1, Pos - Open - 1);
          V.IsPacked = true;
        }
        advance();
        return true;
      }
      return fail(here(), "expected ',' or ']' in array, got " + describeHere());
    }
  }

  /// The numbers read so far into V, an array that started at Text[Open], become Elements.
  void unpack(Value &V, size_t Open) {
    V.Elements.reserve(V.Numbers.size());
    scanPacked(Text.substr(Open + 1, Pos - Open - 1), V.Loc.Line, V.Loc.Col + 1,
               [&](size_t I, unsigned Line, unsigned Col, std::string Spelling) {
                 Value E;
                 E.K = Value::Kind::Number;
                 E.Number = V.Numbers[I];
                 E.IsInteger = V.Integers[I];
                 E.Text = std::move(Spelling);
                 E.Loc = {File, Line, Col};
                 V.Elements.push_back(std::move(E));
                 return true;
               });
    V.Numbers = {};
    V.Integers = {};
  }

  bool parseObject(Value &V, unsigned Depth) {
    V.K = Value::Kind::Object;
    advance();
    skipSpace();
    if (peek() == '}') {
      advance();
      return true;
    }
    std::unordered_set<std::string> Keys;
    while (true) {
      skipSpace();
      if (Failed)
        return false;
      if (peek() == '}')
        return fail(here(), "trailing comma before '}'");
      if (peek() != '"')
        return fail(here(), "expected a string key in object, got " + describeHere());
      Member M;
      M.KeyLoc = here();
      if (!parseString(M.Key))
        return false;
      if (!Keys.insert(M.Key).second) // a set: 100,000 materials are 100,000 keys
        return fail(M.KeyLoc, "duplicate key '" + M.Key + "' in object");
      skipSpace();
      if (Failed)
        return false;
      if (peek() != ':')
        return fail(here(), "expected ':' after object key, got " + describeHere());
      advance();
      skipSpace();
      if (Failed)
        return false;
      if (atEnd())
        return fail(here(), "expected a value, got end of file");
      M.Val = std::make_unique<Value>();
      if (!parseValue(*M.Val, Depth + 1))
        return false;
      V.Members.push_back(std::move(M));
      skipSpace();
      if (Failed)
        return false;
      if (peek() == ',') {
        advance();
        continue;
      }
      if (peek() == '}') {
        advance();
        return true;
      }
      return fail(here(), "expected ',' or '}' in object, got " + describeHere());
    }
  }

  const std::string &File;
  const std::string &Text;
  DiagnosticSink &Diags;
  Value Number; // each number of a packed array is read into it
  size_t Pos = 0;
  unsigned Line = 1;
  unsigned Col = 1;
  bool Failed = false;
};

} // namespace

std::optional<Value> parse(const std::string &File, const std::string &Text,
                           DiagnosticSink &Diags) {
  return Reader(File, Text, Diags).run();
}

std::string formatNumber(double D) {
  char Buf[40];
  for (int Prec = 1; Prec <= 17; ++Prec) {
    std::snprintf(Buf, sizeof Buf, "%.*g", Prec, D);
    if (std::strtod(Buf, nullptr) == D)
      break;
  }
  std::string S = Buf;
  // JSON wants "1e-07", which %g gives; it does not accept "inf" (never written: values are
  // finite by construction).
  return S;
}

unsigned editDistance(const std::string &A, const std::string &B) {
  std::vector<unsigned> Row(B.size() + 1);
  for (size_t J = 0; J <= B.size(); ++J)
    Row[J] = static_cast<unsigned>(J);
  for (size_t I = 1; I <= A.size(); ++I) {
    unsigned Diag = Row[0];
    Row[0] = static_cast<unsigned>(I);
    for (size_t J = 1; J <= B.size(); ++J) {
      unsigned Up = Row[J];
      unsigned Cost = A[I - 1] == B[J - 1] ? 0 : 1;
      Row[J] = std::min({Row[J] + 1, Row[J - 1] + 1, Diag + Cost});
      Diag = Up;
    }
  }
  return Row[B.size()];
}

std::string closestMatch(const std::string &Name, const std::vector<std::string> &Candidates) {
  std::string Best;
  unsigned BestDist = ~0u;
  for (const std::string &C : Candidates) {
    unsigned D = editDistance(Name, C);
    if (D < BestDist) {
      BestDist = D;
      Best = C;
    }
  }
  // Like clang's typo correction: at most a third of the name may differ.
  unsigned Limit = std::max<unsigned>(1, static_cast<unsigned>(Name.size() + 2) / 3);
  return BestDist <= Limit ? Best : std::string();
}

std::string quotedList(const std::vector<std::string> &Names) {
  std::string S;
  for (size_t I = 0; I < Names.size(); ++I) {
    if (I > 0)
      S += I + 1 == Names.size() ? " or " : ", ";
    S += "'" + Names[I] + "'";
  }
  return S;
}

} // namespace texcc::graph::json
