// Validation against the signatures: one test per diagnostic.

#include "GraphTestUtil.h"

using namespace texcc::graph;
using namespace texcc::graph::test;

namespace {

std::string oneNode(const std::string &Node, const std::string &Extra = "") {
  return "{\"texcc\": 1, \"images\": {\"brick\": \"b.png\"}, \"nodes\": [\n" + Node + Extra +
         "],\n\"materials\": {\"m\": {\"bsdf\": \"diffuse\", \"color\": {\"node\": \"a\"}}}}";
}

TEST(Validate, UnknownFunctionSuggests) {
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "fbm", "args": {}})")),
            "g.json:2:19: error: node 'a': unknown function 'fbm'; did you mean 'fbm3'? "
            "[/nodes/0/fn]\n");
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "zzzzzz", "args": {}})")),
            "g.json:2:19: error: node 'a': unknown function 'zzzzzz' [/nodes/0/fn]\n");
}

TEST(Validate, KnownHelperIsNotATexture) {
  DiagnosticSink D;
  auto G = parse(oneNode(R"({"id": "a", "fn": "hash", "args": {}})"), D);
  ASSERT_TRUE(G);
  CompileOptions Opts;
  Opts.KnownFunctions = {"hash"};
  EXPECT_FALSE(compileGraph(*G, stdSigs(), Opts, D));
  EXPECT_NE(text(D).find("node 'a': function 'hash' is not a texture function"),
            std::string::npos);
}

TEST(Validate, UnknownArgument) {
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "leaf", "args": {"x": 1, "xx": 2}})")),
            "g.json:2:44: error: node 'a': unknown argument 'xx' for 'leaf'; did you mean 'x'? "
            "[/nodes/0/args/xx]\n");
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "leaf", "args": {"x": 1, "scale": 2}})")),
            "g.json:2:44: error: node 'a': unknown argument 'scale' for 'leaf'; its "
            "parameters are 'x' [/nodes/0/args/scale]\n");
}

TEST(Validate, MissingArgument) {
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "add", "args": {"a": 1}})")),
            "g.json:2:1: error: node 'a': missing argument 'b' (float) of 'add' [/nodes/0]\n");
}

TEST(Validate, TypeMismatchSaysExpectedAndFound) {
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "ramp", "args": {"t": 0.5, "stops": 1,
  "count": 2}})")),
            "g.json:2:55: error: node 'a': argument 'stops' expects __global const float4*, "
            "got a number [/nodes/0/args/stops]\n");
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "ramp", "args": {"t": 0.5,
  "stops": [[0, 1, 2, 3], [0, 1, 2]], "count": 2}})")),
            "g.json:3:12: error: node 'a': argument 'stops' expects __global const float4*, "
            "got an array of 2 rows; row 1 has 3 numbers, not 4 [/nodes/0/args/stops]\n");
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "fbm3", "args": {"p": [1, 2],
  "scale": 1, "octaves": 2.5}})")),
            "g.json:2:41: error: node 'a': argument 'p' expects float3, got a vector of 2 "
            "numbers [1, 2] [/nodes/0/args/p]\n"
            "g.json:3:26: error: node 'a': argument 'octaves' expects int, got a number (2.5 "
            "is not an int) [/nodes/0/args/octaves]\n");
  // A node of the wrong type, an attribute of the wrong type.
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "add", "args": {"a": {"node": "b"},
  "b": {"attr": "Normal"}}},)", R"({"id": "b", "fn": "mix3", "args": {"a": 0, "b": 1, "t": 0}})")),
            "g.json:2:40: error: node 'a': argument 'a' expects float, got node 'b' of type "
            "float3 [/nodes/0/args/a]\n"
            "g.json:3:8: error: node 'a': argument 'b' expects float, got attribute 'Normal' "
            "of type float3 [/nodes/0/args/b]\n");
  // An image where a number is expected, a number where an image is expected.
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "image", "args": {"img": 0,
  "uv": {"image": "brick"}}})")),
            "g.json:2:44: error: node 'a': argument 'img' expects sam2D, got a number; bind an "
            "image with {\"image\": name} [/nodes/0/args/img]\n"
            "g.json:3:9: error: node 'a': argument 'uv' expects float2, got image 'brick' "
            "(sam2D) [/nodes/0/args/uv]\n");
}

