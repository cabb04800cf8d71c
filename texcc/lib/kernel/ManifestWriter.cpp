// Manifest -> layout.json (docs/abi.md): the one writer of the kernel manifest.

#include "texcc/Kernel/Manifest.h"

#include <nlohmann/json.hpp>

namespace texcc::kernel {

using OJson = nlohmann::ordered_json;

namespace {

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
  if (!K.Shapes.empty()) {
    OJson Shapes = OJson::array();
    for (const ShapeLayout &S : K.Shapes)
      Shapes.push_back({{"id", S.Id}, {"materials", S.Materials}});
    J["shapes"] = Shapes;
  }
  if (!K.ShapeHash.empty())
    J["shapeHash"] = K.ShapeHash;
  if (!K.Uniforms.empty())
    J["uniforms"] = K.Uniforms;
  if (!K.Launches.empty()) {
    OJson Ls = OJson::array();
    for (const LaunchLayout &L : K.Launches)
      Ls.push_back({{"kernel", L.Kernel}, {"node", L.Node}});
    J["launches"] = Ls;
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
  OJson Params = OJson::array();
  for (const ParamLayout &P : F.Params)
    Params.push_back({{"name", P.Name},
                      {"type", P.Type},
                      {"size", P.Size},
                      {"align", P.Align},
                      {"offset", P.Offset}});
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
    OJson Values = OJson::array();
    for (const HoistedLayout &H : F.Hoisted)
      Values.push_back({{"name", H.Name}, {"type", H.Type}, {"size", H.Size}, {"offset", H.Offset}});
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
  OJson Images = OJson::array();
  for (const ImageLayout &I : M.Images)
    Images.push_back({{"name", I.Name}, {"path", I.Path}, {"index", I.Index}});
  J["images"] = Images;
  OJson Functions = OJson::array();
  for (const FunctionLayout &F : M.Functions)
    Functions.push_back(functionJson(F));
  J["functions"] = Functions;
  OJson Quick = OJson::array();
  for (const QuickenedLayout &Q : M.Quickened) {
    if (Q.Legacy)
      Quick.push_back({{"opcode", Q.Opcode}, {"function", Q.Function}, {"second", Q.Second}});
    else
      Quick.push_back({{"opcode", Q.Opcode}, {"function", Q.Function}, {"sources", Q.Sources}});
  }
  J["quickened"] = Quick;
  if (!M.LegacySuperinstructions.empty()) {
    OJson Supers = OJson::array();
    for (unsigned Op : M.LegacySuperinstructions)
      Supers.push_back({{"opcode", Op}});
    J["superinstructions"] = Supers;
  }
  OJson Nodes = OJson::array();
  for (const NodeLayout &N : M.Nodes) {
    OJson Args = OJson::array();
    for (const ArgLayout &A : N.Args)
      Args.push_back(argJson(A));
    Nodes.push_back({{"index", N.Index},
                     {"id", N.Id},
                     {"merged", N.Merged},
                     {"fn", N.Fn},
                     {"fnId", N.FnId},
                     {"record", {{"offset", N.RecordOffset}, {"size", N.RecordSize}}},
                     {"copies", N.Copies},
                     {"args", Args}});
  }
  J["nodes"] = Nodes;
  J["wavefrontOrder"] = M.WavefrontOrder;
  OJson Materials = OJson::array();
  for (const MaterialLayout &Mat : M.Materials) {
    OJson Outputs = OJson::array();
    for (const OutputLayout &O : Mat.Outputs)
      Outputs.push_back({{"node", O.Node}, {"slot", O.Slot}, {"type", O.Type}});
    Materials.push_back({{"name", Mat.Name},
                         {"index", Mat.Index},
                         {"program",
                          {{"wordOffset", Mat.ProgramWordOffset},
                           {"instructions", Mat.ProgramInstructions},
                           {"stackSlots", Mat.ProgramStackSlots}}},
                         {"outputs", Outputs},
                         {"bsdf", bsdfJson(Mat.Surface)}});
  }
  J["materials"] = Materials;
  return J.dump(2) + "\n";
}

} // namespace texcc::kernel
