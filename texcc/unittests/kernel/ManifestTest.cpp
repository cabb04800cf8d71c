// The kernel manifest (layout.json): every field round-trips through writeManifest and
// readManifest; malformed input names the file, position and field; an old layout without
// "capabilities" gets its mode's.

#include "texcc/Kernel/Attributes.h"
#include "texcc/Kernel/Manifest.h"

#include <gtest/gtest.h>

#include <algorithm>

using namespace texcc::kernel;

namespace {

/// A manifest with every field set away from its default.
Manifest everyField() {
  Manifest M;
  M.Mode = "shape";
  M.Target = "opencl";
  M.Graph = "/g/graph.json";
  M.CompileOptions = {"--mode=shape", "-DX=1", "-I/inc"};
  M.Kernel.Source = "k.cl";
  M.Kernel.Entry = "entry_fn";
  M.Kernel.InterpFallback = "proctex.interp.cl";
  M.Kernel.Shapes = {{0, {0, 2}}, {1, {1}}};
  M.Kernel.ShapeHash = "0123456789abcdef";
  M.Kernel.Uniforms = "texcc_uniforms";
  M.Kernel.Launches = {{"texcc_wf_0", 0}, {"texcc_wf_3", 3}};
  M.Caps.ReEncodes = false;
  M.Caps.WiringIsData = true;
  M.Caps.ShapeKeyed = true;
  M.Caps.InterpFallback = true;
  M.Caps.StackHeadroom = true;
  M.Caps.MaxOutputs = 3;
  M.Caps.ValueStackSlots = 7;
  M.Caps.DecodedAttributes = {"Normal", "AO"};
  M.Caps.OutputsEntry = "entry_fn";
  M.ScratchFloat4PerHit = 5;
  M.StackSlots = 9;
  M.StackLimit = 40;
  M.Spill = true;
  M.ValueStack = "global";
  M.MaxOutputs = 3;
  M.ArgsBinSize = 4096;
  M.ProgramWords = 12;
  M.RecordsOffset = 48;
  M.Attributes = {"WorldPos", "AO"};
  M.Settings = {"Time"};
  M.Images = {{"img", "/i/a.png", 0, ""}};
  FunctionLayout F;
  F.Id = 2;
  F.Name = "noise";
  F.Renamed = "texcc_fn_noise";
  F.File = "/src/noise.cl";
  F.Return = "float3";
  F.BlockSize = 32;
  // The parameter table's row of p (frontend::parameterDocs); n has none.
  F.Params = {{"p", "float3", 16, 16, 0,
               {"(0.7, 0.3, 0.2)", {0.7, 0.3, 0.2}, "0..1", 0.0, 1.0, "a colour"}},
              {"n", "int", 4, 4, 16, {}}};
  F.Attributes = {"Normal"};
  F.Settings = {"Frame"};
  F.Cost = 17;
  F.HasHoisted = true;
  F.Hoisted = {{"h", "float", 4, 20}};
  F.HoistedFrom = {"n"};
  M.Functions = {F};
  QuickenedLayout Q;
  Q.Opcode = 9;
  Q.Function = "noise";
  Q.Sources = {"attr:Normal", "int:3"};
  M.Quickened = {Q};
  NodeLayout N;
  N.Index = 0;
  N.Id = "n0";
  N.Merged = {"n0b"};
  N.Fn = "noise";
  N.FnId = 2;
  N.RecordOffset = 48;
  N.RecordSize = 32;
  N.Copies = {80, 112};
  ArgLayout A1, A2, A3;
  A1.Name = "p";
  A1.Src = ArgLayout::Source::Attribute;
  A1.Attr = "Normal";
  A1.Broadcast = true;
  A1.Offset = 0;
  A2.Name = "n";
  A2.Src = ArgLayout::Source::Constant;
  A2.IntValue = true;
  A2.Value = {3};
  A2.Bake = true;
  A2.Offset = 16;
  A3.Name = "tab";
  A3.Src = ArgLayout::Source::Constant;
  A3.IsArray = true;
  A3.ArrayOffset = 256;
  A3.ArrayCount = 2;
  A3.Value = {0.25, 0.1};
  A3.Image = "img";
  A3.Offset = 20;
  N.Args = {A1, A2, A3};
  NodeLayout N1;
  N1.Index = 1;
  N1.Id = "n1";
  N1.Fn = "noise";
  ArgLayout A4;
  A4.Name = "p";
  A4.Src = ArgLayout::Source::Node;
  A4.Node = 0;
  N1.Args = {A4};
  M.Nodes = {N, N1};
  M.WavefrontOrder = {0, 1};
  MaterialLayout Mat;
  Mat.Name = "red";
  Mat.Index = 1;
  Mat.ProgramWordOffset = 4;
  Mat.ProgramInstructions = 2;
  Mat.ProgramStackSlots = 3;
  Mat.Outputs = {{1, 2, "float3"}};
  Mat.Surface.Type = "blend";
  Bsdf Diffuse;
  Diffuse.Type = "diffuse";
  Diffuse.Inputs = {{"color", {true, 0, {}}}, {"roughness", {false, -1, {0.5}}}};
  Mat.Surface.Inputs = {{"mask", {false, -1, {0.3}}}};
  Mat.Surface.Children = {{"a", Diffuse}, {"b", Diffuse}};
  M.Materials = {Mat};
  return M;
}

Manifest read(const std::string &Text, ManifestError *Err = nullptr) {
  Manifest M;
  ManifestError E;
  bool Ok = readManifest(Text, "layout.json", M, E);
  if (Err)
    *Err = E;
  else
    EXPECT_TRUE(Ok) << E.str();
  return M;
}

std::string readError(const std::string &Text) {
  Manifest M;
  ManifestError E;
  EXPECT_FALSE(readManifest(Text, "dir/layout.json", M, E));
  return E.str();
}

} // namespace