TEST(Validate, BroadcastOfFloatIsAllowed) {
  CompiledGraph CG = resolved(R"({"texcc": 1, "nodes": [
    {"id": "s", "fn": "leaf", "args": {"x": 1}},
    {"id": "a", "fn": "mix3", "args": {"a": {"node": "s"}, "b": 0.5, "t": {"attr": "AO"}}},
    {"id": "b", "fn": "mix3", "args": {"a": {"attr": "AO"}, "b": [1, 2, 3], "t": 0}}],
    "materials": {"m": {"bsdf": "diffuse", "color": {"node": "a"}},
                  "n": {"bsdf": "diffuse", "color": {"node": "b"}}}})");
  ASSERT_EQ(CG.Nodes.size(), 3u);
  const CompiledNode &A = CG.Nodes[1];
  EXPECT_EQ(A.Args[0].Src, CompiledArg::Source::Node);
  EXPECT_TRUE(A.Args[0].Broadcast);
  EXPECT_EQ(A.Args[1].Values, (std::vector<double>{0.5, 0.5, 0.5}));
  EXPECT_FALSE(A.Args[1].Broadcast);
  EXPECT_FALSE(A.Args[2].Broadcast);
  EXPECT_TRUE(CG.Nodes[2].Args[0].Broadcast);
  EXPECT_EQ(CG.Nodes[2].Args[0].AttrId, attributeId("AO"));
}

TEST(Validate, CyclePrintsNodesInOrder) {
  EXPECT_EQ(errorsOf(R"({"texcc": 1, "nodes": [
  {"id": "a", "fn": "add", "args": {"a": {"node": "b"}, "b": 1}},
  {"id": "b", "fn": "add", "args": {"a": {"node": "c"}, "b": 1}},
  {"id": "c", "fn": "neg", "args": {"x": {"node": "a"}}}],
  "materials": {"m": {"bsdf": "emission", "color": 1, "strength": {"node": "a"}}}})"),
            "g.json:2:10: error: cycle in the node graph: 'a' -> 'b' -> 'c' -> 'a' "
            "[/nodes/0]\n");
  EXPECT_EQ(errorsOf(R"({"texcc": 1, "nodes": [
  {"id": "a", "fn": "add", "args": {"a": {"node": "a"}, "b": 1}}],
  "materials": {}})"),
            "g.json:2:10: error: cycle in the node graph: 'a' -> 'a' [/nodes/0]\n");
}

TEST(Validate, DanglingReference) {
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "neg", "args": {"x": {"node": "bb"}}},)",
                             R"({"id": "b", "fn": "leaf", "args": {"x": 1}})")),
            "g.json:2:40: error: node 'a': argument 'x' refers to unknown node 'bb'; did you "
            "mean 'b'? [/nodes/0/args/x]\n");
  EXPECT_EQ(errorsOf(R"({"texcc": 1, "materials": {"m": {"bsdf": "diffuse",
  "color": {"node": "nope"}}}})"),
            "g.json:2:12: error: material 'm': diffuse input 'color' refers to unknown node "
            "'nope' [/materials/m/color]\n");
}

TEST(Validate, UnknownImageAndAttribute) {
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "image", "args": {"img": {"image": "bric"},
  "uv": {"attr": "TexCoord"}}})")),
            "g.json:2:44: error: node 'a': unknown image 'bric'; did you mean 'brick'? "
            "[/nodes/0/args/img]\n"
            "g.json:3:9: error: node 'a': unknown attribute 'TexCoord'; did you mean "
            "'TexCoord0'? [/nodes/0/args/uv]\n");
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "neg", "args": {"x": {"attr": "Foo"}}})")),
            "g.json:2:40: error: node 'a': unknown attribute 'Foo'; the attributes are "
            "'WorldPos', 'ObjectPos', 'Normal', 'GeomNormal', 'Tangent', 'TexCoord0', 'AO', "
            "'ViewDir', 'TangentSign' or 'Backfacing' [/nodes/0/args/x]\n");
}

