// layout.json (docs/abi.md) -> Manifest: the one reader of the kernel manifest, with errors
// that name the file, line, column and JSON pointer of the field.

#include "texcc/Kernel/Manifest.h"
#include "texcc/Support/File.h"

#include <nlohmann/json.hpp>

#include <algorithm>

namespace texcc::kernel {

using Json = nlohmann::json;

std::string ManifestError::str() const {
  std::string S = File;
  if (Line)
    S += ":" + std::to_string(Line) + ":" + std::to_string(Column);
  S += ": ";
  if (!Pointer.empty())
    S += Pointer + ": ";
  return S + Message;
}

namespace {

struct Failure {
  std::string Pointer, Message;
};

[[noreturn]] void fail(const std::string &Pointer, const std::string &Message) {
  throw Failure{Pointer.empty() ? "/" : Pointer, Message};
}

/// Line and column (1-based) of byte Offset of Text.
void position(const std::string &Text, size_t Offset, unsigned &Line, unsigned &Column) {
  Line = 1;
  Column = 1;
  for (size_t I = 0; I < Offset && I < Text.size(); ++I) {
    if (Text[I] == '\n') {
      ++Line;
      Column = 1;
    } else {
      ++Column;
    }
  }
}

/// Where the value at JSON pointer Pointer starts in Text (the deepest member found: a field
/// that is missing points at its object). A small scanner over text nlohmann already accepted.
class Locator {
public:
  explicit Locator(const std::string &T) : Text(T) {}

  size_t find(const std::string &Pointer) {
    std::vector<std::string> Tokens;
    for (size_t I = 1; I <= Pointer.size() && !Pointer.empty();) {
      size_t J = Pointer.find('/', I);
      if (J == std::string::npos)
        J = Pointer.size();
      Tokens.push_back(Pointer.substr(I, J - I));
      I = J + 1;
    }
    Pos = 0;
    space();
    for (const std::string &Tok : Tokens) {
      size_t Found = std::string::npos;
      if (Pos < Text.size() && Text[Pos] == '{')
        Found = member(Tok);
      else if (Pos < Text.size() && Text[Pos] == '[')
        Found = element(Tok);
      if (Found == std::string::npos)
        break;
      Pos = Found;
    }
    return Pos;
  }

private:
  const std::string &Text;
  size_t Pos = 0;

  void space() {
    while (Pos < Text.size() && (Text[Pos] == ' ' || Text[Pos] == '\n' || Text[Pos] == '\r' ||
                                 Text[Pos] == '\t'))
      ++Pos;
  }
  std::string string() { // at '"'
    std::string S;
    for (++Pos; Pos < Text.size() && Text[Pos] != '"'; ++Pos) {
      if (Text[Pos] == '\\')
        ++Pos;
      S += Text[Pos];
    }
    ++Pos;
    return S;
  }
  void skip() { // one value
    space();
    if (Pos >= Text.size())
      return;
    char C = Text[Pos];
    if (C == '"') {
      string();
    } else if (C == '{' || C == '[') {
      int Depth = 0;
      for (; Pos < Text.size(); ++Pos) {
        if (Text[Pos] == '"') {
          string();
          --Pos;
        } else if (Text[Pos] == '{' || Text[Pos] == '[') {
          ++Depth;
        } else if ((Text[Pos] == '}' || Text[Pos] == ']') && --Depth == 0) {
          ++Pos;
          return;
        }
      }
    } else {
      while (Pos < Text.size() && Text[Pos] != ',' && Text[Pos] != '}' && Text[Pos] != ']')
        ++Pos;
    }
  }
  /// At a member's or element's value: past it and the ',' after it; false at the container's
  /// end.
  bool nextItem() {
    skip();
    space();
    if (Pos >= Text.size() || Text[Pos] != ',')
      return false;
    ++Pos;
    return true;
  }
  size_t member(const std::string &Key) {
    ++Pos; // '{'
    for (;;) {
      space();
      if (Pos >= Text.size() || Text[Pos] != '"')
        return std::string::npos;
      std::string K = string();
      space();
      ++Pos; // ':'
      space();
      if (K == Key)
        return Pos;
      if (!nextItem())
        return std::string::npos;
    }
  }
  size_t element(const std::string &Index) {
    size_t N = 0;
    try {
      N = std::stoul(Index);
    } catch (...) {
      return std::string::npos;
    }
    ++Pos; // '['
    for (size_t I = 0;; ++I) {
      space();
      if (Pos >= Text.size() || Text[Pos] == ']')
        return std::string::npos;
      if (I == N)
        return Pos;
      if (!nextItem())
        return std::string::npos;
    }
  }
};

std::string typeName(const Json &J) {
  return J.is_null() ? "null" : J.type_name();
}

/// Typed access to one object: every getter names the field's pointer in its error.
struct Obj {
  const Json &J;
  std::string Ptr;

