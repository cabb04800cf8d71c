// Signatures from a JSON list (the dev tool's --signatures file).

#include "texcc/Graph/Signature.h"

#include "Json.h"

namespace texcc::graph {

namespace {

bool readStringList(const json::Value *V, std::vector<std::string> &Out,
                    DiagnosticSink &Diags) {
  if (!V)
    return true;
  if (!V->isArray()) {
    Diags.error(V->Loc, "expected an array of strings, got " + json::describeKind(*V));
    return false;
  }
  for (const json::Value &E : V->elements()) {
    if (!E.isString()) {
      Diags.error(E.Loc, "expected a string, got " + json::describeKind(E));
      return false;
    }
    Out.push_back(E.Text);
  }
  return true;
}

const json::Value *stringMember(const json::Value &Obj, const char *Key, bool Required,
                                DiagnosticSink &Diags) {
  const json::Value *V = Obj.get(Key);
  if (!V) {
    if (Required)
      Diags.error(Obj.Loc, std::string("signature is missing required key '") + Key + "'");
    return nullptr;
  }
  if (!V->isString()) {
    Diags.error(V->Loc, std::string("'") + Key + "' must be a string, got " +
                            json::describeKind(*V));
    return nullptr;
  }
  return V;
}

std::optional<ValueType> typeOf(const json::Value &V, DiagnosticSink &Diags) {
  auto T = parseSpelling(V.Text);
  if (!T)
    Diags.error(V.Loc, "unknown type '" + V.Text +
                           "'; expected float, float2, float3, float4, int, sam2D or "
                           "__global const T*");
  return T;
}

bool readSignature(const json::Value &F, FunctionSignature &S, DiagnosticSink &Diags) {
  if (!F.isObject()) {
    Diags.error(F.Loc, "a signature must be an object, got " + json::describeKind(F));
    return false;
  }
  const json::Value *Name = stringMember(F, "name", true, Diags);
  const json::Value *Ret = stringMember(F, "return", true, Diags);
  if (!Name || !Ret)
    return false;
  S.Name = Name->Text;
  if (const json::Value *R = stringMember(F, "renamed", false, Diags))
    S.RenamedName = R->Text;
  if (const json::Value *File = stringMember(F, "file", false, Diags))
    S.File = File->Text;
  auto RT = typeOf(*Ret, Diags);
  if (!RT)
    return false;
  if (RT->IsGlobalArray || RT->Base == BaseType::Int || RT->Base == BaseType::Sampler) {
    Diags.error(Ret->Loc, "a texture function returns float, float2, float3 or float4");
    return false;
  }
  S.Return = RT->Base;
  if (const json::Value *Params = F.get("params")) {
    if (!Params->isArray()) {
      Diags.error(Params->Loc, "'params' must be an array");
      return false;
    }
    for (const json::Value &P : Params->elements()) {
      if (!P.isObject()) {
        Diags.error(P.Loc, "a parameter must be an object {name, type}");
        return false;
      }
      const json::Value *PN = stringMember(P, "name", true, Diags);
      const json::Value *PT = stringMember(P, "type", true, Diags);
      if (!PN || !PT)
        return false;
      auto T = typeOf(*PT, Diags);
      if (!T)
        return false;
      S.Params.push_back({PN->Text, *T});
    }
  }
  if (const json::Value *Cost = F.get("cost")) {
    if (!Cost->isNumber() || Cost->Number < 0 || Cost->Number > 4294967295.0 ||
        Cost->Number != static_cast<double>(static_cast<unsigned>(Cost->Number))) {
      Diags.error(Cost->Loc, "'cost' must be a non-negative integer, got " +
                                 json::describeKind(*Cost));
      return false;
    }
    S.Cost = static_cast<unsigned>(Cost->Number);
  }
  return readStringList(F.get("attributes"), S.Attributes, Diags) &&
         readStringList(F.get("settings"), S.Settings, Diags);
}

} // namespace

bool readSignaturesJson(const std::string &Path, const std::string &Text, SignatureMap &Sigs,
                        DiagnosticSink &Diags) {
  std::optional<json::Value> Root = json::parse(Path, Text, Diags);
  if (!Root)
    return false;
  if (!Root->isArray()) {
    Diags.error(Root->Loc, "a signatures file is an array of signatures, got " +
                               json::describeKind(*Root));
    return false;
  }
  bool Ok = true;
  for (const json::Value &F : Root->elements()) {
    FunctionSignature S;
    if (!readSignature(F, S, Diags)) {
      Ok = false;
      continue;
    }
    if (S.RenamedName.empty())
      S.RenamedName = S.Name;
    std::string Name = S.Name;
    Sigs[Name] = std::move(S);
  }
  return Ok;
}

} // namespace texcc::graph
