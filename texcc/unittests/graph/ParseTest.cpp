// parseGraph(): the graph.json model, and errors for malformed JSON and a wrong file shape.

#include "GraphTestUtil.h"

using namespace texcc::graph;
using namespace texcc::graph::test;

namespace {

std::string parseErrors(const std::string &Json) {
  DiagnosticSink D;
  EXPECT_FALSE(parse(Json, D).has_value());
  return text(D);
}

TEST(Parse, DesignExample) {
  DiagnosticSink D;
  auto G = parse(R"({
  "texcc": 1,
  "sources": ["noise.cl", "rust.cl"],
  "images": { "brick": "textures/brick.png" },
  "nodes": [
    { "id": "n", "fn": "fbm3", "args": { "p": { "attr": "ObjectPos" }, "scale": 4.0, "octaves": 6 } },
    { "id": "ramp", "fn": "colorRamp", "args": { "t": { "node": "n" },
      "stops": [[0.0, 0.35, 0.12, 0.05, 1.0], [1.0, 0.6, 0.3, 0.1, 1.0]], "count": 2 } },
    { "id": "img", "fn": "image", "args": { "img": { "image": "brick" }, "uv": [0.5, 0.25] } }
  ],
  "materials": {
    "rusty": { "bsdf": "blend", "mask": { "node": "n" },
               "a": { "bsdf": "diffuse", "color": [0.7, 0.7, 0.7] },
               "b": { "bsdf": "glossy", "color": { "node": "ramp" }, "roughness": 0.2 } },
    "gray":  { "bsdf": "diffuse", "color": 0.5 }
  }
})",
                 D);
  ASSERT_TRUE(G) << text(D);
  EXPECT_EQ(G->Sources, (std::vector<std::string>{"noise.cl", "rust.cl"}));
  ASSERT_EQ(G->Images.size(), 1u);
  EXPECT_EQ(G->Images[0].second, "textures/brick.png");
  ASSERT_EQ(G->Nodes.size(), 3u);
  const Node &N = G->Nodes[0];
  EXPECT_EQ(N.Id, "n");
  EXPECT_EQ(N.Fn, "fbm3");
  EXPECT_EQ(N.JsonPath, "/nodes/0");
  EXPECT_EQ(N.Loc.Line, 6u);
  EXPECT_EQ(N.Loc.Col, 5u);
  ASSERT_EQ(N.Args.size(), 3u);
  EXPECT_EQ(N.Args[0].second.K, ArgValue::Kind::AttrRef);
  EXPECT_EQ(N.Args[0].second.Ref, "ObjectPos");
  EXPECT_EQ(N.Args[1].second.K, ArgValue::Kind::Number);
  EXPECT_FALSE(N.Args[1].second.IsInteger);
  EXPECT_TRUE(N.Args[2].second.IsInteger);
  EXPECT_EQ(N.Args[2].second.JsonPath, "/nodes/0/args/octaves");
  const ArgValue &Stops = G->Nodes[1].Args[1].second;
  EXPECT_EQ(Stops.K, ArgValue::Kind::Array);
  EXPECT_TRUE(Stops.IsArrayOfRows);
  ASSERT_EQ(Stops.Rows.size(), 2u);
  EXPECT_EQ(Stops.Rows[1][1], 0.6);
  EXPECT_EQ(G->Nodes[2].Args[0].second.K, ArgValue::Kind::ImageRef);
  EXPECT_EQ(G->Nodes[2].Args[1].second.K, ArgValue::Kind::Vector);
  ASSERT_EQ(G->Materials.size(), 2u);
  EXPECT_EQ(G->Materials[0].Name, "rusty");
  EXPECT_EQ(G->Materials[0].Root.Type, "blend");
  ASSERT_EQ(G->Materials[0].Root.Children.size(), 2u);
  EXPECT_EQ(G->Materials[0].Root.Children[1].second.Type, "glossy");
  EXPECT_EQ(G->Materials[0].Root.Children[1].second.JsonPath, "/materials/rusty/b");
  EXPECT_EQ(G->Materials[1].Root.Inputs[0].second.Numbers, std::vector<double>{0.5});
}

