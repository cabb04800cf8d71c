// graph.json (version 1) to the Graph model. Only the shape of the file is checked here; what
// needs function signatures is checked by compileGraph() (Validate.cpp).

#include "texcc/Graph/Graph.h"
#include "texcc/Support/Numbers.h"

#include "Json.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <unordered_map>

namespace texcc::graph {

const std::vector<std::string> &imageColorSpaces() {
  static const std::vector<std::string> Names = {"sRGB", "Linear Rec.709", "Non-Color"};
  return Names;
}

const Node *Graph::findNode(const std::string &Id) const {
  for (const Node &N : Nodes)
    if (N.Id == Id)
      return &N;
  return nullptr;
}

Node *Graph::findNode(const std::string &Id) {
  for (Node &N : Nodes)
    if (N.Id == Id)
      return &N;
  return nullptr;
}

const std::vector<std::string> &bsdfTypes() {
  static const std::vector<std::string> Types = {"diffuse", "glossy",   "mirror",
                                                 "emission", "principled", "blend"};
  return Types;
}

// The one table of BSDF inputs: canonical order, then which may be left out (the renderer
// then uses the default that docs/graph.md lists). "normal" (a float3 shading normal, e.g. a
// bump node's) is optional on every scattering BSDF.
const std::vector<std::string> &bsdfInputs(const std::string &Type) {
  static const std::vector<std::string> Diffuse = {"color", "normal"},
                                        Glossy = {"color", "roughness", "normal"},
                                        Emission = {"color", "strength"},
                                        Principled = {"baseColor",     "metallic",
                                                      "roughness",     "specular",
                                                      "emissionColor", "emissionStrength",
                                                      "normal"},
                                        Blend = {"mask", "a", "b"}, None;
  if (Type == "diffuse" || Type == "mirror")
    return Diffuse;
  if (Type == "glossy")
    return Glossy;
  if (Type == "emission")
    return Emission;
  if (Type == "principled")
    return Principled;
  if (Type == "blend")
    return Blend;
  return None;
}

bool bsdfInputOptional(const std::string &Type, const std::string &Input) {
  return Input == "normal" || Type == "principled";
}

bool bsdfInputIsVector(const std::string &Input) {
  return Input == "color" || Input == "baseColor" || Input == "emissionColor" ||
         Input == "normal";
}

namespace {

using json::Value;

/// JSON Pointer escaping of one path segment (RFC 6901).
std::string pointerSegment(const std::string &Key) {
  std::string S;
  for (char C : Key) {
    if (C == '~')
      S += "~0";
    else if (C == '/')
      S += "~1";
    else
      S += C;
  }
  return S;
}

class GraphParser {
public:
  GraphParser(const std::string &Path, DiagnosticSink &Diags) : Path(Path), Diags(Diags) {}

  /// Ids and material names are copied into the generated code's comments and into one-line
  /// diagnostics: "" when Name is safe there, else what is wrong with it.
  static std::string unprintableName(const std::string &Name) {
    for (unsigned char C : Name)
      if (C < 0x20 || C == 0x7f) {
        char Buf[48];
        std::snprintf(Buf, sizeof Buf, "a control character (U+%04X)", C);
        return Buf;
      }
    if (Name.find("*/") != std::string::npos)
      return "'*/' (it would end a comment of the generated kernel)";
    return "";
  }

  void error(const SourceLoc &L, const std::string &JsonPath, const std::string &Msg) {
    Diags.error(L, Msg + " [" + (JsonPath.empty() ? "/" : JsonPath) + "]");
  }

  /// Unknown keys are errors that list the allowed ones (and suggest the closest).
  bool checkKeys(const Value &Obj, const std::string &JsonPath, const std::string &What,
                 const std::vector<std::string> &Allowed) {
    bool Ok = true;
    for (const json::Member &M : Obj.Members) {
      bool Known = false;
      for (const std::string &A : Allowed)
        Known |= A == M.Key;
      if (Known)
        continue;
      std::string Msg = "unknown key '" + M.Key + "' in " + What + "; expected " +
                        json::quotedList(Allowed);
      std::string Near = json::closestMatch(M.Key, Allowed);
      if (!Near.empty())
        Msg += "; did you mean '" + Near + "'?";
      error(M.KeyLoc, JsonPath + "/" + pointerSegment(M.Key), Msg);
      Ok = false;
    }
    return Ok;
  }

  const Value *require(const Value &Obj, const std::string &Key, const std::string &JsonPath,
                       const std::string &What) {
    const Value *V = Obj.get(Key);
    if (!V)
      error(Obj.Loc, JsonPath, What + " is missing required key '" + Key + "'");
    return V;
  }