TEST(Manifest, RoundTripEveryField) {
  const Manifest M = everyField();
  const std::string Text = writeManifest(M);
  const Manifest Back = read(Text);
  EXPECT_TRUE(Back == M) << Text;
  EXPECT_EQ(writeManifest(Back), Text);
  // Each part on its own, so a failure says which.
  EXPECT_TRUE(Back.Kernel == M.Kernel);
  EXPECT_TRUE(Back.Caps == M.Caps);
  EXPECT_TRUE(Back.Functions == M.Functions);
  EXPECT_TRUE(Back.Nodes == M.Nodes);
  EXPECT_TRUE(Back.Materials == M.Materials);
  EXPECT_TRUE(Back.Quickened == M.Quickened);
  EXPECT_TRUE(Back.HasCapabilities && Back.HasCompileOptions);
}

TEST(Manifest, ProgramsByRole) {
  // layout.json keeps its keys (kernel.source, interpFallback, quick.programs); the typed
  // manifest reads them as programs by role.
  Manifest M = everyField();
  M.Kernel.QuickPrograms = {{"proctex.quick.f.cl", {"texcc_wf_0", "texcc_wf_3"}},
                            {"proctex.quick.outputs.cl", {"texcc_wf_outputs"}}};
  M.Kernel.QuickLaunches = {{"texcc_wf_0", 0}, {"texcc_wf_3", 3}};
  M.Kernel.QuickEntry = "texcc_wf_outputs";
  const Manifest Back = read(writeManifest(M));
  using R = ProgramRole;
  const std::vector<RoleProgram> Want{
      {R::Primary, "k.cl", {"texcc_wf_0", "texcc_wf_3", "entry_fn", "texcc_uniforms"}},
      {R::Fallback, "proctex.interp.cl", {"entry_fn"}},
      {R::Quick, "proctex.quick.f.cl", {"texcc_wf_0", "texcc_wf_3"}},
      {R::Quick, "proctex.quick.outputs.cl", {"texcc_wf_outputs"}}};
  EXPECT_TRUE(Back.Kernel.programs() == Want);
  EXPECT_EQ(Back.Kernel.programs(R::Quick).size(), 2u);
  ASSERT_EQ(Back.Kernel.programs(R::Fallback).size(), 1u);
  EXPECT_EQ(Back.Kernel.programs(R::Fallback)[0].Source, "proctex.interp.cl");
  EXPECT_STREQ(programRoleName(R::Primary), "primary");
  EXPECT_STREQ(programRoleName(R::Fallback), "fallback");
  EXPECT_STREQ(programRoleName(R::Quick), "quick");
  // interp mode: one program, no fallback, no quick tier.
  KernelEntries Interp;
  const std::vector<RoleProgram> One{{R::Primary, "proctex.cl", {"texcc_proctex"}}};
  EXPECT_TRUE(Interp.programs() == One);
}