TEST(Parse, MalformedJsonHasLineAndColumn) {
  EXPECT_EQ(parseErrors("{\n  \"texcc\": 1\n  \"nodes\": []\n}"),
            "g.json:3:3: error: expected ',' or '}' in object, got '\"'\n");
  EXPECT_EQ(parseErrors("{\"texcc\": 1, \"nodes\": [1, 2"),
            "g.json:1:28: error: expected ',' or ']' in array, got end of file\n");
  EXPECT_EQ(parseErrors(""), "g.json:1:1: error: expected a JSON value, got an empty file\n");
  EXPECT_EQ(parseErrors("{\"a\": \"abc"), "g.json:1:7: error: unterminated string\n");
  EXPECT_EQ(parseErrors("{\"a\": 1,}"), "g.json:1:9: error: trailing comma before '}'\n");
  EXPECT_EQ(parseErrors("{\"a\": 01}"),
            "g.json:1:7: error: invalid number: leading zeros are not allowed\n");
  EXPECT_EQ(parseErrors("// c\n{}"), "g.json:1:1: error: comments are not allowed in JSON\n");
  EXPECT_EQ(parseErrors("{} x"),
            "g.json:1:4: error: unexpected 'x' after the top-level value\n");
  EXPECT_EQ(parseErrors("{\"a\": 1, \"a\": 2}"),
            "g.json:1:10: error: duplicate key 'a' in object\n");
  EXPECT_EQ(parseErrors("{'a': 1}"),
            "g.json:1:2: error: expected a string key in object, got '''\n");
}

TEST(Parse, NonFiniteAndHugeNumbers) {
  EXPECT_EQ(parseErrors("{\"texcc\": 1, \"nodes\": [NaN]}"),
            "g.json:1:24: error: 'NaN' is not a number: graph values must be finite\n");
  EXPECT_EQ(parseErrors("{\"texcc\": 1, \"nodes\": [-Infinity]}"),
            "g.json:1:24: error: '-Infinity' is not a number: graph values must be finite\n");
  EXPECT_EQ(parseErrors("{\"texcc\": 1, \"x\": 1e400}"),
            "g.json:1:19: error: number '1e400' is out of range\n");
  EXPECT_NE(parseErrors(R"({"texcc": 1, "nodes": [{"id": "a", "fn": "leaf",
    "args": {"x": 1e39}}], "materials": {}})")
                .find("g.json:2:19: error: number '1e39' does not fit in a 32-bit float "
                      "[/nodes/0/args/x]"),
            std::string::npos);
}

TEST(Parse, WrongKindsAndUnknownKeys) {
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "nodes": {}, "materials": {}})"),
            "g.json:1:23: error: 'nodes' must be an array of node objects, got an object "
            "[/nodes]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "node": [], "materials": {}})"),
            "g.json:1:14: error: unknown key 'node' in graph; expected 'texcc', 'sources', "
            "'images', 'nodes' or 'materials'; did you mean 'nodes'? [/node]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 2, "materials": {}})"),
            "g.json:1:11: error: unsupported graph version '2'; this texcc reads version 1 "
            "[/texcc]\n");
  EXPECT_EQ(parseErrors(R"({"materials": {}})"),
            "g.json:1:1: error: the graph is missing required key 'texcc' [/]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "nodes": [{"id": "a"}], "materials": {}})"),
            "g.json:1:24: error: node is missing required key 'fn' [/nodes/0]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "nodes": [{"id": 3, "fn": "f"}], "materials": {}})"),
            "g.json:1:31: error: 'id' must be a string, got a number [/nodes/0/id]\n");
  EXPECT_EQ(parseErrors(
                R"({"texcc": 1, "nodes": [{"id": "a", "fn": "f", "arg": {}}], "materials": {}})"),
            "g.json:1:47: error: unknown key 'arg' in node; expected 'id', 'fn' or 'args'; "
            "did you mean 'args'? [/nodes/0/arg]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "nodes": [{"id": "a", "fn": "f",
      "args": {"x": "0.5"}}], "materials": {}})"),
            "g.json:2:21: error: expected a number, an array, or an object with 'node', "
            "'attr', 'image' or 'value'; got a string [/nodes/0/args/x]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "nodes": [{"id": "a", "fn": "f",
      "args": {"x": {"nod": "b"}}}], "materials": {}})"),
            "g.json:2:22: error: unknown key 'nod' in reference; expected 'node', 'attr' or "
            "'image'; did you mean 'node'? [/nodes/0/args/x/nod]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "nodes": [{"id": "a", "fn": "f",
      "args": {"x": [1, [2]]}}], "materials": {}})"),
            "g.json:2:21: error: an array value must hold only numbers (a vector or a flat "
            "array) or only arrays of numbers (an array of vectors) [/nodes/0/args/x]\n");
}

TEST(Parse, DuplicateNodeId) {
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "nodes": [
  {"id": "a", "fn": "leaf", "args": {"x": 1}},
  {"id": "a", "fn": "leaf", "args": {"x": 2}}], "materials": {}})"),
            "g.json:3:10: error: duplicate node id 'a' [/nodes/1/id]\n"
            "g.json:2:10: note: previous definition of 'a' is here\n");
}