  bool expectKind(const Value &V, Value::Kind K, const std::string &JsonPath,
                  const std::string &What, const char *Expected) {
    if (V.K == K)
      return true;
    error(V.Loc, JsonPath, What + " must be " + Expected + ", got " + json::describeKind(V));
    return false;
  }

  bool checkFloat(const Value &V, const std::string &JsonPath) {
    if (texcc::fitsInFloat(V.Number))
      return true;
    error(V.Loc, JsonPath, "number '" + V.Text + "' does not fit in a 32-bit float");
    return false;
  }

  bool numbersOf(const Value &Arr, std::vector<double> &Out, const std::string &JsonPath) {
    Out.reserve(Out.size() + Arr.size());
    if (Arr.IsPacked) {
      for (size_t I = 0; I < Arr.Numbers.size(); ++I) {
        if (!texcc::fitsInFloat(Arr.Numbers[I])) {
          error(Arr.elementLoc(I), JsonPath + "/" + std::to_string(I),
                "number '" + Arr.elementText(I) + "' does not fit in a 32-bit float");
          return false;
        }
        Out.push_back(Arr.Numbers[I]);
      }
      return true;
    }
    for (size_t I = 0; I < Arr.Elements.size(); ++I) {
      const Value &E = Arr.Elements[I];
      if (!checkFloat(E, JsonPath + "/" + std::to_string(I)))
        return false;
      Out.push_back(E.Number);
    }
    return true;
  }

  bool parseArgArray(const Value &V, ArgValue &A, const std::string &JsonPath) {
    bool AllNumbers = true, AllArrays = !V.IsPacked, AllInts = true;
    for (const Value &E : V.Elements) {
      AllNumbers &= E.isNumber();
      AllArrays &= E.isArray();
      if (E.isNumber())
        AllInts &= E.IsInteger;
    }
    for (bool Integer : V.Integers)
      AllInts &= Integer;
    if (AllNumbers) {
      A.K = V.size() >= 2 && V.size() <= 4 ? ArgValue::Kind::Vector : ArgValue::Kind::Array;
      A.IsInteger = AllInts && V.size() != 0;
      return numbersOf(V, A.Numbers, JsonPath);
    }
    if (!AllArrays) {
      error(V.Loc, JsonPath,
            "an array value must hold only numbers (a vector or a flat array) or only arrays "
            "of numbers (an array of vectors)");
      return false;
    }
    A.K = ArgValue::Kind::Array;
    A.IsArrayOfRows = true;
    A.IsInteger = true;
    for (size_t I = 0; I < V.Elements.size(); ++I) {
      const Value &Row = V.Elements[I];
      std::string RowPath = JsonPath + "/" + std::to_string(I);
      std::vector<double> Numbers;
      for (bool Integer : Row.Integers)
        A.IsInteger &= Integer;
      for (size_t J = 0; J < Row.Elements.size(); ++J) {
        const Value &E = Row.Elements[J];
        if (!E.isNumber()) {
          error(E.Loc, RowPath + "/" + std::to_string(J),
                "an element of an array of vectors must be a number, got " +
                    json::describeKind(E));
          return false;
        }
        A.IsInteger &= E.IsInteger;
      }
      if (!numbersOf(Row, Numbers, RowPath))
        return false;
      A.Rows.push_back(std::move(Numbers));
    }
    return true;
  }

  bool parseArgRef(const Value &V, ArgValue &A, const std::string &JsonPath) {
    static const std::vector<std::string> RefKeys = {"node", "attr", "image"};
    if (V.Members.size() != 1) {
      error(V.Loc, JsonPath,
            "a reference must be an object with exactly one key: 'node', 'attr' or 'image'");
      return false;
    }
    const json::Member &M = V.Members.front();
    if (!checkKeys(V, JsonPath, "reference", RefKeys))
      return false;
    std::string Path = JsonPath + "/" + M.Key;
    if (!expectKind(*M.Val, Value::Kind::String, Path, "'" + M.Key + "'", "a string"))
      return false;
    A.K = M.Key == "node"   ? ArgValue::Kind::NodeRef
          : M.Key == "attr" ? ArgValue::Kind::AttrRef
                            : ArgValue::Kind::ImageRef;
    A.Ref = M.Val->Text;
    return true;
  }

