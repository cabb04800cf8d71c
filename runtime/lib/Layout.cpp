#include "texrender/Layout.h"
#include "texrender/Error.h"
#include "texrender/Image.h"
#include "texcc/Support/File.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <set>
#include <optional>
#include <sstream>

namespace fs = std::filesystem;

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

LayoutInput input(const texcc::kernel::BsdfInput &In) {
  LayoutInput L;
  L.IsOutput = In.IsOutput;
  L.Output = In.Output;
  L.Constant.assign(In.Constant.begin(), In.Constant.end());
  return L;
}

LayoutBsdf bsdf(const texcc::kernel::Bsdf &B) {
  LayoutBsdf L;
  L.Type = B.Type;
  for (const auto &[Name, In] : B.Inputs)
    L.Inputs.push_back({Name, input(In)});
  for (const auto &[Name, Child] : B.Children)
    L.Children.push_back({Name, bsdf(Child)});
  return L;
}

} // namespace

/// Per node: whether it reads AO (its function's call tree, or an argument) directly or through
/// the nodes it depends on. Memoized and with an explicit stack: a DAG with much sharing must
/// not take exponential time, nor a 5000-deep chain recursion. An unknown node (or a cycle,
/// which texcc never writes) counts as reading AO.
static std::vector<bool> nodesReadingAo(const std::vector<texcc::kernel::NodeLayout> &Nodes,
                                        const std::set<unsigned> &FnReadsAo) {
  enum State : char { Unvisited, Open, Done };
  std::vector<State> St(Nodes.size(), Unvisited);
  std::vector<bool> Reads(Nodes.size(), false);
  using Arg = texcc::kernel::ArgLayout;
  auto Children = [&](size_t I) {
    std::vector<size_t> C;
    for (const Arg &A : Nodes[I].Args)
      if (A.Src == Arg::Source::Node)
        C.push_back(A.Node);
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
      bool R = FnReadsAo.count(Nodes[I].FnId) > 0;
      for (const Arg &A : Nodes[I].Args)
        R |= A.Src == Arg::Source::Attribute && A.Attr == "AO";
      for (size_t C : Kids)
        R |= C >= Nodes.size() || St[C] != Done || Reads[C];
      Reads[I] = R;
      St[I] = Done;
      Stack.pop_back();
    }
  }
  return Reads;
}

Layout loadLayout(const std::string &OutDir) {
  Layout L;
  L.Dir = OutDir;
  std::string File = (fs::path(OutDir) / "layout.json").string();
  L.Text = readFile(File);
  texcc::kernel::ManifestError Why;
  if (!texcc::kernel::readManifest(L.Text, File, L.Manifest, Why))
    throw Error(Why.str());
  const texcc::kernel::Manifest &M = L.Manifest;
  if (M.Mode.empty())
    throw Error(File + ": /: no \"mode\" and no \"kernel\": a graph-only layout (texcc-graph), "
                       "not a texture folder made by texcc");
  if (M.Target != "opencl")
    throw Error(File + ": /target: texrender runs OpenCL output only (texcc --target=opencl)");
  L.Mode = M.Mode;
  L.Caps = M.Caps;
  L.GraphPath = M.Graph;
  if (!L.GraphPath.empty() && fs::path(L.GraphPath).is_relative())
    L.GraphPath = (fs::path(OutDir) / L.GraphPath).lexically_normal().string();
  L.CompileOptions = M.CompileOptions;
  L.KernelSource = (fs::path(OutDir) / M.Kernel.Source).string();
  L.Entry = M.Kernel.Entry;
  for (const texcc::kernel::LaunchLayout &La : M.Kernel.Launches)
    L.WavefrontLaunches.push_back(La.Kernel);
  if (!M.Kernel.InterpFallback.empty())
    L.InterpFallback = (fs::path(OutDir) / M.Kernel.InterpFallback).string();
  L.NumShapes = unsigned(M.Kernel.Shapes.size());
  L.ShapeHash = M.Kernel.ShapeHash;
  L.Uniforms = M.Kernel.Uniforms;
  L.StackSlots = M.StackSlots;
  L.StackLimit = M.StackLimit;
  L.Spill = M.Spill;
  L.MaxOutputs = M.MaxOutputs;
  L.Caps.MaxOutputs = L.MaxOutputs;
  L.ScratchFloat4PerHit = M.ScratchFloat4PerHit;
  L.Attributes = M.Attributes;
  L.Settings = M.Settings;
  for (const texcc::kernel::ImageLayout &I : M.Images) {
    fs::path P(I.Path);
    L.Images.push_back(
        {I.Name, (P.is_absolute() ? P : fs::path(OutDir) / P).string(), I.ColorSpace});
  }
  // Which nodes read AO (their function's call tree, or an argument), through the nodes they
  // depend on: a material whose outputs do not depend on AO traces no AO rays.
  std::set<unsigned> FnReadsAo;
  for (const texcc::kernel::FunctionLayout &F : M.Functions)
    if (std::find(F.Attributes.begin(), F.Attributes.end(), "AO") != F.Attributes.end())
      FnReadsAo.insert(F.Id);
  std::vector<bool> ReadsAo = nodesReadingAo(M.Nodes, FnReadsAo);
  for (const texcc::kernel::MaterialLayout &Mat : M.Materials) {
    LayoutMaterial LM;
    LM.Name = Mat.Name;
    LM.Index = Mat.Index;
    for (const texcc::kernel::OutputLayout &O : Mat.Outputs) {
      LM.OutputComponents.push_back(O.components());
      LM.ReadsAo |= M.Nodes.empty() || O.Node >= ReadsAo.size() || ReadsAo[O.Node];
      LM.OutputNodes.push_back(O.Node < M.Nodes.size() ? M.Nodes[O.Node].Id : "?");
    }
    LM.Bsdf = bsdf(Mat.Surface);
    L.Materials.push_back(LM);
  }
  std::optional<uint64_t> ArgsBinSize = M.ArgsBinSize;
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
