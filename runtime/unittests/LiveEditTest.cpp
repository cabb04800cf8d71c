// The live editor's graph model written back as graph.json (graphJson): what a regeneration
// hands to texcc. Every example graph, parsed, written and parsed again, gives the same model
// (ids, functions, arguments with their kinds, numbers, integer-ness and bakes, materials in
// file order) and the same text; numbers that are not exactly representable in decimal
// round-trip bit for bit; a baked literal is written as {"value": v, "bake": true}.
#include "texrender/Error.h"
#include "texrender/LiveEdit.h"
#include "texrender/Renderer.h"

#include "texcc/Graph/Edit.h"
#include "texcc/Graph/Graph.h"

#include <gtest/gtest.h>

#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace texrender;
namespace graph = texcc::graph;

namespace {

graph::Graph parse(const std::string &Path, const std::string &Text) {
  graph::DiagnosticSink Diags;
  std::optional<graph::Graph> G = graph::parseGraph(Path, Text, Diags);
  std::ostringstream OS;
  Diags.print(OS);
  EXPECT_TRUE(G.has_value()) << OS.str();
  return G ? std::move(*G) : graph::Graph();
}

void expectSameValue(const graph::ArgValue &A, const graph::ArgValue &B, const std::string &What) {
  EXPECT_EQ(int(A.K), int(B.K)) << What;
  EXPECT_EQ(A.IsInteger, B.IsInteger) << What;
  EXPECT_EQ(A.IsArrayOfRows, B.IsArrayOfRows) << What;
  EXPECT_EQ(A.Bake, B.Bake) << What;
  EXPECT_EQ(A.Ref, B.Ref) << What;
  ASSERT_EQ(A.Numbers.size(), B.Numbers.size()) << What;
  for (size_t I = 0; I < A.Numbers.size(); ++I) // bit for bit, not to a tolerance
    EXPECT_EQ(std::memcmp(&A.Numbers[I], &B.Numbers[I], sizeof(double)), 0) << What;
  EXPECT_EQ(A.Rows, B.Rows) << What;
}

void expectSameBsdf(const graph::Bsdf &A, const graph::Bsdf &B, const std::string &What) {
  EXPECT_EQ(A.Type, B.Type) << What;
  ASSERT_EQ(A.Inputs.size(), B.Inputs.size()) << What;
  for (size_t I = 0; I < A.Inputs.size(); ++I) {
    EXPECT_EQ(A.Inputs[I].first, B.Inputs[I].first) << What;
    expectSameValue(A.Inputs[I].second, B.Inputs[I].second, What + "/" + A.Inputs[I].first);
  }
  ASSERT_EQ(A.Children.size(), B.Children.size()) << What;
  for (size_t I = 0; I < A.Children.size(); ++I) {
    EXPECT_EQ(A.Children[I].first, B.Children[I].first) << What;
    expectSameBsdf(A.Children[I].second, B.Children[I].second, What + "/" + A.Children[I].first);
  }
}

void expectSameGraph(const graph::Graph &A, const graph::Graph &B) {
  EXPECT_EQ(A.Sources, B.Sources);
  EXPECT_EQ(A.Images, B.Images);
  ASSERT_EQ(A.Nodes.size(), B.Nodes.size());
  for (size_t I = 0; I < A.Nodes.size(); ++I) {
    const graph::Node &N = A.Nodes[I], &M = B.Nodes[I];
    EXPECT_EQ(N.Id, M.Id);
    EXPECT_EQ(N.Fn, M.Fn);
    ASSERT_EQ(N.Args.size(), M.Args.size()) << N.Id;
    for (size_t J = 0; J < N.Args.size(); ++J) {
      EXPECT_EQ(N.Args[J].first, M.Args[J].first) << N.Id;
      expectSameValue(N.Args[J].second, M.Args[J].second, N.Id + "." + N.Args[J].first);
    }
  }
  ASSERT_EQ(A.Materials.size(), B.Materials.size());
  for (size_t I = 0; I < A.Materials.size(); ++I) {
    EXPECT_EQ(A.Materials[I].Name, B.Materials[I].Name); // texcc numbers them in this order
    expectSameBsdf(A.Materials[I].Root, B.Materials[I].Root, A.Materials[I].Name);
  }
}

} // namespace