TEST(Parse, BsdfErrors) {
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "materials": {"m": {"bsdf": "difuse", "color": 1}}})"),
            "g.json:1:42: error: unknown BSDF 'difuse'; expected 'diffuse', 'glossy', "
            "'mirror', 'emission', 'principled' or 'blend'; did you mean 'diffuse'? "
            "[/materials/m/bsdf]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "materials": {"m": {"bsdf": "diffuse", "colour": 1}}})"),
            "g.json:1:53: error: BSDF 'diffuse' has no input 'colour'; its inputs are "
            "'color' or 'normal'; did you mean 'color'? [/materials/m/colour]\n"
            "g.json:1:33: error: BSDF 'diffuse' is missing input 'color' [/materials/m]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "materials": {"m": {"color": 1}}})"),
            "g.json:1:33: error: material 'm' is missing required key 'bsdf' [/materials/m]\n");
  EXPECT_EQ(parseErrors(R"({"texcc": 1, "materials": {"m": {"bsdf": "blend", "mask": 0.5,
      "a": {"bsdf": "diffuse", "color": {"attr": "AO"}}, "b": 3}}})"),
            "g.json:2:41: error: BSDF input 'color' must be a number, a vector or "
            "{\"node\": id} [/materials/m/a/color]\n"
            "g.json:2:63: error: blend input 'b' must be an object with a 'bsdf' key, got a "
            "number [/materials/m/b]\n");
}

TEST(Parse, EveryTruncationIsAnErrorWithAPosition) {
  const std::string Full = R"({"texcc": 1, "images": {"i": "a.png"}, "nodes": [
  {"id": "n", "fn": "fbm3", "args": {"p": {"attr": "ObjectPos"}, "scale": -4.5e-1, "octaves": 6}},
  {"id": "r", "fn": "ramp", "args": {"t": {"node": "n"}, "stops": [[0, 1, 2, 3]], "count": 1}}],
  "materials": {"m": {"bsdf": "blend", "mask": {"node": "n"},
    "a": {"bsdf": "diffuse", "color": [0.7, 0.7, 0.7]},
    "b": {"bsdf": "glossy", "color": {"node": "r"}, "roughness": 0.2}}}})";
  DiagnosticSink Ok;
  ASSERT_TRUE(parse(Full, Ok)) << text(Ok);
  for (size_t Len = 0; Len < Full.size(); ++Len) {
    DiagnosticSink D;
    EXPECT_FALSE(parse(Full.substr(0, Len), D).has_value()) << Len;
    ASSERT_FALSE(D.diagnostics().empty()) << Len;
    EXPECT_GT(D.diagnostics().front().Loc.Line, 0u) << Len;
  }
}

TEST(Parse, ArgValueText) {
  DiagnosticSink D;
  auto V = parseArgValue("e", "[[0,0.3,0.1,0.05,1],[1,0.6,0.3,0.1,1]]", D);
  ASSERT_TRUE(V);
  EXPECT_EQ(V->K, ArgValue::Kind::Array);
  EXPECT_EQ(V->Rows.size(), 2u);
  V = parseArgValue("e", "[1,0,0]", D);
  ASSERT_TRUE(V);
  EXPECT_EQ(V->K, ArgValue::Kind::Vector);
  V = parseArgValue("e", "0.5", D);
  ASSERT_TRUE(V);
  EXPECT_EQ(V->Numbers, std::vector<double>{0.5});
  EXPECT_FALSE(parseArgValue("n.x", "[1,", D));
  EXPECT_EQ(text(D), "n.x:1:4: error: expected a value or ']', got end of file\n");
}

TEST(Parse, BakedArguments) {
  // {"value": v, "bake": b}: the value's own kind, marked or not; "bake" defaults to false.
  DiagnosticSink D;
  auto V = parseArgValue("e", R"({"value": [1, 0, 0], "bake": true})", D);
  ASSERT_TRUE(V);
  EXPECT_EQ(V->K, ArgValue::Kind::Vector);
  EXPECT_TRUE(V->Bake);
  V = parseArgValue("e", R"({"value": 2})", D);
  ASSERT_TRUE(V);
  EXPECT_EQ(V->K, ArgValue::Kind::Number);
  EXPECT_TRUE(V->IsInteger);
  EXPECT_FALSE(V->Bake);
  V = parseArgValue("e", "3", D);
  ASSERT_TRUE(V);
  EXPECT_FALSE(V->Bake);
  EXPECT_EQ(text(D), "");
  EXPECT_FALSE(parseArgValue("n.x", R"({"value": 2, "bake": "yes"})", D));
  EXPECT_EQ(text(D), "n.x:1:22: error: 'bake' must be true or false, got a string [/bake]\n");
}

} // namespace