TEST(Manifest, LegacyQuickenedEntriesRoundTrip) {
  // A layout of a texcc before 2026-12, read and written again (texcc-eval, the graph editor):
  // its superinstructions and its quickened entries with "second" are kept.
  Manifest M = everyField();
  QuickenedLayout Q;
  Q.Opcode = 9;
  Q.Function = "lite";
  Q.Legacy = true;
  Q.Second = "pair";
  M.Quickened.push_back(Q);
  M.LegacySuperinstructions = {9, 12};
  const std::string Text = writeManifest(M);
  EXPECT_NE(Text.find(R"("second": "pair")"), std::string::npos) << Text;
  EXPECT_NE(Text.find(R"("superinstructions": [)"), std::string::npos) << Text;
  const Manifest Back = read(Text);
  EXPECT_TRUE(Back.Quickened == M.Quickened) << Text;
  EXPECT_EQ(Back.LegacySuperinstructions, M.LegacySuperinstructions);
  EXPECT_EQ(writeManifest(Back), Text);
}

TEST(Manifest, SyntaxErrorHasLineAndColumn) {
  EXPECT_EQ(readError("{\n  \"texcc\": 1,\n  \"mode\": ]\n}").substr(0, 21), "dir/layout.json:3:11:");
}

TEST(Manifest, FieldErrorNamesPointerAndPosition) {
  std::string Text = writeManifest(everyField());
  // A mistyped field: its pointer and where its value starts.
  std::string Bad = Text;
  Bad.replace(Bad.find("\"entry\": \"entry_fn\""), 19, "\"entry\": 5");
  EXPECT_EQ(readError(Bad), "dir/layout.json:13:14: /kernel/entry: expected a string, not number");
  // A missing field: the object it is missing from.
  std::string NoName = Text;
  size_t At = NoName.find("\"name\": \"red\",");
  NoName.erase(At, std::string("\"name\": \"red\",").size());
  std::string E = readError(NoName);
  EXPECT_NE(E.find(": /materials/0: missing \"name\""), std::string::npos) << E;
  EXPECT_EQ(E.rfind("dir/layout.json:", 0), 0u) << E;
  // A wrong version.
  std::string V2 = Text;
  V2.replace(V2.find("\"texcc\": 1"), 10, "\"texcc\": 2");
  EXPECT_EQ(readError(V2),
            "dir/layout.json:2:12: /texcc: layout version 2, expected 1 (run this texcc again)");
  // An argument of an unknown source.
  std::string Src = Text;
  Src.replace(Src.find("\"source\": \"node\""), 16, "\"source\": \"wire\"");
  E = readError(Src);
  EXPECT_NE(E.find("/nodes/1/args/0/source: expected \"attr\", \"node\" or \"const\""),
            std::string::npos)
      << E;
  // ... at the value's line and column: the scanner passed node 0 and the members before.
  const size_t At2 = Src.find("\"wire\"");
  const size_t LineStart = Src.rfind('\n', At2) + 1;
  const std::string Where = "dir/layout.json:" +
                            std::to_string(1 + std::count(Src.begin(), Src.begin() + At2, '\n')) +
                            ":" + std::to_string(At2 - LineStart + 1) + ": ";
  EXPECT_EQ(E.rfind(Where, 0), 0u) << E << " (expected " << Where << ")";
}

TEST(Manifest, KernelLayoutWithoutCapabilitiesIsRefused) {
  // A layout of texcc before the capabilities block: no table guesses them from the mode.
  const char *Old = R"({"texcc": 1, "mode": "interp", "maxOutputs": 2,
                        "kernel": {"source": "proctex.cl", "entry": "texcc_proctex"},
                        "materials": []})";
  std::string E = readError(Old);
  EXPECT_NE(E.find("/capabilities: missing: this layout.json was written by an older texcc"),
            std::string::npos)
      << E;
  // A shape layout must name its fallback kernel.
  E = readError(R"({"texcc": 1, "mode": "shape", "kernel": {}, "materials": [],
                     "capabilities": {"interpFallback": true}})");
  EXPECT_NE(E.find("/kernel/interpFallback: missing"), std::string::npos) << E;
}

TEST(Attributes, OneTable) {
  EXPECT_EQ(NumAttributes, 10u);
  EXPECT_EQ(attributeId("WorldPos"), 0);
  EXPECT_EQ(attributeId("ViewDir"), 7);
  EXPECT_EQ(attributeId("TangentSign"), 8);
  EXPECT_EQ(attributeId("Backfacing"), 9);
  EXPECT_EQ(attributeId("viewdir"), -1);
  EXPECT_STREQ(attributeName(6), "AO");
  EXPECT_EQ(AttributeTable[5].Components, 2u); // TexCoord0
}
