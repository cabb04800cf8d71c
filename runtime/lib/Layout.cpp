#include "texrender/Layout.h"
#include "texrender/Error.h"
#include "texrender/Image.h"
#include "texcc/Support/File.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace texrender {

const LayoutInput *LayoutBsdf::input(const std::string &Name) const {
  for (auto &I : Inputs)
    if (I.first == Name)
      return &I.second;
  return nullptr;
}

int Layout::findMaterial(const std::string &Name) const {
  for (auto &M : Materials)
    if (M.Name == Name)
      return M.Index;
  return -1;
}

std::string Layout::materialNames() const {
  std::string S;
  for (auto &M : Materials)
    S += (S.empty() ? "" : ", ") + M.Name;
  return S.empty() ? "(none)" : S;
}

namespace {

std::string readFile(const std::string &Path) {
  std::string Text, Why;
  if (!texcc::readRegularFile(Path, Text, Why))
    throw Error(Path + ": cannot open: " + Why + " (is --textures the texcc output folder?)");
  return Text;
}

unsigned componentsOf(const std::string &Type) {
  if (Type == "float2") return 2;
  if (Type == "float3") return 3;
  if (Type == "float4") return 4;
  return 1;
}

struct LayoutReader {
  std::string File;
  [[noreturn]] void fail(const std::string &Path, const std::string &Why) const {
    throw Error(File + ": " + Path + ": " + Why);
  }
  const json &get(const json &J, const char *Key, const std::string &Path) const {
    if (!J.is_object() || !J.contains(Key))
      fail(Path, std::string("missing \"") + Key + "\"");
    return J[Key];
  }

  LayoutInput input(const json &J, const std::string &Path) const {
    LayoutInput In;
    if (J.is_object() && J.contains("output")) {
      In.IsOutput = true;
      In.Output = J["output"].get<int>();
    } else if (J.is_object() && J.contains("const")) {
      const json &C = J["const"];
      if (C.is_number())
        In.Constant = {C.get<float>()};
      else if (C.is_array())
        for (auto &V : C)
          In.Constant.push_back(V.get<float>());
      if (In.Constant.empty() || In.Constant.size() > 4)
        fail(Path, "expected 1 to 4 numbers in \"const\"");
    } else if (J.is_number()) {
      In.Constant = {J.get<float>()};
    } else {
      fail(Path, "expected {\"const\": ...} or {\"output\": k}");
    }
    return In;
  }

  LayoutBsdf bsdf(const json &J, const std::string &Path) const {
    LayoutBsdf B;
    B.Type = get(J, "type", Path).get<std::string>();
    for (auto &[K, V] : J.items()) {
      if (K == "type")
        continue;
      if (K == "a" || K == "b")
        B.Children.push_back({K, bsdf(V, Path + "/" + K)});
      else
        B.Inputs.push_back({K, input(V, Path + "/" + K)});
    }
    return B;
  }
};

} // namespace

/// Per node: whether it reads AO (its function's call tree, or an argument) directly or through
/// the nodes it depends on. Memoized and with an explicit stack: a DAG with much sharing must
/// not take exponential time, nor a 5000-deep chain recursion. An unknown node (or a cycle,
/// which texcc never writes) counts as reading AO.
static std::vector<bool> nodesReadingAo(const std::vector<json> &Nodes,
                                        const std::map<unsigned, bool> &FnReadsAo) {
  enum State : char { Unvisited, Open, Done };
  std::vector<State> St(Nodes.size(), Unvisited);
  std::vector<bool> Reads(Nodes.size(), false);
  auto Children = [&](size_t I) {
    std::vector<size_t> C;
    for (auto &A : Nodes[I].value("args", json::array()))
      if (A.value("source", "") == "node")
        C.push_back(A.value("node", Nodes.size()));
    return C;
  };
  for (size_t Root = 0; Root < Nodes.size(); ++Root) {
    std::vector<size_t> Stack{Root};
    while (!Stack.empty()) {
      size_t I = Stack.back();
      if (St[I] == Done) {
        Stack.pop_back();
        continue;
      }
      std::vector<size_t> Kids = Children(I);
      if (St[I] == Unvisited) {
        St[I] = Open;
        for (size_t C : Kids)
          if (C < Nodes.size() && St[C] == Unvisited)
            Stack.push_back(C);
        continue;
      }
      bool R = FnReadsAo.count(Nodes[I].value("fnId", 0u)) > 0;
      for (auto &A : Nodes[I].value("args", json::array()))
        R |= A.value("source", "") == "attr" && A.value("attr", "") == "AO";
      for (size_t C : Kids)
        R |= C >= Nodes.size() || St[C] != Done || Reads[C];
      Reads[I] = R;
      St[I] = Done;
      Stack.pop_back();
    }
  }
  return Reads;
}