  Obj(const Json &J, std::string P) : J(J), Ptr(std::move(P)) {
    if (!J.is_object())
      fail(Ptr, "expected an object, not " + typeName(J));
  }
  std::string at(const char *K) const { return Ptr + "/" + K; }
  bool has(const char *K) const { return J.contains(K); }
  const Json &req(const char *K) const {
    if (!J.contains(K))
      fail(Ptr, std::string("missing \"") + K + "\"");
    return J[K];
  }
  std::string str(const char *K, std::optional<std::string> Def = std::nullopt) const {
    if (!J.contains(K)) {
      if (!Def)
        fail(Ptr, std::string("missing \"") + K + "\"");
      return *Def;
    }
    if (!J[K].is_string())
      fail(at(K), "expected a string, not " + typeName(J[K]));
    return J[K].get<std::string>();
  }
  uint64_t num(const char *K, std::optional<uint64_t> Def = std::nullopt) const {
    if (!J.contains(K)) {
      if (!Def)
        fail(Ptr, std::string("missing \"") + K + "\"");
      return *Def;
    }
    if (!J[K].is_number_unsigned() && !(J[K].is_number_integer() && J[K].get<int64_t>() >= 0))
      fail(at(K), "expected a non-negative integer, not " + J[K].dump());
    return J[K].get<uint64_t>();
  }
  unsigned u(const char *K, std::optional<unsigned> Def = std::nullopt) const {
    uint64_t V = num(K, Def ? std::optional<uint64_t>(*Def) : std::nullopt);
    if (V > 0xFFFFFFFFu)
      fail(at(K), "out of range: " + std::to_string(V));
    return static_cast<unsigned>(V);
  }
  bool flag(const char *K, bool Def) const {
    if (!J.contains(K))
      return Def;
    if (!J[K].is_boolean())
      fail(at(K), "expected true or false, not " + J[K].dump());
    return J[K].get<bool>();
  }
  std::vector<std::string> strings(const char *K) const {
    std::vector<std::string> V;
    if (!J.contains(K))
      return V;
    const Json &A = J[K];
    if (!A.is_array())
      fail(at(K), "expected an array of strings, not " + typeName(A));
    for (size_t I = 0; I < A.size(); ++I) {
      if (!A[I].is_string())
        fail(at(K), "expected an array of strings (element " + std::to_string(I) + " is " +
                        typeName(A[I]) + ")");
      V.push_back(A[I].get<std::string>());
    }
    return V;
  }
  std::vector<unsigned> unsigneds(const char *K) const {
    std::vector<unsigned> V;
    if (!J.contains(K))
      return V;
    const Json &A = array(K);
    for (size_t I = 0; I < A.size(); ++I) {
      if (!A[I].is_number_unsigned())
        fail(at(K) + "/" + std::to_string(I), "expected a non-negative integer, not " + A[I].dump());
      V.push_back(A[I].get<unsigned>());
    }
    return V;
  }
  const Json &array(const char *K) const {
    const Json &A = req(K);
    if (!A.is_array())
      fail(at(K), "expected an array, not " + typeName(A));
    return A;
  }
};

BsdfInput readInput(const Json &J, const std::string &Ptr) {
  BsdfInput In;
  if (J.is_object() && J.contains("output")) {
    In.IsOutput = true;
    In.Output = static_cast<int>(Obj(J, Ptr).u("output"));
  } else if (J.is_object() && J.contains("const")) {
    const Json &C = J["const"];
    if (C.is_number())
      In.Constant = {C.get<double>()};
    else if (C.is_array())
      for (auto &V : C) {
        if (!V.is_number())
          fail(Ptr + "/const", "expected numbers");
        In.Constant.push_back(V.get<double>());
      }
    if (In.Constant.empty() || In.Constant.size() > 4)
      fail(Ptr, "expected 1 to 4 numbers in \"const\"");
  } else if (J.is_number()) {
    In.Constant = {J.get<double>()};
  } else {
    fail(Ptr, "expected {\"const\": ...} or {\"output\": k}");
  }
  return In;
}

Bsdf readBsdf(const Json &J, const std::string &Ptr) {
  Obj O(J, Ptr);
  Bsdf B;
  B.Type = O.str("type");
  for (auto &[K, V] : J.items()) {
    if (K == "type")
      continue;
    if (K == "a" || K == "b")
      B.Children.push_back({K, readBsdf(V, Ptr + "/" + K)});
    else
      B.Inputs.push_back({K, readInput(V, Ptr + "/" + K)});
  }
  return B;
}

Capabilities readCapabilities(const Obj &O) {
  Capabilities C;
  C.ReEncodes = O.flag("reEncodes", true);
  C.WiringIsData = O.flag("wiringIsData", false);
  C.ShapeKeyed = O.flag("shapeKeyed", false);
  C.InterpFallback = O.flag("interpFallback", false);
  C.StackHeadroom = O.flag("stackHeadroom", false);
  C.MaxOutputs = std::max(1u, O.u("maxOutputs", 1));
  C.ValueStackSlots = O.u("valueStackSlots", 0);
  C.DecodedAttributes = O.strings("decodedAttributes");
  C.OutputsEntry = O.str("outputsEntry", std::string());
  return C;
}

ParamDoc readParamDoc(const Obj &O) {
  ParamDoc D;
  D.DefaultText = O.str("defaultText", std::string());
  D.RangeText = O.str("range", std::string());
  D.Text = O.str("text", std::string());
  auto number = [&](const char *K) -> std::optional<double> {
    if (!O.has(K))
      return std::nullopt;
    if (!O.J[K].is_number())
      fail(O.at(K), "expected a number, not " + O.J[K].dump());
    return O.J[K].get<double>();
  };
  D.Min = number("min");
  D.Max = number("max");
  if (O.has("default")) {
    const Json &A = O.array("default");
    for (size_t I = 0; I < A.size(); ++I) {
      if (!A[I].is_number())
        fail(O.at("default") + "/" + std::to_string(I), "expected a number, not " + A[I].dump());
      D.Default.push_back(A[I].get<double>());
    }
  }
  return D;
}

FunctionLayout readFunction(const Obj &O) {
  FunctionLayout F;
  F.Id = O.u("id");
  F.Name = O.str("name");
  F.Renamed = O.str("renamed", std::string());
  F.File = O.str("file", std::string());
  F.Return = O.str("return", std::string());
  F.BlockSize = O.u("blockSize", 0);
  const Json &Ps = O.array("params");
  for (size_t I = 0; I < Ps.size(); ++I) {
    Obj P(Ps[I], O.at("params") + "/" + std::to_string(I));
    F.Params.push_back({P.str("name", std::string()), P.str("type"), P.u("size", 0), P.u("align", 0),
                        P.u("offset", 0), P.has("doc") ? readParamDoc(Obj(P.J["doc"], P.at("doc")))
                                                       : ParamDoc{}});
  }
  F.Attributes = O.strings("attributes");
  F.Settings = O.strings("settings");
  F.Cost = O.u("cost", 0);
  if (O.has("hoisted") && !O.J["hoisted"].is_null()) {
    Obj H(O.J["hoisted"], O.at("hoisted"));
    F.HasHoisted = true;
    const Json &Vs = H.array("values");
    for (size_t I = 0; I < Vs.size(); ++I) {
      Obj V(Vs[I], H.at("values") + "/" + std::to_string(I));
      F.Hoisted.push_back({V.str("name"), V.str("type"), V.u("size", 0), V.u("offset", 0)});
    }
    F.HoistedFrom = H.strings("from");
  }
  return F;
}

ArgLayout readArg(const Obj &O) {
  ArgLayout A;
  A.Name = O.str("name");
  const std::string Src = O.str("source");
  A.Offset = O.u("offset", 0);
  if (Src == "attr") {
    A.Src = ArgLayout::Source::Attribute;
    A.Attr = O.str("attr");
    A.Broadcast = O.flag("broadcast", false);
  } else if (Src == "node") {
    A.Src = ArgLayout::Source::Node;
    A.Node = O.u("node");
    A.Broadcast = O.flag("broadcast", false);
  } else if (Src == "const") {
    A.Src = ArgLayout::Source::Constant;
    A.Image = O.str("image", std::string());
    if (O.has("array")) {
      Obj Ar(O.J["array"], O.at("array"));
      A.IsArray = true;
      A.ArrayOffset = Ar.u("offset");
      A.ArrayCount = Ar.u("count");
    }
    if (O.has("value")) {
      const Json &V = O.J["value"];
      if (!V.is_array())
        fail(O.at("value"), "expected an array of numbers, not " + typeName(V));
      A.IntValue = !V.empty();
      for (size_t I = 0; I < V.size(); ++I) {
        if (!V[I].is_number())
          fail(O.at("value") + "/" + std::to_string(I), "expected a number, not " + typeName(V[I]));
        A.IntValue &= V[I].is_number_integer();
        A.Value.push_back(V[I].get<double>());
      }
    }
    A.Bake = O.flag("bake", false);
  } else {
    fail(O.at("source"), "expected \"attr\", \"node\" or \"const\", not \"" + Src + "\"");
  }
  return A;
}

NodeLayout readNode(const Obj &O, size_t I) {
  NodeLayout N;
  N.Index = O.u("index", static_cast<unsigned>(I));
  N.Id = O.str("id");
  N.Merged = O.strings("merged");
  N.Fn = O.str("fn");
  N.FnId = O.u("fnId", 0);
  if (O.has("record")) {
    Obj R(O.J["record"], O.at("record"));
    N.RecordOffset = R.u("offset", 0);
    N.RecordSize = R.u("size", 0);
  }
  N.Copies = O.unsigneds("copies");
  if (O.has("args")) {
    const Json &As = O.array("args");
    for (size_t K = 0; K < As.size(); ++K)
      N.Args.push_back(readArg(Obj(As[K], O.at("args") + "/" + std::to_string(K))));
  }
  return N;
}

MaterialLayout readMaterial(const Obj &O, size_t I) {
  MaterialLayout M;
  M.Name = O.str("name");
  M.Index = static_cast<int>(O.u("index", static_cast<unsigned>(I)));
  if (O.has("program")) {
    Obj P(O.J["program"], O.at("program"));
    M.ProgramWordOffset = P.u("wordOffset", 0);
    M.ProgramInstructions = P.u("instructions", 0);
    M.ProgramStackSlots = P.u("stackSlots", 0);
  }
  if (O.has("outputs")) {
    const Json &Os = O.array("outputs");
    for (size_t K = 0; K < Os.size(); ++K) {
      Obj Out(Os[K], O.at("outputs") + "/" + std::to_string(K));
      M.Outputs.push_back({Out.u("node", 0), Out.u("slot", 0), Out.str("type", "float")});
    }
  }
  M.Surface = readBsdf(O.req("bsdf"), O.at("bsdf"));
  return M;
}

void readTop(const Json &J, Manifest &M) {
  Obj O(J, "");
  if (!O.has("texcc"))
    fail("/", "missing \"texcc\" (not a layout.json of texcc?)");
  if (!J["texcc"].is_number_unsigned() || J["texcc"].get<unsigned>() != ManifestVersion)
    fail("/texcc", "layout version " + J["texcc"].dump() + ", expected " +
                       std::to_string(ManifestVersion) + " (run this texcc again)");
  M.Version = ManifestVersion;
  // A graph-only layout (texcc-graph) has neither a mode nor a kernel.
  const bool GraphOnly = !O.has("mode") && !O.has("kernel");
  M.Mode = GraphOnly ? std::string() : O.str("mode");
  M.Target = O.str("target", std::string("opencl"));
  M.Graph = O.str("graph", std::string());
  M.HasCompileOptions = O.has("compileOptions");
  M.CompileOptions = M.HasCompileOptions ? O.strings("compileOptions")
                     : GraphOnly         ? std::vector<std::string>{}
                                         : std::vector<std::string>{"--mode=" + M.Mode};
  if (!GraphOnly) {
    Obj K(O.req("kernel"), "/kernel");
    M.Kernel.Source = K.str("source", std::string("proctex.cl"));
    M.Kernel.Entry = K.str("entry", std::string("texcc_proctex"));
    M.Kernel.InterpFallback = K.str("interpFallback", std::string());
    if (K.has("shapes")) {
      const Json &S = K.array("shapes");
      for (size_t I = 0; I < S.size(); ++I) {
        Obj Sh(S[I], "/kernel/shapes/" + std::to_string(I));
        M.Kernel.Shapes.push_back({Sh.u("id", static_cast<unsigned>(I)), Sh.unsigneds("materials")});
      }
    }
    M.Kernel.ShapeHash = K.str("shapeHash", std::string());
    M.Kernel.Uniforms = K.str("uniforms", std::string());
    if (K.has("launches")) {
      const Json &Ls = K.array("launches");
      for (size_t I = 0; I < Ls.size(); ++I) {
        Obj La(Ls[I], "/kernel/launches/" + std::to_string(I));
        M.Kernel.Launches.push_back({La.str("kernel"), La.u("node", 0)});
      }
    }
    if (K.has("quick")) {
      Obj Q(K.req("quick"), "/kernel/quick");
      const Json &Ps = Q.array("programs");
      for (size_t I = 0; I < Ps.size(); ++I) {
        Obj P(Ps[I], "/kernel/quick/programs/" + std::to_string(I));
        M.Kernel.QuickPrograms.push_back({P.str("source"), P.strings("kernels")});
      }
      const Json &Ls = Q.array("launches");
      for (size_t I = 0; I < Ls.size(); ++I) {
        Obj La(Ls[I], "/kernel/quick/launches/" + std::to_string(I));
        M.Kernel.QuickLaunches.push_back({La.str("kernel"), La.u("node", 0)});
      }
      M.Kernel.QuickEntry = Q.str("entry");
      M.Kernel.QuickScratchFloat4PerHit = Q.u("scratchFloat4PerHit", 0);
    }
  }
  M.MaxOutputs = std::max(1u, O.u("maxOutputs", 1));
  M.HasCapabilities = O.has("capabilities");
  if (M.HasCapabilities) {
    M.Caps = readCapabilities(Obj(J["capabilities"], "/capabilities"));
  } else if (GraphOnly) {
    M.Caps = Capabilities{};
    M.Caps.MaxOutputs = M.MaxOutputs;
  } else {
    // What a kernel can absorb is the backend's word (docs/abi.md); a layout without it was
    // written by a texcc older than the block, and no table here guesses it from the mode.
    fail("/capabilities", "missing: this layout.json was written by an older texcc (run texcc "
                          "again)");
  }
  if (M.Caps.InterpFallback && M.Kernel.InterpFallback.empty())
    fail("/kernel/interpFallback", "missing (the capabilities name an interp fallback kernel)");
  M.ScratchFloat4PerHit = O.u("scratchFloat4PerHit", 0);
  M.StackSlots = O.u("stackSlots", 0);
  M.StackLimit = O.u("stackLimit", 32);
  M.Spill = O.flag("spill", false);
  M.ValueStack = O.str("valueStack", std::string(M.Spill ? "global" : "private"));
  if (O.has("argsBin")) {
    Obj A(J["argsBin"], "/argsBin");
    if (A.has("size"))
      M.ArgsBinSize = A.num("size");
    M.ProgramWords = A.u("programWords", 0);
    M.RecordsOffset = A.u("recordsOffset", 0);
  }
  M.Attributes = O.strings("attributes");
  M.Settings = O.strings("settings");
  if (O.has("images")) {
    const Json &Is = O.array("images");
    for (size_t I = 0; I < Is.size(); ++I) {
      Obj Im(Is[I], "/images/" + std::to_string(I));
      M.Images.push_back({Im.str("name"), Im.str("path"), Im.u("index", static_cast<unsigned>(I)),
                          Im.str("colorspace", std::string())});
    }
  }
  if (O.has("functions")) {
    const Json &Fs = O.array("functions");
    for (size_t I = 0; I < Fs.size(); ++I)
      M.Functions.push_back(readFunction(Obj(Fs[I], "/functions/" + std::to_string(I))));
  }
  if (O.has("superinstructions")) { // a texcc before 2026-12
    const Json &Ss = O.array("superinstructions");
    for (size_t I = 0; I < Ss.size(); ++I)
      M.LegacySuperinstructions.push_back(
          Obj(Ss[I], "/superinstructions/" + std::to_string(I)).u("opcode"));
  }
  if (O.has("quickened")) {
    const Json &Qs = O.array("quickened");
    for (size_t I = 0; I < Qs.size(); ++I) {
      Obj Q(Qs[I], "/quickened/" + std::to_string(I));
      QuickenedLayout E;
      E.Opcode = Q.u("opcode");
      E.Function = Q.str("function");
      if (Q.has("second")) {
        E.Legacy = true;
        E.Second = Q.J["second"].is_string() ? Q.J["second"].get<std::string>() : Q.J["second"].dump();
      } else {
        E.Sources = Q.strings("sources");
      }
      M.Quickened.push_back(E);
    }
  }
  if (O.has("nodes")) {
    const Json &Ns = O.array("nodes");
    for (size_t I = 0; I < Ns.size(); ++I)
      M.Nodes.push_back(readNode(Obj(Ns[I], "/nodes/" + std::to_string(I)), I));
  }
  M.WavefrontOrder = O.unsigneds("wavefrontOrder");
  const Json &Ms = O.array("materials");
  for (size_t I = 0; I < Ms.size(); ++I)
    M.Materials.push_back(readMaterial(Obj(Ms[I], "/materials/" + std::to_string(I)), I));
}

} // namespace

bool readManifest(const std::string &Text, const std::string &File, Manifest &Out,
                  ManifestError &Error) {
  Error = ManifestError();
  Error.File = File;
  Json J;
  try {
    J = Json::parse(Text);
  } catch (const Json::parse_error &E) {
    position(Text, E.byte ? E.byte - 1 : 0, Error.Line, Error.Column);
    std::string What = E.what();
    // "[json.exception.parse_error.101] parse error at line 3, column 5: syntax error ..."
    size_t Colon = What.find("syntax error");
    Error.Message = "invalid JSON: " + (Colon == std::string::npos ? What : What.substr(Colon));
    return false;
  }
  Manifest M;
  try {
    readTop(J, M);
  } catch (const Failure &F) {
    Error.Pointer = F.Pointer;
    Error.Message = F.Message;
    position(Text, Locator(Text).find(F.Pointer == "/" ? "" : F.Pointer), Error.Line,
             Error.Column);
    return false;
  } catch (const Json::exception &E) {
    Error.Message = std::string("malformed layout: ") + E.what();
    return false;
  }
  Out = std::move(M);
  return true;
}

bool readManifestFile(const std::string &Path, Manifest &Out, ManifestError &Error) {
  std::string Text, Why;
  if (!texcc::readRegularFile(Path, Text, Why)) {
    Error = ManifestError();
    Error.File = Path;
    Error.Message = "cannot open: " + Why;
    return false;
  }
  return readManifest(Text, Path, Out, Error);
}

} // namespace texcc::kernel
