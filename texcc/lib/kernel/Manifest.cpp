// The kernel manifest's data (texcc/Kernel/Manifest.h): equality (round-trip tests) and the
// small accessors. ManifestReader.cpp reads layout.json, ManifestWriter.cpp writes it.

#include "texcc/Kernel/Manifest.h"

#include <tuple>

namespace texcc::kernel {

// --- Equality (round-trip tests) ---------------------------------------------------------------

bool Capabilities::operator==(const Capabilities &O) const {
  return std::tie(ReEncodes, WiringIsData, ShapeKeyed, InterpFallback, StackHeadroom, MaxOutputs,
                  ValueStackSlots, DecodedAttributes, OutputsEntry) ==
         std::tie(O.ReEncodes, O.WiringIsData, O.ShapeKeyed, O.InterpFallback, O.StackHeadroom,
                  O.MaxOutputs, O.ValueStackSlots, O.DecodedAttributes, O.OutputsEntry);
}
bool BsdfInput::operator==(const BsdfInput &O) const {
  return std::tie(IsOutput, Output, Constant) == std::tie(O.IsOutput, O.Output, O.Constant);
}
bool Bsdf::operator==(const Bsdf &O) const {
  return std::tie(Type, Inputs, Children) == std::tie(O.Type, O.Inputs, O.Children);
}
bool ParamDoc::operator==(const ParamDoc &O) const {
  return std::tie(DefaultText, Default, RangeText, Min, Max, Text) ==
         std::tie(O.DefaultText, O.Default, O.RangeText, O.Min, O.Max, O.Text);
}
bool ParamLayout::operator==(const ParamLayout &O) const {
  return std::tie(Name, Type, Size, Align, Offset, Doc) ==
         std::tie(O.Name, O.Type, O.Size, O.Align, O.Offset, O.Doc);
}
bool HoistedLayout::operator==(const HoistedLayout &O) const {
  return std::tie(Name, Type, Size, Offset) == std::tie(O.Name, O.Type, O.Size, O.Offset);
}
bool FunctionLayout::operator==(const FunctionLayout &O) const {
  return std::tie(Id, Name, Renamed, File, Return, BlockSize, Params, Attributes, Settings, Cost,
                  HasHoisted, Hoisted, HoistedFrom) ==
         std::tie(O.Id, O.Name, O.Renamed, O.File, O.Return, O.BlockSize, O.Params, O.Attributes,
                  O.Settings, O.Cost, O.HasHoisted, O.Hoisted, O.HoistedFrom);
}
bool QuickenedLayout::operator==(const QuickenedLayout &O) const {
  return std::tie(Opcode, Function, Sources, Legacy, Second) ==
         std::tie(O.Opcode, O.Function, O.Sources, O.Legacy, O.Second);
}
bool ArgLayout::operator==(const ArgLayout &O) const {
  return std::tie(Name, Src, Attr, Node, Broadcast, Image, IsArray, ArrayOffset, ArrayCount,
                  IntValue, Value, Bake, Offset) ==
         std::tie(O.Name, O.Src, O.Attr, O.Node, O.Broadcast, O.Image, O.IsArray, O.ArrayOffset,
                  O.ArrayCount, O.IntValue, O.Value, O.Bake, O.Offset);
}
bool NodeLayout::operator==(const NodeLayout &O) const {
  return std::tie(Index, Id, Merged, Fn, FnId, RecordOffset, RecordSize, Copies, Args) ==
         std::tie(O.Index, O.Id, O.Merged, O.Fn, O.FnId, O.RecordOffset, O.RecordSize, O.Copies,
                  O.Args);
}
bool OutputLayout::operator==(const OutputLayout &O) const {
  return std::tie(Node, Slot, Type) == std::tie(O.Node, O.Slot, O.Type);
}
bool MaterialLayout::operator==(const MaterialLayout &O) const {
  return std::tie(Name, Index, ProgramWordOffset, ProgramInstructions, ProgramStackSlots, Outputs,
                  Surface) == std::tie(O.Name, O.Index, O.ProgramWordOffset,
                                       O.ProgramInstructions, O.ProgramStackSlots, O.Outputs,
                                       O.Surface);
}
bool ImageLayout::operator==(const ImageLayout &O) const {
  return std::tie(Name, Path, Index, ColorSpace) ==
         std::tie(O.Name, O.Path, O.Index, O.ColorSpace);
}
bool ShapeLayout::operator==(const ShapeLayout &O) const {
  return std::tie(Id, Materials) == std::tie(O.Id, O.Materials);
}
bool LaunchLayout::operator==(const LaunchLayout &O) const {
  return std::tie(Kernel, Node) == std::tie(O.Kernel, O.Node);
}
bool QuickProgram::operator==(const QuickProgram &O) const {
  return std::tie(Source, Kernels) == std::tie(O.Source, O.Kernels);
}
const char *programRoleName(ProgramRole R) {
  switch (R) {
  case ProgramRole::Primary:
    return "primary";
  case ProgramRole::Fallback:
    return "fallback";
  case ProgramRole::Quick:
    return "quick";
  }
  return "primary";
}

bool RoleProgram::operator==(const RoleProgram &O) const {
  return std::tie(Role, Source, Kernels) == std::tie(O.Role, O.Source, O.Kernels);
}

std::vector<RoleProgram> KernelEntries::programs() const {
  RoleProgram Primary{ProgramRole::Primary, Source, {}};
  for (const LaunchLayout &L : Launches)
    Primary.Kernels.push_back(L.Kernel);
  Primary.Kernels.push_back(Entry);
  if (!Uniforms.empty())
    Primary.Kernels.push_back(Uniforms);
  std::vector<RoleProgram> All{Primary};
  if (!InterpFallback.empty())
    All.push_back({ProgramRole::Fallback, InterpFallback, {Entry}});
  for (const QuickProgram &P : QuickPrograms)
    All.push_back({ProgramRole::Quick, P.Source, P.Kernels});
  return All;
}

std::vector<RoleProgram> KernelEntries::programs(ProgramRole R) const {
  std::vector<RoleProgram> Of;
  for (RoleProgram &P : programs())
    if (P.Role == R)
      Of.push_back(std::move(P));
  return Of;
}

bool KernelEntries::operator==(const KernelEntries &O) const {
  return std::tie(Source, Entry, InterpFallback, Shapes, ShapeHash, Uniforms, Launches,
                  QuickPrograms, QuickLaunches, QuickEntry, QuickScratchFloat4PerHit) ==
         std::tie(O.Source, O.Entry, O.InterpFallback, O.Shapes, O.ShapeHash, O.Uniforms,
                  O.Launches, O.QuickPrograms, O.QuickLaunches, O.QuickEntry,
                  O.QuickScratchFloat4PerHit);
}
bool Manifest::operator==(const Manifest &O) const {
  return std::tie(Version, Mode, Target, Graph, CompileOptions, HasCompileOptions, Kernel, Caps,
                  HasCapabilities, ScratchFloat4PerHit, StackSlots, StackLimit, Spill,
                  ValueStack, MaxOutputs, ArgsBinSize, ProgramWords, RecordsOffset, Attributes,
                  Settings, Images, Functions, Quickened, LegacySuperinstructions, Nodes,
                  WavefrontOrder, Materials) ==
         std::tie(O.Version, O.Mode, O.Target, O.Graph, O.CompileOptions, O.HasCompileOptions,
                  O.Kernel, O.Caps, O.HasCapabilities, O.ScratchFloat4PerHit, O.StackSlots,
                  O.StackLimit, O.Spill, O.ValueStack, O.MaxOutputs, O.ArgsBinSize,
                  O.ProgramWords, O.RecordsOffset, O.Attributes, O.Settings, O.Images,
                  O.Functions, O.Quickened, O.LegacySuperinstructions, O.Nodes,
                  O.WavefrontOrder, O.Materials);
}

const BsdfInput *Bsdf::input(const std::string &Name) const {
  for (auto &I : Inputs)
    if (I.first == Name)
      return &I.second;
  return nullptr;
}

unsigned OutputLayout::components() const {
  if (Type == "float2") return 2;
  if (Type == "float3") return 3;
  if (Type == "float4") return 4;
  return 1;
}

} // namespace texcc::kernel
