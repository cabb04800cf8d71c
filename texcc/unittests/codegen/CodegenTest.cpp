// The generators on hand-built compiled graphs: what each mode emits, the host rewrite of
// vector literals, layout.json's keys.
#include "texcc/Codegen/Codegen.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace texcc;
using namespace texcc::graph;
using namespace texcc::codegen;

namespace {

CompiledArg attrArg(const std::string &Name, BaseType B, int AttrId) {
  CompiledArg A;
  A.Name = Name;
  A.Type.Base = B;
  A.Src = CompiledArg::Source::Attribute;
  A.AttrId = AttrId;
  return A;
}

CompiledArg constArg(const std::string &Name, BaseType B, std::vector<double> Values,
                     uint32_t BlockOffset) {
  CompiledArg A;
  A.Name = Name;
  A.Type.Base = B;
  A.Values = std::move(Values);
  A.BlockOffset = BlockOffset;
  return A;
}

CompiledArg nodeArg(const std::string &Name, BaseType B, unsigned Node, bool Broadcast) {
  CompiledArg A;
  A.Name = Name;
  A.Type.Base = B;
  A.Src = CompiledArg::Source::Node;
  A.NodeIndex = Node;
  A.Broadcast = Broadcast;
  return A;
}

/// Two nodes: n = noise(ObjectPos, 0.5) (float), c = tint(n broadcast to float3) (float3);
/// material 0 outputs both, material 1 has no texture outputs.
CompiledGraph twoNodeGraph() {
  CompiledGraph CG;
  CG.GraphPath = "/abs/g.json";
  FunctionSignature Noise{"noise", "t_noise", "t.cl", BaseType::Float,
                          {{"p", {BaseType::Float3, false}}, {"s", {BaseType::Float, false}}},
                          {},
                          {},
                          0,
                          {},
                          {}};
  FunctionSignature Tint{"tint", "t_tint", "t.cl", BaseType::Float3,
                         {{"c", {BaseType::Float3, false}}},
                         {},
                         {},
                         0,
                         {},
                         {}};
  CG.Signatures = {{"noise", Noise}, {"tint", Tint}};
  CG.FunctionsById = {"noise", "tint"};
  CompiledNode N0;
  N0.Id = "n";
  N0.Fn = "noise";
  N0.FnId = 0;
  N0.Return = BaseType::Float;
  N0.Args = {attrArg("p", BaseType::Float3, 1), constArg("s", BaseType::Float, {0.5}, 16)};
  N0.RecordOffset = 48;
  N0.RecordSize = 48;
  CompiledNode N1;
  N1.Id = "c-1";
  N1.Fn = "tint";
  N1.FnId = 1;
  N1.Return = BaseType::Float3;
  N1.Args = {nodeArg("c", BaseType::Float3, 0, true)};
  N1.RecordOffset = 96;
  N1.RecordSize = 32;
  CG.Nodes = {N0, N1};
  CompiledMaterial M0;
  M0.Name = "painted";
  M0.Index = 0;
  M0.Program = {{0, 0, 48}, {1, 1, 96}};
  M0.Outputs = {{0, 0, BaseType::Float}, {1, 1, BaseType::Float3}};
  M0.StackSlots = 2;
  CompiledMaterial M1;
  M1.Name = "plain";
  M1.Index = 1;
  M1.ProgramWordOffset = 10;
  CG.Materials = {M0, M1};
  CG.StackSlots = 2;
  CG.StackLimit = 32;
  CG.MaxOutputs = 2;
  CG.Attributes = {"ObjectPos"};
  CG.WavefrontOrder = {0, 1};
  CG.ProgramWords = 12;
  CG.RecordsOffset = 48;
  CG.ArgsBin.assign(128, 0);
  return CG;
}

CodegenOptions options(Mode M, Target T = Target::OpenCL) {
  CodegenOptions Opts;
  Opts.EvalMode = M;
  Opts.Tgt = T;
  Opts.GraphPath = "/abs/g.json";
  Opts.UserCode = "float t_noise(TEXCC_CTX_PARAM, float3 p, float s) { return p.x * s; }\n"
                  "float3 t_tint(TEXCC_CTX_PARAM, float3 c) { return c * (float3)(1.0f, 0.5f, "
                  "0.25f); }\n";
  return Opts;
}

bool contains(const std::string &Text, const std::string &Part) {
  return Text.find(Part) != std::string::npos;
}

TEST(CodegenModes, ParsesTheFourModes) {
  EXPECT_EQ(parseMode("interp"), Mode::Interp);
  EXPECT_EQ(parseMode("inline"), Mode::Inline);
  EXPECT_EQ(parseMode("wavefront"), Mode::Wavefront);
  EXPECT_EQ(parseMode("shape"), Mode::Shape);
  EXPECT_FALSE(parseMode("Shape").has_value());
  EXPECT_EQ(parseTarget("host"), Target::Host);
  EXPECT_FALSE(parseTarget("cuda").has_value());
}

TEST(CodegenInterp, DefinesTheMacrosAndOneCasePerFunction) {
  std::string K = generateKernel(twoNodeGraph(), options(Mode::Interp));
  EXPECT_TRUE(contains(K, "#define TEXCC_STACK_SLOTS 2\n"));
  EXPECT_TRUE(contains(K, "#define TEXCC_MAX_OUTPUTS 2\n"));
  EXPECT_TRUE(contains(K, "#define TEXCC_NUM_MATERIALS 2\n"));
  EXPECT_TRUE(contains(K, "#define TEXCC_SPILL 0\n"));
  EXPECT_TRUE(contains(K, abiHeaderText()));
  EXPECT_TRUE(contains(K, deviceHeaderText()));
  EXPECT_TRUE(contains(K, "case 0u: /* float noise(float3 p, float s), t.cl */"));
  EXPECT_TRUE(contains(K, "case 1u: /* float3 tint(float3 c), t.cl */"));
  // Source words at rec + p; the parameter block starts after 16 bytes of source words.
  EXPECT_TRUE(contains(K, "TEXCC_ARG(0u, rec + 4u, 3u).xyz"));
  EXPECT_TRUE(contains(K, "TEXCC_ARG(1u, rec + 8u, 1u).x"));
  EXPECT_TRUE(contains(K, "float4 stack[TEXCC_STACK_SLOTS];"));
  EXPECT_TRUE(contains(K, "__kernel void texcc_proctex("));
}

TEST(CodegenInterp, SpillKeepsTheStackInScratch) {
  CompiledGraph CG = twoNodeGraph();
  CG.StackLimit = 1;
  CG.Spill = true;
  std::string K = generateKernel(CG, options(Mode::Interp));
  EXPECT_TRUE(contains(K, "#define TEXCC_SPILL 1\n"));
  EXPECT_TRUE(contains(K, "#define TEXCC_SLOT(s) scratch[(s) * (uint)numHits + (uint)gid]"));
  EXPECT_FALSE(contains(K, "float4 stack[TEXCC_STACK_SLOTS];"));
  nlohmann::json L = nlohmann::json::parse(generateLayout(CG, options(Mode::Interp)));
  EXPECT_EQ(L["scratchFloat4PerHit"], 2);
}

TEST(CodegenInline, BakesConstantsAndCallsChildrenIntoLocals) {
  std::string K = generateKernel(twoNodeGraph(), options(Mode::Inline));
  EXPECT_TRUE(contains(K, "const float v0_n = t_noise(texcc_ctx, "
                          "texcc_attr_ObjectPos(texcc_ctx), 0.5f);"));
  EXPECT_TRUE(contains(K, "const float3 v1_c_1 = t_tint(texcc_ctx, (float3)(v0_n));"));
  EXPECT_TRUE(contains(K, "out[1] = (float4)(v1_c_1, 0.0f);"));
  EXPECT_FALSE(contains(K, "texcc_material_1")); // no texture outputs
  EXPECT_FALSE(contains(K, "texcc_arg("));        // no interpreter
}

TEST(CodegenWavefront, OneKernelPerNodeAndTheOutputsKernel) {
  CompiledGraph CG = twoNodeGraph();
  std::string K = generateKernel(CG, options(Mode::Wavefront));
  EXPECT_TRUE(contains(K, "__kernel void texcc_wf_0("));
  EXPECT_TRUE(contains(K, "__kernel void texcc_wf_1("));
  EXPECT_TRUE(contains(K, "__kernel void texcc_wf_outputs("));
  // Only 'painted' runs the nodes: each node kernel tests for it, 'plain' returns.
  EXPECT_TRUE(contains(K, "static inline bool texcc_wf_uses_0(int mat) {"));
  EXPECT_TRUE(contains(K, "static inline bool texcc_wf_uses_1(int mat) {"));
  EXPECT_TRUE(contains(K, "case 0: /* 'painted' */"));
  EXPECT_FALSE(contains(K, "/* 1 'plain' */"));
  EXPECT_FALSE(contains(K, "case 1: /* 'plain' */"));
  // The constant comes from the record's parameter block: (48 + 16 + 16) / 4 = word 20.
  EXPECT_TRUE(contains(K, "as_float(fakeStack[20u])"));
  EXPECT_TRUE(contains(K, "(float3)(scratch[0u * (uint)numHits + (uint)gid].x)"));
  nlohmann::json L = nlohmann::json::parse(generateLayout(CG, options(Mode::Wavefront)));
  EXPECT_EQ(L["kernel"]["entry"], "texcc_wf_outputs");
  ASSERT_EQ(L["kernel"]["launches"].size(), 2u);
  EXPECT_EQ(L["kernel"]["launches"][1]["kernel"], "texcc_wf_1");
  EXPECT_EQ(L["scratchFloat4PerHit"], 2);
}

TEST(CodegenHost, EmitsTheCEntryAndRewritesVectorLiterals) {
  std::string K = generateKernel(twoNodeGraph(), options(Mode::Interp, Target::Host));
  EXPECT_TRUE(contains(K, hostPreludeText()));
  EXPECT_FALSE(contains(K, deviceHeaderText()));
  EXPECT_TRUE(contains(K, "texcc_make_float3(1.0f, 0.5f, 0.25f)"));
  EXPECT_TRUE(contains(K, "extern \"C\" int texcc_host_evaluate(int material,"));
  EXPECT_TRUE(contains(K, "const float3 v1_c_1 = t_tint(texcc_ctx, float3(v0_n));"));
  EXPECT_EQ(kernelFileName(Target::Host), "proctex.cpp");
}

TEST(CodegenHost, RewritesOnlyVectorLiteralsOutsideCommentsAndStrings) {
  EXPECT_EQ(rewriteVectorLiteralsForHost("x = (float3)(a, b, c);"),
            "x = texcc_make_float3(a, b, c);");
  EXPECT_EQ(rewriteVectorLiteralsForHost("( int2 ) (1, 2)"), "texcc_make_int2(1, 2)");
  EXPECT_EQ(rewriteVectorLiteralsForHost("(float)(x) + (float3)x"), "(float)(x) + (float3)x");
  EXPECT_EQ(rewriteVectorLiteralsForHost("/* (float3)(1) */ // (float2)(1)\n\"(float4)(\""),
            "/* (float3)(1) */ // (float2)(1)\n\"(float4)(\"");
}

TEST(CodegenLayout, AddsModeTargetGraphAndKernelFirst) {
  nlohmann::ordered_json L =
      nlohmann::ordered_json::parse(generateLayout(twoNodeGraph(), options(Mode::Inline)));
  std::vector<std::string> Keys;
  for (auto It = L.begin(); It != L.end() && Keys.size() < 8; ++It)
    Keys.push_back(It.key());
  EXPECT_EQ(Keys, (std::vector<std::string>{"texcc", "mode", "target", "graph", "compileOptions",
                                            "kernel", "capabilities", "scratchFloat4PerHit"}));
  EXPECT_EQ(L["mode"], "inline");
  // The inline backend's capabilities: values are literals, every edit regenerates.
  EXPECT_EQ(L["capabilities"]["reEncodes"], false);
  EXPECT_EQ(L["capabilities"]["outputsEntry"], "texcc_proctex");
  EXPECT_EQ(L["kernel"]["entry"], "texcc_proctex");
  EXPECT_EQ(L["graph"], "/abs/g.json");
}

TEST(CodegenGraphDot, ShowsNodesEdgesAndPrograms) {
  std::string D = generateGraphDot(twoNodeGraph());
  EXPECT_TRUE(contains(D, "digraph texcc {"));
  EXPECT_TRUE(contains(D, "n0 -> n1:a0;"));
  EXPECT_TRUE(contains(D, "m0 -> n1 [style=dashed, label=\"#1 -> slot 1\"];"));
  EXPECT_TRUE(contains(D, "(broadcast)"));
}

TEST(CodegenOutputs, NamesTheFilesOfOneRun) {
  std::vector<OutputFile> Files = generateOutputs(twoNodeGraph(), options(Mode::Interp), true);
  ASSERT_EQ(Files.size(), 4u);
  EXPECT_EQ(Files[0].Name, "proctex.cl");
  EXPECT_EQ(Files[1].Name, "layout.json");
  EXPECT_EQ(Files[2].Name, "args.bin");
  EXPECT_EQ(Files[2].Contents.size(), 128u);
  EXPECT_EQ(Files[3].Name, "graph.dot");
}

} // namespace
