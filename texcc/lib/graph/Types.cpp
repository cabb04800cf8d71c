// Value types of texture functions: OpenCL C 1.2 sizes, alignments and spellings.

#include "texcc/Graph/Types.h"

namespace texcc::graph {

unsigned componentCount(BaseType B) {
  switch (B) {
  case BaseType::Float2:
    return 2;
  case BaseType::Float3:
    return 3;
  case BaseType::Float4:
    return 4;
  case BaseType::Float:
  case BaseType::Int:
  case BaseType::Sampler:
    return 1;
  }
  return 1;
}

static unsigned baseSize(BaseType B) {
  switch (B) {
  case BaseType::Float2:
    return 8;
  case BaseType::Float3:
  case BaseType::Float4:
    return 16;
  case BaseType::Float:
  case BaseType::Int:
  case BaseType::Sampler:
    return 4;
  }
  return 4;
}

unsigned sizeOf(const ValueType &T) { return T.IsGlobalArray ? 8 : baseSize(T.Base); }

unsigned alignOf(const ValueType &T) { return T.IsGlobalArray ? 4 : baseSize(T.Base); }

std::string spelling(BaseType B) {
  switch (B) {
  case BaseType::Float:
    return "float";
  case BaseType::Float2:
    return "float2";
  case BaseType::Float3:
    return "float3";
  case BaseType::Float4:
    return "float4";
  case BaseType::Int:
    return "int";
  case BaseType::Sampler:
    return "sam2D";
  }
  return "float";
}

std::string spelling(const ValueType &T) {
  if (T.IsGlobalArray)
    return "__global const " + spelling(T.Base) + "*";
  return spelling(T.Base);
}

static std::optional<BaseType> parseBase(const std::string &S) {
  for (BaseType B : {BaseType::Float, BaseType::Float2, BaseType::Float3, BaseType::Float4,
                     BaseType::Int, BaseType::Sampler})
    if (S == spelling(B))
      return B;
  return std::nullopt;
}

std::optional<ValueType> parseSpelling(const std::string &S) {
  static const std::string Prefix = "__global const ";
  ValueType T;
  if (S.compare(0, Prefix.size(), Prefix) == 0 && S.size() > Prefix.size() + 1 &&
      S.back() == '*') {
    std::string Inner = S.substr(Prefix.size(), S.size() - Prefix.size() - 1);
    while (!Inner.empty() && Inner.back() == ' ')
      Inner.pop_back();
    auto B = parseBase(Inner);
    if (!B || *B == BaseType::Sampler)
      return std::nullopt;
    T.Base = *B;
    T.IsGlobalArray = true;
    return T;
  }
  auto B = parseBase(S);
  if (!B)
    return std::nullopt;
  T.Base = *B;
  return T;
}

bool isAssignable(BaseType From, const ValueType &To) {
  if (To.IsGlobalArray)
    return false;
  if (From == To.Base)
    return true;
  return From == BaseType::Float &&
         (To.Base == BaseType::Float2 || To.Base == BaseType::Float3 ||
          To.Base == BaseType::Float4);
}

} // namespace texcc::graph