  /// `{"value": 3, "bake": true}`: a literal with options. Only a number or a vector can be
  /// baked: arrays always live in the fake stack (inline code points into it too).
  bool parseLiteralObject(const Value &V, ArgValue &A, const std::string &JsonPath) {
    if (!checkKeys(V, JsonPath, "argument", {"value", "bake"}))
      return false;
    const Value *Literal = require(V, "value", JsonPath, "argument");
    if (!Literal)
      return false;
    std::string ValuePath = JsonPath + "/value";
    if (!Literal->isNumber() && !Literal->isArray()) {
      error(Literal->Loc, ValuePath,
            "'value' must be a number or an array of numbers, got " +
                json::describeKind(*Literal));
      return false;
    }
    if (!parseArgValue(*Literal, A, ValuePath))
      return false;
    A.Loc = V.Loc;
    A.JsonPath = JsonPath;
    const Value *Bake = V.get("bake");
    if (!Bake)
      return true;
    if (!expectKind(*Bake, Value::Kind::Bool, JsonPath + "/bake", "'bake'", "true or false"))
      return false;
    A.Bake = Bake->Bool;
    if (A.Bake && A.K == ArgValue::Kind::Array) {
      error(Bake->Loc, JsonPath + "/bake",
            "only a number or a vector can be baked; arrays stay in the fake stack");
      return false;
    }
    return true;
  }

public:
  bool parseArgValue(const Value &V, ArgValue &A, const std::string &JsonPath) {
    A.Loc = V.Loc;
    A.JsonPath = JsonPath;
    switch (V.K) {
    case Value::Kind::Number:
      A.K = ArgValue::Kind::Number;
      A.IsInteger = V.IsInteger;
      A.Numbers = {V.Number};
      return checkFloat(V, JsonPath);
    case Value::Kind::Array:
      return parseArgArray(V, A, JsonPath);
    case Value::Kind::Object:
      if (V.get("value") || V.get("bake"))
        return parseLiteralObject(V, A, JsonPath);
      return parseArgRef(V, A, JsonPath);
    default:
      error(V.Loc, JsonPath,
            "expected a number, an array, or an object with 'node', 'attr', 'image' or "
            "'value'; got " +
                json::describeKind(V));
      return false;
    }
  }

private:
  bool parseNode(const Value &V, const std::string &JsonPath, Node &N) {
    N.Loc = V.Loc;
    N.JsonPath = JsonPath;
    if (!expectKind(V, Value::Kind::Object, JsonPath, "a node", "an object"))
      return false;
    bool Ok = checkKeys(V, JsonPath, "node", {"id", "fn", "args"});
    const Value *Id = require(V, "id", JsonPath, "node");
    const Value *Fn = require(V, "fn", JsonPath, "node");
    if (Id && expectKind(*Id, Value::Kind::String, JsonPath + "/id", "'id'", "a string")) {
      N.Id = Id->Text;
      N.IdLoc = Id->Loc;
      if (N.Id.empty()) {
        error(Id->Loc, JsonPath + "/id", "a node id must not be empty");
        Ok = false;
      } else if (std::string Why = unprintableName(N.Id); !Why.empty()) {
        error(Id->Loc, JsonPath + "/id", "a node id must not contain " + Why);
        Ok = false;
      }
    } else {
      Ok = false;
    }
    if (Fn && expectKind(*Fn, Value::Kind::String, JsonPath + "/fn", "'fn'", "a string")) {
      N.Fn = Fn->Text;
      N.FnLoc = Fn->Loc;
    } else {
      Ok = false;
    }
    if (const Value *Args = V.get("args")) {
      std::string ArgsPath = JsonPath + "/args";
      if (!expectKind(*Args, Value::Kind::Object, ArgsPath, "'args'", "an object"))
        return false;
      for (const json::Member &M : Args->Members) {
        ArgValue A;
        A.KeyLoc = M.KeyLoc;
        Ok &= parseArgValue(*M.Val, A, ArgsPath + "/" + pointerSegment(M.Key));
        N.Args.emplace_back(M.Key, std::move(A));
      }
    }
    return Ok;
  }