/// The one place the runtime knows the modes by name: what each mode's kernel can absorb.
static const std::pair<const char *, KernelCapabilities> ModeCapabilities[] = {
    // ReEncodes, WiringIsData, ShapeKeyed, InterpFallback, StackHeadroom
    {"interp", {true, true, false, false, true}},
    {"inline", {false, false, false, false, false}},
    {"wavefront", {true, false, false, false, false}},
    {"shape", {true, false, true, true, false}},
};

std::optional<KernelCapabilities> modeCapabilities(const std::string &Mode) {
  for (const auto &MC : ModeCapabilities)
    if (Mode == MC.first)
      return MC.second;
  return std::nullopt;
}

Layout loadLayout(const std::string &OutDir) {
  Layout L;
  L.Dir = OutDir;
  std::string File = (fs::path(OutDir) / "layout.json").string();
  L.Text = readFile(File);
  LayoutReader R{File};
  json J;
  std::optional<size_t> ArgsBinSize;
  try {
    J = json::parse(L.Text);
  } catch (const json::parse_error &E) {
    throw Error(File + ": invalid JSON: " + E.what());
  }
  try {
    if (!J.contains("texcc") || J["texcc"] != 1)
      R.fail("/texcc", "expected layout version 1");
    L.Mode = R.get(J, "mode", "").get<std::string>();
    std::optional<KernelCapabilities> Caps = modeCapabilities(L.Mode);
    if (!Caps)
      R.fail("/mode", "unknown mode '" + L.Mode + "'");
    L.Caps = *Caps;
    if (J.contains("target") && J["target"] != "opencl")
      R.fail("/target", "texrender runs OpenCL output only (texcc --target=opencl)");
    if (J.contains("argsBin") && J["argsBin"].contains("size"))
      ArgsBinSize = J["argsBin"]["size"].get<size_t>();
    L.GraphPath = J.value("graph", "");
    if (!L.GraphPath.empty() && fs::path(L.GraphPath).is_relative())
      L.GraphPath = (fs::path(OutDir) / L.GraphPath).lexically_normal().string();
    // The arguments a regeneration passes to texcc again; a layout from a texcc before
    // "compileOptions" had only the mode to go by.
    if (J.contains("compileOptions")) {
      const json &CO = J["compileOptions"];
      if (!CO.is_array() || !std::all_of(CO.begin(), CO.end(), [](const json &A) { return A.is_string(); }))
        R.fail("/compileOptions", "expected an array of strings (texcc's arguments)");
      L.CompileOptions = CO.get<std::vector<std::string>>();
    } else {
      L.CompileOptions = {"--mode=" + L.Mode};
    }
    const json &K = R.get(J, "kernel", "");
    L.KernelSource = (fs::path(OutDir) / K.value("source", "proctex.cl")).string();
    L.Entry = K.value("entry", "texcc_proctex");
    if (K.contains("launches"))
      for (auto &La : K["launches"])
        L.WavefrontLaunches.push_back(La.at("kernel").get<std::string>());
    if (K.contains("interpFallback"))
      L.InterpFallback = (fs::path(OutDir) / K["interpFallback"].get<std::string>()).string();
    if (K.contains("shapes"))
      L.NumShapes = unsigned(K["shapes"].size());
    L.ShapeHash = K.value("shapeHash", "");
    if (K.contains("uniforms") && !K["uniforms"].is_string())
      R.fail("/kernel/uniforms", "the hoisted-value kernel's name must be a string");
    L.Uniforms = K.value("uniforms", "");
    if (L.Caps.InterpFallback && L.InterpFallback.empty())
      R.fail("/kernel/interpFallback", "a shape-mode layout names its interp fallback kernel");
    L.StackSlots = J.value("stackSlots", 0u);
    L.StackLimit = J.value("stackLimit", 32u);
    L.Spill = J.value("spill", false);
    L.MaxOutputs = std::max(1u, J.value("maxOutputs", 1u));
    L.Caps.MaxOutputs = L.MaxOutputs;
    L.ScratchFloat4PerHit = J.value("scratchFloat4PerHit", 0u);
    if (J.contains("attributes"))
      L.Attributes = J["attributes"].get<std::vector<std::string>>();
    if (J.contains("settings"))
      L.Settings = J["settings"].get<std::vector<std::string>>();
    if (J.contains("images"))
      for (auto &I : J["images"]) {
        fs::path P(I.at("path").get<std::string>());
        L.Images.push_back(
            {I.at("name").get<std::string>(), (P.is_absolute() ? P : fs::path(OutDir) / P).string()});
      }
    // Which nodes read AO (their function's call tree, or an argument), through the nodes
    // they depend on: a material whose outputs do not depend on AO traces no AO rays.
    std::map<unsigned, bool> FnReadsAo;
    if (J.contains("functions"))
      for (auto &F : J["functions"])
        for (auto &A : F.value("attributes", json::array()))
          if (A == "AO")
            FnReadsAo[F.at("id").get<unsigned>()] = true;
    std::vector<json> Nodes;
    if (J.contains("nodes"))
      for (auto &N : J["nodes"])
        Nodes.push_back(N);
    std::vector<bool> ReadsAo = nodesReadingAo(Nodes, FnReadsAo);
    auto NodeReadsAo = [&](size_t I) { return I >= ReadsAo.size() || ReadsAo[I]; };
    const json &Ms = R.get(J, "materials", "");
    for (size_t I = 0; I < Ms.size(); ++I) {
      std::string P = "/materials/" + std::to_string(I);
      LayoutMaterial M;
      M.Name = R.get(Ms[I], "name", P).get<std::string>();
      M.Index = Ms[I].value("index", static_cast<int>(I));
      if (Ms[I].contains("outputs"))
        for (auto &O : Ms[I]["outputs"])
        {
          M.OutputComponents.push_back(componentsOf(O.value("type", "float")));
          size_t Node = O.value("node", size_t(0));
          M.ReadsAo |= Nodes.empty() ? true : NodeReadsAo(Node);
          M.OutputNodes.push_back(Node < Nodes.size() ? Nodes[Node].value("id", "?") : "?");
        }
      M.Bsdf = R.bsdf(R.get(Ms[I], "bsdf", P), P + "/bsdf");
      L.Materials.push_back(M);
    }
  } catch (const json::exception &E) {
    throw Error(File + ": malformed layout: " + E.what());
  }
  std::string ArgsPath = (fs::path(OutDir) / "args.bin").string();
  std::string Args = readFile(ArgsPath);
  L.ArgsBin.assign(Args.begin(), Args.end());
  // The kernels index args.bin by layout.json's offsets: a short (truncated, or stale) file
  // would have them read past the buffer.
  size_t Declared = ArgsBinSize ? *ArgsBinSize : L.ArgsBin.size();
  if (L.ArgsBin.size() != Declared)
    throw Error(ArgsPath + ": " + std::to_string(L.ArgsBin.size()) + " bytes, but " + File +
                " says " + std::to_string(Declared) +
                " (a truncated or stale texcc output: run texcc again)");
  return L;
}

} // namespace texrender