TEST(Validate, BsdfInputTypes) {
  std::string Nodes = R"("nodes": [{"id": "f", "fn": "leaf", "args": {"x": 1}},
  {"id": "v2", "fn": "uv", "args": {"s": 1}}, {"id": "c3", "fn": "mix3", "args": {"a": 0,
  "b": 1, "t": 0}}, {"id": "c4", "fn": "tint", "args": {"c": 1}}])";
  auto Mat = [&](const std::string &M) {
    return "{\"texcc\": 1, " + Nodes + ",\n\"materials\": {\"m\": " + M + "}}";
  };
  // float, float3 and float4 (.xyz) are colors; float2 is not.
  CompiledGraph CG = resolved(Mat(R"({"bsdf": "blend", "mask": {"node": "f"},
    "a": {"bsdf": "diffuse", "color": {"node": "c4"}},
    "b": {"bsdf": "glossy", "color": {"node": "f"}, "roughness": {"node": "f"}}})"));
  ASSERT_EQ(CG.Materials.size(), 1u);
  EXPECT_EQ(CG.Materials[0].Outputs.size(), 2u); // f once, c4
  EXPECT_EQ(errorsOf(Mat(R"({"bsdf": "diffuse", "color": {"node": "v2"}})")),
            "g.json:4:49: error: material 'm': diffuse input 'color' expects a color (float3, "
            "float4 or float), got node 'v2' of type float2 [/materials/m/color]\n");
  EXPECT_EQ(errorsOf(Mat(R"({"bsdf": "glossy", "color": 1, "roughness": {"node": "c3"}})")),
            "g.json:4:64: error: material 'm': glossy input 'roughness' expects float, got "
            "node 'c3' of type float3 [/materials/m/roughness]\n");
  EXPECT_EQ(errorsOf(Mat(R"({"bsdf": "emission", "color": [1, 2], "strength": [1, 2, 3]})")),
            "g.json:4:50: error: material 'm': emission input 'color' expects a color "
            "(float3, float4 or float), got [1, 2] [/materials/m/color]\n"
            "g.json:4:70: error: material 'm': emission input 'strength' expects float, got "
            "[1, 2, 3] [/materials/m/strength]\n");
}

TEST(Validate, BsdfConstantsAreNormalized) {
  CompiledGraph CG = resolved(R"({"texcc": 1, "materials": {
    "a": {"bsdf": "diffuse", "color": 0.5},
    "b": {"bsdf": "mirror", "color": [1, 0.5, 0.25, 9]}}})");
  ASSERT_EQ(CG.Materials.size(), 2u);
  EXPECT_EQ(CG.Materials[0].Bsdf.Inputs[0].Constant, (std::vector<double>{0.5, 0.5, 0.5}));
  EXPECT_EQ(CG.Materials[1].Bsdf.Inputs[0].Constant, (std::vector<double>{1, 0.5, 0.25}));
}

TEST(Validate, UnusedNodeWarns) {
  DiagnosticSink D;
  auto G = parse(oneNode(R"({"id": "a", "fn": "leaf", "args": {"x": 1}},)",
                         R"({"id": "u", "fn": "leaf", "args": {"x": 2}})"),
                 D);
  ASSERT_TRUE(G);
  EXPECT_TRUE(compileGraph(*G, stdSigs(), CompileOptions(), D));
  EXPECT_FALSE(D.hasErrors());
  EXPECT_EQ(text(D), "g.json:2:52: warning: node 'u' is not used by any material "
                     "[/nodes/1]\n");
}

TEST(Validate, ArraysOfScalarsAndInts) {
  CompiledGraph CG = resolved(oneNode(R"({"id": "a", "fn": "weights", "args": {
  "w": [0.5, 1, 2, 3, 4], "dirs": [[1, 0, 0], [0, 1, 0]], "n": 2}})"));
  ASSERT_EQ(CG.Nodes.size(), 1u);
  EXPECT_EQ(CG.Nodes[0].Args[0].ArrayCount, 5u);
  EXPECT_EQ(CG.Nodes[0].Args[1].ArrayCount, 2u);
  EXPECT_EQ(CG.Nodes[0].Args[1].Values.size(), 6u);
  EXPECT_EQ(errorsOf(oneNode(R"({"id": "a", "fn": "weights", "args": {
  "w": [[1], [2]], "dirs": [], "n": 2}})")),
            "g.json:3:8: error: node 'a': argument 'w' expects __global const float*, got an "
            "array of 2 rows (an array of numbers is expected) [/nodes/0/args/w]\n");
}

} // namespace