TEST(LiveEditGraph, EveryExampleRoundTrips) {
  unsigned Graphs = 0;
  for (const auto &E : fs::directory_iterator(fs::path(TEXRENDER_SOURCE_DIR) / "examples")) {
    fs::path Path = E.path() / "graph.json";
    if (!fs::exists(Path))
      continue;
    SCOPED_TRACE(Path.string());
    std::ifstream In(Path);
    std::stringstream Text;
    Text << In.rdbuf();
    graph::Graph G = parse(Path.string(), Text.str());
    std::string Written = graphJson(G).dump(2);
    graph::Graph Again = parse("written.json", Written);
    expectSameGraph(G, Again);
    EXPECT_EQ(graphJson(Again).dump(2), Written);
    ++Graphs;
  }
  EXPECT_GE(Graphs, 4u); // rust, scratches, marble, wood at least
}

TEST(LiveEditGraph, NumbersBakesAndReferences) {
  const std::string Text = R"({
    "texcc": 1, "sources": ["a.cl"], "images": {"brick": "img/brick.png"},
    "nodes": [
      {"id": "n", "fn": "f", "args": {"x": 0.1, "k": 6, "big": 3.4028234663852886e38,
                                      "tiny": 1.17549435e-38, "v": [0.7, 1, 0.3],
                                      "b": {"value": 2, "bake": true},
                                      "bv": {"value": [0.25, 0.5, 1.0], "bake": true},
                                      "rows": [[0.0, 0.35, 0.12, 0.05, 1.0], [1, 0.6, 0.3, 0.1, 1]],
                                      "flat": [1, 2, 3, 4, 5], "p": {"attr": "ObjectPos"},
                                      "img": {"image": "brick"}}},
      {"id": "m", "fn": "g", "args": {"t": {"node": "n"}}}
    ],
    "materials": {"z": {"bsdf": "blend", "mask": {"node": "m"},
                        "a": {"bsdf": "diffuse", "color": [0.7, 0.7, 0.7]},
                        "b": {"bsdf": "glossy", "color": {"node": "n"}, "roughness": 0.2}},
                  "a": {"bsdf": "emission", "color": [1, 1, 1], "strength": 2.5}}
  })";
  graph::Graph G = parse("g.json", Text);
  nlohmann::ordered_json J = graphJson(G);
  const auto &Args = J["nodes"][0]["args"];
  EXPECT_EQ(Args["k"].dump(), "6");
  EXPECT_EQ(Args["x"].dump(), "0.1");
  EXPECT_EQ(Args["b"].dump(), R"({"value":2,"bake":true})");
  EXPECT_EQ(Args["bv"].dump(), R"({"value":[0.25,0.5,1.0],"bake":true})");
  EXPECT_EQ(Args["p"].dump(), R"({"attr":"ObjectPos"})");
  EXPECT_EQ(Args["img"].dump(), R"({"image":"brick"})");
  EXPECT_EQ(J["nodes"][1]["args"]["t"].dump(), R"({"node":"n"})");
  EXPECT_EQ(J["images"].dump(), R"({"brick":"img/brick.png"})");
  // Materials stay in file order ("z" before "a"), not sorted.
  EXPECT_EQ(J["materials"].begin().key(), "z");
  expectSameGraph(G, parse("again.json", J.dump()));
}

