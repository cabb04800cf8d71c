// Manifest -> layout.json (docs/abi.md): the one writer of the kernel manifest.

#include "texcc/Kernel/Manifest.h"

#include <nlohmann/json.hpp>

namespace texcc::kernel {

using OJson = nlohmann::ordered_json;

namespace {

/// A JSON array of Items, each written by ToJson.
template <typename T, typename F> OJson arrayOf(const std::vector<T> &Items, F ToJson) {
  OJson A = OJson::array();
  for (const T &Item : Items)
    A.push_back(ToJson(Item));
  return A;
}

OJson bsdfJson(const Bsdf &B) {
  OJson J = {{"type", B.Type}};
  for (const auto &[Name, In] : B.Inputs) {
    if (In.IsOutput)
      J[Name] = {{"output", In.Output}};
    else
      J[Name] = {{"const", In.Constant}};
  }
  for (const auto &[Name, Child] : B.Children)
    J[Name] = bsdfJson(Child);
  return J;
}

OJson kernelJson(const KernelEntries &K) {
  OJson J = OJson::object();
  J["source"] = K.Source;
  J["entry"] = K.Entry;
  if (!K.InterpFallback.empty())
    J["interpFallback"] = K.InterpFallback;
  if (!K.Shapes.empty())
    J["shapes"] = arrayOf(K.Shapes, [](const ShapeLayout &S) -> OJson {
      return {{"id", S.Id}, {"materials", S.Materials}};
    });
  if (!K.ShapeHash.empty())
    J["shapeHash"] = K.ShapeHash;
  if (!K.Uniforms.empty())
    J["uniforms"] = K.Uniforms;
  if (!K.Launches.empty())
    J["launches"] = arrayOf(K.Launches, [](const LaunchLayout &L) -> OJson {
      return {{"kernel", L.Kernel}, {"node", L.Node}};
    });
  if (!K.QuickPrograms.empty()) {
    OJson Q = OJson::object();
    Q["programs"] = arrayOf(K.QuickPrograms, [](const QuickProgram &P) -> OJson {
      return {{"source", P.Source}, {"kernels", P.Kernels}};
    });
    Q["launches"] = arrayOf(K.QuickLaunches, [](const LaunchLayout &L) -> OJson {
      return {{"kernel", L.Kernel}, {"node", L.Node}};
    });
    Q["entry"] = K.QuickEntry;
    Q["scratchFloat4PerHit"] = K.QuickScratchFloat4PerHit;
    J["quick"] = Q;
  }
  return J;
}

OJson capabilitiesJson(const Capabilities &C) {
  return {{"reEncodes", C.ReEncodes},
          {"wiringIsData", C.WiringIsData},
          {"shapeKeyed", C.ShapeKeyed},
          {"interpFallback", C.InterpFallback},
          {"stackHeadroom", C.StackHeadroom},
          {"maxOutputs", C.MaxOutputs},
          {"valueStackSlots", C.ValueStackSlots},
          {"decodedAttributes", C.DecodedAttributes},
          {"outputsEntry", C.OutputsEntry}};
}

OJson functionJson(const FunctionLayout &F) {
  OJson Params = arrayOf(F.Params, [](const ParamLayout &P) -> OJson {
    OJson J = {{"name", P.Name}, {"type", P.Type}, {"size", P.Size}, {"align", P.Align},
               {"offset", P.Offset}};
    if (!P.Doc.empty())
      J["doc"] = paramDocJson(P.Doc);
    return J;
  });
  OJson J = {{"id", F.Id},
             {"name", F.Name},
             {"renamed", F.Renamed},
             {"file", F.File},
             {"return", F.Return},
             {"blockSize", F.BlockSize},
             {"params", Params},
             {"attributes", F.Attributes},
             {"settings", F.Settings},
             {"cost", F.Cost}};
  if (F.HasHoisted) {
    OJson Values = arrayOf(F.Hoisted, [](const HoistedLayout &H) -> OJson {
      return {{"name", H.Name}, {"type", H.Type}, {"size", H.Size}, {"offset", H.Offset}};
    });
    J["hoisted"] = {{"values", Values}, {"from", F.HoistedFrom}};
  }
  return J;
}

OJson argJson(const ArgLayout &A) {
  OJson J = {{"name", A.Name}};
  switch (A.Src) {
  case ArgLayout::Source::Attribute:
    J["source"] = "attr";
    J["attr"] = A.Attr;
    J["broadcast"] = A.Broadcast;
    break;
  case ArgLayout::Source::Node:
    J["source"] = "node";
    J["node"] = A.Node;
    J["broadcast"] = A.Broadcast;
    break;
  case ArgLayout::Source::Constant:
    J["source"] = "const";
    if (!A.Image.empty())
      J["image"] = A.Image;
    if (A.IsArray)
      J["array"] = {{"offset", A.ArrayOffset}, {"count", A.ArrayCount}};
    if (A.IntValue) {
      std::vector<long long> Ints(A.Value.begin(), A.Value.end());
      J["value"] = Ints;
    } else {
      J["value"] = A.Value;
    }
    if (A.Bake)
      J["bake"] = true;
    break;
  }
  J["offset"] = A.Offset;
  return J;
}

} // namespace

OJson paramDocJson(const ParamDoc &D) {
  OJson J = OJson::object();
  if (!D.DefaultText.empty())
    J["defaultText"] = D.DefaultText;
  if (!D.Default.empty())
    J["default"] = D.Default;
  if (!D.RangeText.empty())
    J["range"] = D.RangeText;
  if (D.Min)
    J["min"] = *D.Min;
  if (D.Max)
    J["max"] = *D.Max;
  if (!D.Text.empty())
    J["text"] = D.Text;
  return J;
}


std::string writeManifest(const Manifest &M) {
  OJson J;
  J["texcc"] = M.Version;
  // A graph-only layout (texcc-graph: no mode, no kernel) has no mode, options, kernel or
  // capabilities to write.
  const bool HasKernel = !M.Mode.empty();
  if (HasKernel)
    J["mode"] = M.Mode;
  J["target"] = M.Target;
  J["graph"] = M.Graph;
  if (HasKernel) {
    J["compileOptions"] = M.CompileOptions;
    J["kernel"] = kernelJson(M.Kernel);
    J["capabilities"] = capabilitiesJson(M.Caps);
  }
  J["scratchFloat4PerHit"] = M.ScratchFloat4PerHit;
  J["stackSlots"] = M.StackSlots;
  J["stackLimit"] = M.StackLimit;
  J["spill"] = M.Spill;
  J["valueStack"] = M.ValueStack;
  J["maxOutputs"] = M.MaxOutputs;
  J["argsBin"] = {{"size", M.ArgsBinSize.value_or(0)},
                  {"programWords", M.ProgramWords},
                  {"recordsOffset", M.RecordsOffset}};
  J["attributes"] = M.Attributes;
  J["settings"] = M.Settings;
  J["images"] = arrayOf(M.Images, [](const ImageLayout &I) -> OJson {
    OJson J = {{"name", I.Name}, {"path", I.Path}, {"index", I.Index}};
    if (!I.ColorSpace.empty())
      J["colorspace"] = I.ColorSpace;
    return J;
  });
  J["functions"] = arrayOf(M.Functions, functionJson);
  J["quickened"] = arrayOf(M.Quickened, [](const QuickenedLayout &Q) -> OJson {
    if (Q.Legacy)
      return {{"opcode", Q.Opcode}, {"function", Q.Function}, {"second", Q.Second}};
    return {{"opcode", Q.Opcode}, {"function", Q.Function}, {"sources", Q.Sources}};
  });
  if (!M.LegacySuperinstructions.empty())
    J["superinstructions"] = arrayOf(M.LegacySuperinstructions,
                                     [](unsigned Op) -> OJson { return {{"opcode", Op}}; });
  J["nodes"] = arrayOf(M.Nodes, [](const NodeLayout &N) -> OJson {
    return {{"index", N.Index},
            {"id", N.Id},
            {"merged", N.Merged},
            {"fn", N.Fn},
            {"fnId", N.FnId},
            {"record", {{"offset", N.RecordOffset}, {"size", N.RecordSize}}},
            {"copies", N.Copies},
            {"args", arrayOf(N.Args, argJson)}};
  });
  J["wavefrontOrder"] = M.WavefrontOrder;
  J["materials"] = arrayOf(M.Materials, [](const MaterialLayout &Mat) -> OJson {
    OJson Outputs = arrayOf(Mat.Outputs, [](const OutputLayout &O) -> OJson {
      return {{"node", O.Node}, {"slot", O.Slot}, {"type", O.Type}};
    });
    return {{"name", Mat.Name},
            {"index", Mat.Index},
            {"program",
             {{"wordOffset", Mat.ProgramWordOffset},
              {"instructions", Mat.ProgramInstructions},
              {"stackSlots", Mat.ProgramStackSlots}}},
            {"outputs", Outputs},
            {"bsdf", bsdfJson(Mat.Surface)}};
  });
  return J.dump(2) + "\n";
}

} // namespace texcc::kernel
