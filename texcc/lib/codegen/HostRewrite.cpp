// The one textual change the host target makes to user code: OpenCL vector literals.
// `(float3)(a, b, c)` is a cast of a comma expression in C++; it becomes
// `texcc_make_float3(a, b, c)` (HostPrelude.hpp). Comments, strings and character literals are
// copied as they are.
#include "texcc/Codegen/Codegen.h"

#include <cctype>

namespace texcc::codegen {

static bool isIdentChar(char C) {
  return std::isalnum(static_cast<unsigned char>(C)) || C == '_';
}

/// If Code[At] starts `( vectortype ) (`, the vector type's name and the index just past the
/// second '('.
static bool matchVectorLiteral(const std::string &Code, size_t At, std::string &Type,
                               size_t &End) {
  static const char *const Bases[] = {"float", "int", "uint"};
  size_t I = At + 1;
  while (I < Code.size() && std::isspace(static_cast<unsigned char>(Code[I])))
    ++I;
  size_t NameBegin = I;
  while (I < Code.size() && isIdentChar(Code[I]))
    ++I;
  std::string Name = Code.substr(NameBegin, I - NameBegin);
  bool Known = false;
  for (const char *B : Bases)
    for (const char *N : {"2", "3", "4"})
      Known |= Name == std::string(B) + N;
  if (!Known)
    return false;
  while (I < Code.size() && std::isspace(static_cast<unsigned char>(Code[I])))
    ++I;
  if (I >= Code.size() || Code[I] != ')')
    return false;
  ++I;
  while (I < Code.size() && std::isspace(static_cast<unsigned char>(Code[I])))
    ++I;
  if (I >= Code.size() || Code[I] != '(')
    return false;
  Type = Name;
  End = I + 1;
  return true;
}

/// Copies a comment, string or character literal starting at I; false if none starts there.
static bool copyOpaque(const std::string &Code, size_t &I, std::string &Out) {
  size_t Begin = I;
  if (Code.compare(I, 2, "//") == 0) {
    size_t E = Code.find('\n', I);
    I = E == std::string::npos ? Code.size() : E;
  } else if (Code.compare(I, 2, "/*") == 0) {
    size_t E = Code.find("*/", I + 2);
    I = E == std::string::npos ? Code.size() : E + 2;
  } else if (Code[I] == '"' || Code[I] == '\'') {
    char Quote = Code[I++];
    while (I < Code.size() && Code[I] != Quote && Code[I] != '\n')
      I += Code[I] == '\\' ? 2 : 1;
    I = I < Code.size() ? I + 1 : Code.size();
  } else {
    return false;
  }
  Out.append(Code, Begin, I - Begin);
  return true;
}

std::string rewriteVectorLiteralsForHost(const std::string &Code) {
  std::string Out;
  Out.reserve(Code.size() + Code.size() / 8);
  size_t I = 0;
  while (I < Code.size()) {
    if (copyOpaque(Code, I, Out))
      continue;
    std::string Type;
    size_t End = 0;
    if (Code[I] == '(' && matchVectorLiteral(Code, I, Type, End)) {
      Out += "texcc_make_" + Type + "(";
      I = End;
      continue;
    }
    Out += Code[I++];
  }
  return Out;
}

} // namespace texcc::codegen