namespace {

/// NODE.ARG's value in G.
const graph::ArgValue &argument(const graph::Graph &G, const std::string &Node,
                                const std::string &Arg) {
  for (const auto &[Name, V] : G.findNode(Node)->Args)
    if (Name == Arg)
      return V;
  ADD_FAILURE() << Node << "." << Arg;
  return G.Nodes.front().Args.front().second;
}

/// A 4x4 film of one quad with the material "tex", for a renderer of Lay.
Scene quadScene(const fs::path &Dir) {
  Scene S;
  S.Path = (Dir / "scene.json").string();
  S.Cam.Position = {0.0f, 0.0f, 3.0f};
  S.Cam.Target = {0.0f, 0.0f, 0.0f};
  S.Cam.FovDegrees = 45;
  S.Render.Width = S.Render.Height = 4;
  S.Render.Spp = 1;
  std::ofstream(Dir / "quad.obj") << "v -1 -1 0\nv 1 -1 0\nv 1 1 0\nv -1 1 0\nf 1 2 3 4\n";
  MeshInstance M;
  M.ObjPath = (Dir / "quad.obj").string();
  M.Material = "tex";
  M.Transform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  M.JsonPath = "/meshes/0";
  S.Meshes.push_back(M);
  return S;
}

} // namespace

// texrender's --set and edit script: LiveEditor::check validates every edit once, each against
// the graph the edits before it leave, and applies none; the frames then apply the checked
// edits without validating them again (the check on a scratch editor and the apply used to
// validate each edit twice).
TEST(LiveEditor, CheckedEditsAreValidatedOnce) {
  Layout L = loadLayout(std::string(TEXRENDER_SOURCE_DIR) + "/testsuite/Inputs/runtime/const-tex");
  LiveEditor Editor(L);
  std::vector<CheckedEdit> Checked, None;
  std::optional<EditProblem> P =
      Editor.check({parseEdit("set t.gain=0.5"), parseEdit("t.gian=2")}, None);
  ASSERT_TRUE(P);
  EXPECT_EQ(P->Index, 1u);
  EXPECT_EQ(P->Col, 3u); // the parameter
  EXPECT_NE(P->Message.find("unknown argument 'gian'"), std::string::npos) << P->Message;

  const uint64_t Before = graph::GraphEditor::validations();
  ASSERT_FALSE(Editor.check({parseEdit("set t.gain=0.5"), parseEdit("wait"),
                             parseEdit("t.color=[1, 0, 0]"), parseEdit("t.gain=0.25")},
                            Checked));
  EXPECT_EQ(graph::GraphEditor::validations() - Before, 3u);
  ASSERT_EQ(Checked.size(), 4u);
  EXPECT_EQ(Checked[2].line().Text, "t.color=[1, 0, 0]");
  EXPECT_EQ(argument(Editor.graph(), "t", "gain").Numbers, std::vector<double>{1.0});

  if (listDevices().empty())
    GTEST_SKIP() << "no OpenCL device: applying the checked edits needs a renderer";
  fs::path Dir = fs::temp_directory_path() / ("texrender-checked-" + std::to_string(::getpid()));
  fs::create_directories(Dir);
  RendererOptions O;
  O.CacheDir = (fs::temp_directory_path() / "texrender-test-cache").string();
  if (!std::getenv("TEXRENDER_KERNELS"))
    O.KernelDir = TEXRENDER_KERNEL_DIR;
  Renderer R(quadScene(Dir), L, O);
  const uint64_t Checks = graph::GraphEditor::validations();
  for (CheckedEdit &C : Checked)
    EXPECT_FALSE(Editor.apply(std::move(C), R).Rebuilt);
  EXPECT_EQ(graph::GraphEditor::validations(), Checks);
  EXPECT_EQ(argument(Editor.graph(), "t", "gain").Numbers, std::vector<double>{0.25});
  EXPECT_EQ(argument(Editor.graph(), "t", "color").Numbers, (std::vector<double>{1, 0, 0}));
  // The watch session's ways in validate once too: a control line's typed edit, and a saved
  // graph.json's diff (all or nothing).
  Editor.apply(graphEdit(parseEdit("t.gain=0.75")), R);
  EXPECT_EQ(graph::GraphEditor::validations() - Checks, 1u);
  graph::Graph Saved = Editor.graph();
  Saved.findNode("t")->Args[0].second.Numbers = {0.5, 0.5, 0.5};
  Saved.findNode("t")->Args[1].second.Numbers = {2.0};
  std::string Why;
  std::optional<std::vector<graph::Edit>> Diff = graph::diff(Editor.graph(), Saved, Why);
  ASSERT_TRUE(Diff && Diff->size() == 2) << Why;
  Editor.apply(*Diff, R);
  EXPECT_EQ(graph::GraphEditor::validations() - Checks, 3u);
  EXPECT_TRUE(graph::sameGraph(Editor.graph(), Saved));
  fs::remove_all(Dir);
}

