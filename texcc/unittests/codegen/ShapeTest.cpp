// Shape mode: which materials share a shape (graph::groupShapes on graphs compiled by the graph
// library), what the kernel emits for them, the interp fallback and layout.json's shapes.
#include "texcc/Codegen/Codegen.h"
#include "texcc/Graph/Compile.h"
#include "texcc/Graph/Graph.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

using namespace texcc::graph;
using namespace texcc::codegen;

namespace {

/// wave(float3 p, float s, int mode) -> float; tint(float t, float3 c) -> float3.
SignatureMap signatures() {
  FunctionSignature Wave{"wave", "t_wave", "t.cl", BaseType::Float,
                         {{"p", {BaseType::Float3, false}},
                          {"s", {BaseType::Float, false}},
                          {"mode", {BaseType::Int, false}}},
                         {},
                         {},
                         0,
                         {},
                         {}};
  FunctionSignature Tint{"tint", "t_tint", "t.cl", BaseType::Float3,
                         {{"t", {BaseType::Float, false}}, {"c", {BaseType::Float3, false}}},
                         {},
                         {},
                         0,
                         {},
                         {}};
  return {{"wave", Wave}, {"tint", Tint}};
}

/// Materials: a and b (same shape, other constants), c (tint reads an attribute instead of a
/// node: another shape), d (a's shape, but its wave's baked mode differs), e (no texture).
const char *GraphText = R"({
  "texcc": 1,
  "nodes": [
    { "id": "wa", "fn": "wave", "args": { "p": { "attr": "ObjectPos" }, "s": 1.0, "mode": 0 } },
    { "id": "ta", "fn": "tint", "args": { "t": { "node": "wa" }, "c": [1, 0, 0] } },
    { "id": "wb", "fn": "wave", "args": { "p": { "attr": "ObjectPos" }, "s": 2.0, "mode": 0 } },
    { "id": "tb", "fn": "tint", "args": { "t": { "node": "wb" }, "c": [0, 1, 0] } },
    { "id": "tc", "fn": "tint", "args": { "t": { "attr": "AO" }, "c": [0, 0, 1] } },
    { "id": "wd", "fn": "wave", "args": { "p": { "attr": "ObjectPos" }, "s": 3.0,
                                           "mode": { "value": 1, "bake": true } } },
    { "id": "td", "fn": "tint", "args": { "t": { "node": "wd" }, "c": [1, 1, 0] } }
  ],
  "materials": {
    "a": { "bsdf": "diffuse", "color": { "node": "ta" } },
    "b": { "bsdf": "diffuse", "color": { "node": "tb" } },
    "c": { "bsdf": "diffuse", "color": { "node": "tc" } },
    "d": { "bsdf": "diffuse", "color": { "node": "td" } },
    "e": { "bsdf": "diffuse", "color": [0.5, 0.5, 0.5] }
  }
})";

CompiledGraph compile(const std::string &Text, const std::vector<std::string> &Bakes = {}) {
  DiagnosticSink Diags;
  std::optional<Graph> G = parseGraph("g.json", Text, Diags);
  EXPECT_TRUE(G.has_value());
  for (const std::string &B : Bakes) {
    std::string Error;
    EXPECT_TRUE(markBaked(*G, B, Error)) << Error;
  }
  std::optional<CompiledGraph> CG = compileGraph(*G, signatures(), CompileOptions(), Diags);
  EXPECT_TRUE(CG.has_value());
  return CG ? *CG : CompiledGraph();
}

std::vector<std::vector<unsigned>> groups(const CompiledGraph &CG) {
  std::vector<std::vector<unsigned>> G;
  for (const MaterialShape &S : groupShapes(CG))
    G.push_back(S.Materials);
  return G;
}

size_t count(const std::string &Text, const std::string &Part) {
  size_t N = 0;
  for (size_t At = Text.find(Part); At != std::string::npos; At = Text.find(Part, At + 1))
    ++N;
  return N;
}

TEST(ShapeGrouping, ConstantsDoNotSplitAShapeWiringAndBakedValuesDo) {
  CompiledGraph CG = compile(GraphText);
  EXPECT_EQ(groups(CG), (std::vector<std::vector<unsigned>>{{0, 1}, {2}, {3}}));
  EXPECT_EQ(shapeKey(CG, CG.Materials[0]), shapeKey(CG, CG.Materials[1]));
  EXPECT_NE(shapeKey(CG, CG.Materials[0]), shapeKey(CG, CG.Materials[3]));
}

TEST(ShapeGrouping, EqualBakedValuesShareAShape) {
  // --bake wa.mode with mode 0 in a and b: still one shape, and d (mode 1) another.
  CompiledGraph CG = compile(GraphText, {"wa.mode", "wb.mode"});
  EXPECT_EQ(groups(CG), (std::vector<std::vector<unsigned>>{{0, 1}, {2}, {3}}));
  // Baking only a's mode splits a from b.
  CompiledGraph One = compile(GraphText, {"wa.mode"});
  EXPECT_EQ(groups(One), (std::vector<std::vector<unsigned>>{{0}, {1}, {2}, {3}}));
}