  bool parseBsdf(const Value &V, const std::string &JsonPath, const std::string &What,
                 Bsdf &B) {
    B.Loc = V.Loc;
    B.JsonPath = JsonPath;
    if (!expectKind(V, Value::Kind::Object, JsonPath, What, "an object with a 'bsdf' key"))
      return false;
    const Value *Type = require(V, "bsdf", JsonPath, What);
    if (!Type ||
        !expectKind(*Type, Value::Kind::String, JsonPath + "/bsdf", "'bsdf'", "a string"))
      return false;
    B.Type = Type->Text;
    const std::vector<std::string> &Inputs = bsdfInputs(B.Type);
    if (Inputs.empty()) {
      std::string Msg =
          "unknown BSDF '" + B.Type + "'; expected " + json::quotedList(bsdfTypes());
      std::string Near = json::closestMatch(B.Type, bsdfTypes());
      if (!Near.empty())
        Msg += "; did you mean '" + Near + "'?";
      error(Type->Loc, JsonPath + "/bsdf", Msg);
      return false;
    }
    std::vector<std::string> Allowed = {"bsdf"};
    Allowed.insert(Allowed.end(), Inputs.begin(), Inputs.end());
    bool Ok = true;
    for (const json::Member &M : V.Members) {
      if (M.Key == "bsdf" || bsdfInputsContain(Inputs, M.Key))
        continue;
      std::string Msg = "BSDF '" + B.Type + "' has no input '" + M.Key + "'; its inputs are " +
                        json::quotedList(Inputs);
      std::string Near = json::closestMatch(M.Key, Inputs);
      if (!Near.empty())
        Msg += "; did you mean '" + Near + "'?";
      error(M.KeyLoc, JsonPath + "/" + pointerSegment(M.Key), Msg);
      Ok = false;
    }
    for (const std::string &In : Inputs) {
      const json::Member *M = V.getMember(In);
      std::string InPath = JsonPath + "/" + In;
      if (!M) {
        if (bsdfInputOptional(B.Type, In))
          continue;
        error(V.Loc, JsonPath, "BSDF '" + B.Type + "' is missing input '" + In + "'");
        Ok = false;
        continue;
      }
      if (B.Type == "blend" && In != "mask") {
        Bsdf Child;
        Ok &= parseBsdf(*M->Val, InPath, "blend input '" + In + "'", Child);
        B.Children.emplace_back(In, std::move(Child));
        continue;
      }
      ArgValue A;
      A.KeyLoc = M->KeyLoc;
      if (!parseArgValue(*M->Val, A, InPath)) {
        Ok = false;
        continue;
      }
      if (A.Bake) {
        error(A.Loc, InPath, "BSDF input '" + In + "' cannot be baked; 'bake' is for node "
                             "arguments");
        Ok = false;
        continue;
      }
      if (A.K != ArgValue::Kind::Number && A.K != ArgValue::Kind::Vector &&
          A.K != ArgValue::Kind::NodeRef) {
        error(A.Loc, InPath,
              "BSDF input '" + In + "' must be a number, a vector or {\"node\": id}");
        Ok = false;
        continue;
      }
      B.Inputs.emplace_back(In, std::move(A));
    }
    return Ok;
  }

  static bool bsdfInputsContain(const std::vector<std::string> &Inputs, const std::string &K) {
    for (const std::string &I : Inputs)
      if (I == K)
        return true;
    return false;
  }

  bool parseStrings(const Value &V, const std::string &JsonPath, std::vector<std::string> &Out) {
    if (!expectKind(V, Value::Kind::Array, JsonPath, "'sources'", "an array of strings"))
      return false;
    for (size_t I = 0; I < V.elements().size(); ++I) {
      const Value &E = V.elements()[I];
      if (!expectKind(E, Value::Kind::String, JsonPath + "/" + std::to_string(I),
                      "a source", "a string"))
        return false;
      Out.push_back(E.Text);
    }
    return true;
  }

  bool parseImages(const Value &V, Graph &G) {
    if (!expectKind(V, Value::Kind::Object, "/images", "'images'",
                    "an object (image name to file path)"))
      return false;
    bool Ok = true;
    for (const json::Member &M : V.Members) {
      std::string P = "/images/" + pointerSegment(M.Key);
      const std::string What = "image '" + M.Key + "'";
      if (M.Val->K == Value::Kind::Object) {
        Ok &= parseImageObject(*M.Val, P, What, M.Key, G);
        continue;
      }
      if (expectKind(*M.Val, Value::Kind::String, P, What,
                     "a string (a file path) or an object with 'path' and 'colorspace'"))
        G.Images.emplace_back(M.Key, M.Val->Text);
      else
        Ok = false;
    }
    return Ok;
  }