// The watch session's scene reload: a renderer made from the live editor's rendered layout
// (its kernel with the args.bin of every edit so far) renders what the renderer before it
// rendered, and nothing is validated again: the editor carries on. (The reload used to start a
// new renderer from the session's layout and apply the edits made since to a new editor, each
// validated a second time.) An edit the renderer never got (its regeneration failed: no texcc)
// leaves no layout to carry, and the reload falls back to applying the edits again.
TEST(LiveEditor, ASceneReloadValidatesNothing) {
  if (listDevices().empty())
    GTEST_SKIP() << "no OpenCL device: the reload needs renderers";
  Layout L = loadLayout(std::string(TEXRENDER_SOURCE_DIR) + "/testsuite/Inputs/runtime/const-tex");
  fs::path Dir = fs::temp_directory_path() / ("texrender-reload-" + std::to_string(::getpid()));
  fs::create_directories(Dir);
  RendererOptions O;
  O.CacheDir = (fs::temp_directory_path() / "texrender-test-cache").string();
  if (!std::getenv("TEXRENDER_KERNELS"))
    O.KernelDir = TEXRENDER_KERNEL_DIR;
  Scene Lit = quadScene(Dir);
  Light Sky;
  Sky.Type = "sky";
  Sky.Radiance = {1, 1, 1};
  Lit.Lights.push_back(Sky);
  LiveEditor Editor(L, std::make_shared<const Regenerator>((Dir / "no-texcc").string()));
  Renderer R(Lit, L, O);
  ASSERT_TRUE(Editor.renderedLayout());
  Editor.apply(graphEdit(parseEdit("t.gain=0.5")), R);
  Editor.apply(graphEdit(parseEdit("t.color=[1, 0.25, 0]")), R);
  const uint64_t Before = graph::GraphEditor::validations();
  std::optional<Layout> Carried = Editor.renderedLayout();
  ASSERT_TRUE(Carried);
  Renderer Reloaded(Lit, *Carried, O);
  EXPECT_EQ(graph::GraphEditor::validations(), Before);
  FrameStats S;
  const std::vector<float> Edited = R.render(S);
  EXPECT_EQ(Reloaded.render(S), Edited); // bit for bit
  Renderer Unedited(Lit, L, O);
  EXPECT_NE(Unedited.render(S), Edited);
  // The editor carries on with the reloaded renderer.
  Editor.apply(graphEdit(parseEdit("t.gain=2")), Reloaded);
  EXPECT_EQ(graph::GraphEditor::validations() - Before, 1u);
  ASSERT_TRUE(Editor.renderedLayout());
  // A normal read by the tint needs a case the interp kernel lacks: a regeneration, which
  // fails here; the graph editor has the edit, the renderer does not.
  EXPECT_THROW(Editor.apply(graphEdit(parseEdit(R"(t.color={"attr": "Normal"})")), Reloaded),
               Error);
  EXPECT_FALSE(Editor.renderedLayout());
  fs::remove_all(Dir);
}