TEST(ShapeGrouping, MarkBakedReportsBadTargets) {
  DiagnosticSink Diags;
  std::optional<Graph> G = parseGraph("g.json", GraphText, Diags);
  ASSERT_TRUE(G.has_value());
  std::string Error;
  EXPECT_FALSE(markBaked(*G, "wz.mode", Error));
  EXPECT_EQ(Error, "--bake 'wz.mode': unknown node 'wz'; did you mean 'wa'?");
  EXPECT_FALSE(markBaked(*G, "wa.mod", Error));
  EXPECT_EQ(Error, "--bake 'wa.mod': node 'wa' has no argument 'mod'; did you mean 'mode'?");
  EXPECT_FALSE(markBaked(*G, "wa.p", Error));
  EXPECT_EQ(Error, "--bake 'wa.p': argument 'p' of node 'wa' is not a number or a vector; only "
                   "constants can be baked");
  EXPECT_FALSE(markBaked(*G, "wa", Error));
  EXPECT_EQ(Error, "--bake 'wa': expected NODE.ARG");
}

CodegenOptions shapeOptions() {
  CodegenOptions Opts;
  Opts.EvalMode = Mode::Shape;
  Opts.GraphPath = "/abs/g.json";
  return Opts;
}

TEST(ShapeKernel, OneBodyPerShapeAndACaseForEveryMaterial) {
  std::string K = generateKernel(compile(GraphText), shapeOptions());
  EXPECT_EQ(count(K, "static inline void texcc_shape_"), 3u);
  // a and b share body 0, each with its own program offset (a's program: 2 + 3 * 2 + 1 words).
  EXPECT_EQ(count(K, "texcc_shape_0(texcc_ctx, fakeStack, "), 2u);
  EXPECT_NE(K.find("  case 0: /* 'a' */\n    texcc_shape_0(texcc_ctx, fakeStack, 0u, out);\n"
                   "    break;\n  case 1: /* 'b' */\n    texcc_shape_0(texcc_ctx, fakeStack, 9u, out);"),
            std::string::npos);
  // The baked mode of d (shape 2) is a literal; a's and b's mode is read from their records.
  EXPECT_EQ(count(K, "as_float(fakeStack[r0 + 8u]), 1);"), 1u);
  EXPECT_EQ(count(K, "as_int(fakeStack[r0 + 9u])"), 1u);
  EXPECT_NE(K.find("#pragma OPENCL FP_CONTRACT OFF"), std::string::npos);
  EXPECT_EQ(K.find("case 4:"), std::string::npos);
}

TEST(ShapeKernel, WritesTheInterpKernelAsFallbackAndListsTheShapes) {
  CompiledGraph CG = compile(GraphText);
  std::vector<OutputFile> Files = generateOutputs(CG, shapeOptions(), false);
  // proctex.cl, the fallback, the quick tier's program of each of the 2 live functions and of
  // the outputs kernel (docs/live.md), layout.json, args.bin.
  ASSERT_EQ(Files.size(), 7u);
  EXPECT_EQ(Files[1].Name, InterpFallbackFile);
  CodegenOptions Interp = shapeOptions();
  Interp.EvalMode = Mode::Interp;
  EXPECT_EQ(Files[1].Contents, generateKernel(CG, Interp));
  for (size_t I : {2u, 3u}) {
    EXPECT_EQ(Files[I].Name.rfind("proctex.quick.fn.", 0), 0u) << Files[I].Name;
    EXPECT_NE(Files[I].Contents.find("__kernel void texcc_wf_"), std::string::npos);
    EXPECT_EQ(Files[I].Contents.find("__kernel void texcc_wf_outputs"), std::string::npos);
  }
  EXPECT_EQ(Files[4].Name, "proctex.quick.outputs.cl");
  EXPECT_EQ(count(Files[4].Contents, "__kernel void "), 1u);
  nlohmann::json L = nlohmann::json::parse(Files[5].Contents);
  EXPECT_EQ(L["kernel"]["quick"]["programs"].size(), 3u);
  EXPECT_EQ(L["kernel"]["quick"]["entry"], "texcc_wf_outputs");
  EXPECT_EQ(L["mode"], "shape");
  EXPECT_EQ(L["kernel"]["interpFallback"], "proctex.interp.cl");
  EXPECT_EQ(L["kernel"]["shapes"].dump(),
            R"([{"id":0,"materials":[0,1]},{"id":1,"materials":[2]},{"id":2,"materials":[3]}])");
}

} // namespace

namespace {

std::string withValue(std::string Text, const std::string &From, const std::string &To) {
  size_t At = Text.find(From);
  EXPECT_NE(At, std::string::npos) << From;
  return At == std::string::npos ? Text : Text.replace(At, From.size(), To);
}

} // namespace

TEST(ShapeHash, SameForOtherConstantsDifferentForOtherShapes) {
  const std::string Base = shapeHash(compile(GraphText));
  EXPECT_EQ(Base.size(), 16u);
  // An unbaked constant: the same shapes, the same kernel.
  EXPECT_EQ(shapeHash(compile(withValue(GraphText, "\"s\": 2.0", "\"s\": 7.5"))), Base);
  // A baked value is part of the shape.
  EXPECT_NE(shapeHash(compile(withValue(GraphText, "\"value\": 1, \"bake\"",
                                        "\"value\": 2, \"bake\""))),
            Base);
  // Wiring: b's tint reading an attribute instead of its wave.
  EXPECT_NE(shapeHash(compile(withValue(GraphText, "\"t\": { \"node\": \"wb\" }",
                                        "\"t\": { \"attr\": \"AO\" }"))),
            Base);
  // Baking a's scale makes a's program another shape than b's.
  EXPECT_NE(shapeHash(compile(GraphText, {"wa.s"})), Base);
}