  /// {"path": "...", "colorspace": "sRGB" | "Linear Rec.709" | "Non-Color"}.
  bool parseImageObject(const Value &V, const std::string &P, const std::string &What,
                        const std::string &Name, Graph &G) {
    bool Ok = checkKeys(V, P, What, {"path", "colorspace"});
    const Value *Path = require(V, "path", P, What);
    if (!Path || !expectKind(*Path, Value::Kind::String, P + "/path", What + ": 'path'",
                             "a string (a file path)"))
      return false;
    if (const Value *C = V.get("colorspace")) {
      if (!expectKind(*C, Value::Kind::String, P + "/colorspace", What + ": 'colorspace'",
                      "a string"))
        return false;
      const std::vector<std::string> &Known = imageColorSpaces();
      if (std::find(Known.begin(), Known.end(), C->Text) == Known.end()) {
        std::string Msg = What + ": unknown colorspace '" + C->Text + "'; expected " +
                          json::quotedList(Known);
        std::string Near = json::closestMatch(C->Text, Known);
        if (!Near.empty())
          Msg += "; did you mean '" + Near + "'?";
        error(C->Loc, P + "/colorspace", Msg);
        return false;
      }
      G.ImageColorSpaces[Name] = C->Text;
    }
    G.Images.emplace_back(Name, Path->Text);
    return Ok;
  }

  bool parseNodes(const Value &V, Graph &G) {
    if (!expectKind(V, Value::Kind::Array, "/nodes", "'nodes'", "an array of node objects"))
      return false;
    bool Ok = true;
    std::unordered_map<std::string, size_t> IndexOf;
    for (size_t I = 0; I < V.elements().size(); ++I) {
      Node N;
      std::string P = "/nodes/" + std::to_string(I);
      if (!parseNode(V.elements()[I], P, N)) {
        Ok = false;
        continue;
      }
      auto [It, Inserted] = IndexOf.emplace(N.Id, G.Nodes.size());
      if (!Inserted) {
        const Node &Prev = G.Nodes[It->second];
        error(N.IdLoc, P + "/id", "duplicate node id '" + N.Id + "'");
        Diags.note(Prev.IdLoc, "previous definition of '" + N.Id + "' is here");
        Ok = false;
        continue;
      }
      G.Nodes.push_back(std::move(N));
    }
    return Ok;
  }

  bool parseMaterials(const Value &V, Graph &G) {
    if (!expectKind(V, Value::Kind::Object, "/materials", "'materials'",
                    "an object (material name to BSDF)"))
      return false;
    bool Ok = true;
    for (const json::Member &M : V.Members) {
      Material Mat;
      Mat.Name = M.Key;
      Mat.Loc = M.KeyLoc;
      if (std::string Why = unprintableName(M.Key); !Why.empty()) {
        error(M.KeyLoc, "/materials", "a material name must not contain " + Why);
        Ok = false;
      }
      Ok &= parseBsdf(*M.Val, "/materials/" + pointerSegment(M.Key),
                      "material '" + M.Key + "'", Mat.Root);
      G.Materials.push_back(std::move(Mat));
    }
    return Ok;
  }

public:
  bool parseTop(const Value &Root, Graph &G) {
    if (!expectKind(Root, Value::Kind::Object, "", "a graph", "an object"))
      return false;
    bool Ok = checkKeys(Root, "", "graph",
                        {"texcc", "sources", "images", "nodes", "materials"});
    const Value *Version = require(Root, "texcc", "", "the graph");
    if (!Version)
      return false;
    if (!Version->isNumber() || !Version->IsInteger || Version->Number != 1) {
      error(Version->Loc, "/texcc",
            "unsupported graph version " +
                (Version->isNumber() ? "'" + Version->Text + "'" : json::describeKind(*Version)) +
                "; this texcc reads version 1");
      return false;
    }
    if (const Value *S = Root.get("sources"))
      Ok &= parseStrings(*S, "/sources", G.Sources);
    if (const Value *I = Root.get("images"))
      Ok &= parseImages(*I, G);
    if (const Value *N = Root.get("nodes"))
      Ok &= parseNodes(*N, G);
    const Value *M = require(Root, "materials", "", "the graph");
    if (M)
      Ok &= parseMaterials(*M, G);
    return Ok && M;
  }

private:
  const std::string &Path;
  DiagnosticSink &Diags;
};

} // namespace

std::optional<Graph> parseGraph(const std::string &Path, const std::string &Text,
                                DiagnosticSink &Diags) {
  std::optional<Value> Root = json::parse(Path, Text, Diags);
  if (!Root)
    return std::nullopt;
  Graph G;
  G.Path = Path;
  GraphParser P(Path, Diags);
  if (!P.parseTop(*Root, G))
    return std::nullopt;
  return G;
}

std::optional<ArgValue> parseArgValue(const std::string &File, const std::string &Text,
                                      DiagnosticSink &Diags) {
  std::optional<Value> V = json::parse(File, Text, Diags);
  if (!V)
    return std::nullopt;
  ArgValue A;
  GraphParser P(File, Diags);
  if (!P.parseArgValue(*V, A, ""))
    return std::nullopt;
  return A;
}

} // namespace texcc::graph
