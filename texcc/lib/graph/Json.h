#ifndef TEXCC_LIB_GRAPH_JSON_H
#define TEXCC_LIB_GRAPH_JSON_H

// A small JSON reader that keeps the line:col of every value and object key, for diagnostics
// that point into graph.json (nlohmann::json does not track positions). Strict RFC 8259, plus
// clear errors for what people write by mistake: comments, trailing commas, NaN/Infinity,
// single quotes, truncated files.

#include "texcc/Graph/Diagnostics.h"

#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace texcc::graph::json {

struct Value;

struct Member {
  std::string Key;
  SourceLoc KeyLoc;
  std::unique_ptr<Value> Val;
};

struct Value {
  enum class Kind { Null, Bool, Number, String, Array, Object };
  Kind K = Kind::Null;
  bool Bool = false;
  double Number = 0;
  bool IsInteger = false;   // written without fraction or exponent
  std::string Text;         // String: the decoded text; Number: as written
  std::vector<Value> Elements; // an array's elements, unless IsPacked
  std::vector<Member> Members;
  SourceLoc Loc;

  /// An array of numbers only is read packed, with Elements left empty: each number's value
  /// (Numbers), whether it was written as an integer (Integers), and the array's text between
  /// its brackets (Packed), from which elementLoc and elementText recover one element's
  /// line:col and spelling for a diagnostic. About 15 bytes per number, where an element Value
  /// takes over 150 (a 5-million-number array: docs/reliability.md "Limits").
  bool IsPacked = false;
  std::vector<double> Numbers;
  std::vector<bool> Integers;
  std::string Packed;

  /// An array's length, packed or not.
  size_t size() const { return IsPacked ? Numbers.size() : Elements.size(); }
  /// An array's elements in either form (a packed array's are made on first use and kept).
  const std::vector<Value> &elements() const;
  /// Element I of a packed array: where it is written, and as written.
  SourceLoc elementLoc(size_t I) const;
  std::string elementText(size_t I) const;

  /// The member with this key, or null.
  const Value *get(const std::string &Key) const;
  const Member *getMember(const std::string &Key) const;
  bool isNumber() const { return K == Kind::Number; }
  bool isString() const { return K == Kind::String; }
  bool isArray() const { return K == Kind::Array; }
  bool isObject() const { return K == Kind::Object; }

private:
  mutable std::vector<Value> Unpacked;
};

/// "a number", "a string", "an array", "an object", "true", "null".
std::string describeKind(const Value &V);

/// Parses Text; on a syntax error reports "File:line:col: error: ..." to Diags and returns
/// std::nullopt. Duplicate object keys are errors too.
std::optional<Value> parse(const std::string &File, const std::string &Text,
                           DiagnosticSink &Diags);

/// Formats a double so that it reads back to the same double, as briefly as possible
/// ("0.5", "4", "1e-07").
std::string formatNumber(double D);

/// Levenshtein distance, for "did you mean" suggestions.
unsigned editDistance(const std::string &A, const std::string &B);
/// The candidate closest to Name if it is close enough to be a plausible typo, else "".
std::string closestMatch(const std::string &Name, const std::vector<std::string> &Candidates);
/// "'a', 'b' or 'c'".
std::string quotedList(const std::vector<std::string> &Names);

} // namespace texcc::graph::json

#endif
