// diff(Old, New): the edits that take one graph to another, checked on every graph.json of
// the repository (examples/, textures/, the test and benchmark inputs) with generated edits:
// every argument given a new value, every constant rewired to another node's output, every
// reference set back to a constant, all at once, an argument added; applying diff(A, B) to A
// gives B, and diff(B, A) takes it back. What edits cannot express is refused with its reason.
// GraphEditor::apply validates a typed edit once and leaves the graph unchanged on refusal.

#include "texcc/Graph/Diff.h"
#include "texcc/Graph/Edit.h"

#include "GraphTestUtil.h"

#include <filesystem>
#include <fstream>

namespace fs = std::filesystem;
using namespace texcc::graph;
using namespace texcc::graph::test;

namespace {

struct NamedGraph {
  std::string Path;
  Graph G;
};

/// Every file under examples/, textures/, testsuite/Inputs and bench/inputs that parses as a
/// graph.json.
const std::vector<NamedGraph> &allGraphs() {
  static const std::vector<NamedGraph> Graphs = [] {
    std::vector<NamedGraph> Out;
    for (const char *Dir : {"examples", "textures", "testsuite/Inputs", "bench/inputs"}) {
      fs::path Root = fs::path(TEXCC_SOURCE_DIR) / Dir;
      if (!fs::exists(Root))
        continue;
      for (const auto &E : fs::recursive_directory_iterator(Root)) {
        if (!E.is_regular_file() || E.path().extension() != ".json" || E.file_size() > (1 << 20))
          continue;
        std::ifstream In(E.path());
        std::stringstream Text;
        Text << In.rdbuf();
        if (Text.str().find("\"nodes\"") == std::string::npos)
          continue;
        DiagnosticSink D;
        std::optional<Graph> G = parseGraph(E.path().string(), Text.str(), D);
        if (G)
          Out.push_back({E.path().string(), std::move(*G)});
      }
    }
    std::sort(Out.begin(), Out.end(),
              [](const NamedGraph &A, const NamedGraph &B) { return A.Path < B.Path; });
    return Out;
  }();
  return Graphs;
}

/// Another value of the same kind and size: numbers moved (an integer by 1), a reference
/// turned into the constant 0.5.
ArgValue changed(const ArgValue &V) {
  ArgValue C = V;
  const double Step = V.IsInteger ? 1 : 0.25;
  switch (V.K) {
  case ArgValue::Kind::NodeRef:
  case ArgValue::Kind::AttrRef:
  case ArgValue::Kind::ImageRef:
    C = ArgValue();
    C.Numbers = {0.5};
    return C;
  default:
    for (double &D : C.Numbers)
      D += Step;
    for (std::vector<double> &Row : C.Rows)
      for (double &D : Row)
        D += Step;
    if (C.Numbers.empty() && C.Rows.empty())
      C.Numbers = {1};
    return C;
  }
}

ArgValue nodeRef(const std::string &Id) {
  ArgValue V;
  V.K = ArgValue::Kind::NodeRef;
  V.Ref = Id;
  return V;
}

/// Applies Edits to a copy of G.
Graph applied(Graph G, const std::vector<Edit> &Edits) {
  for (const Edit &E : Edits) {
    std::string Why;
    EXPECT_TRUE(applyEdit(G, E, Why)) << Why;
  }
  return G;
}

/// diff(A, B) applied to A gives B; diff(B, A) applied to B gives A. Returns diff(A, B).
std::vector<Edit> expectRoundTrip(const Graph &A, const Graph &B) {
  std::string Why;
  std::optional<std::vector<Edit>> There = diff(A, B, Why);
  EXPECT_TRUE(There.has_value()) << Why;
  std::optional<std::vector<Edit>> Back = diff(B, A, Why);
  EXPECT_TRUE(Back.has_value()) << Why;
  if (!There || !Back)
    return {};
  EXPECT_TRUE(sameGraph(applied(A, *There), B));
  EXPECT_TRUE(sameGraph(applied(B, *Back), A));
  return *There;
}

TEST(DiffTest, FindsTheRepositorysGraphs) {
  unsigned Examples = 0;
  for (const NamedGraph &N : allGraphs())
    Examples += N.Path.find("/examples/") != std::string::npos;
  EXPECT_GE(Examples, 7u);          // cornell, custom-node, image-multiply, marble, rust, ...
  EXPECT_GE(allGraphs().size(), 40u);
  std::printf("%zu graphs, %u of them examples\n", allGraphs().size(), Examples);
}

TEST(DiffTest, AGraphAgainstItselfHasNoEdits) {
  for (const NamedGraph &N : allGraphs()) {
    SCOPED_TRACE(N.Path);
    std::string Why;
    std::optional<std::vector<Edit>> D = diff(N.G, N.G, Why);
    ASSERT_TRUE(D.has_value()) << Why;
    EXPECT_TRUE(D->empty());
    // Locations and a node's argument order are not differences.
    Graph Again = N.G;
    for (Node &Nd : Again.Nodes) {
      std::reverse(Nd.Args.begin(), Nd.Args.end());
      for (auto &[Name, V] : Nd.Args)
        V.Loc = V.KeyLoc = {}, V.JsonPath.clear();
    }
    EXPECT_TRUE(sameGraph(N.G, Again));
  }
}

TEST(DiffTest, EveryArgumentChangedAlone) {
  unsigned Checked = 0;
  for (const NamedGraph &N : allGraphs())
    for (size_t I = 0; I < N.G.Nodes.size(); ++I)
      for (size_t J = 0; J < N.G.Nodes[I].Args.size(); ++J) {
        SCOPED_TRACE(N.Path + ": " + N.G.Nodes[I].Id + "." + N.G.Nodes[I].Args[J].first);
        Graph B = N.G;
        B.Nodes[I].Args[J].second = changed(B.Nodes[I].Args[J].second);
        std::vector<Edit> D = expectRoundTrip(N.G, B);
        ASSERT_EQ(D.size(), 1u);
        EXPECT_EQ(D[0].Node, N.G.Nodes[I].Id);
        EXPECT_EQ(D[0].Arg, N.G.Nodes[I].Args[J].first);
        EXPECT_EQ(int(D[0].K), int(Edit::Kind::Set));
        EXPECT_TRUE(sameValue(D[0].Value, B.Nodes[I].Args[J].second));
        ++Checked;
      }
  EXPECT_GE(Checked, 200u);
}

TEST(DiffTest, EveryConstantRewiredAndBack) {
  unsigned Checked = 0;
  for (const NamedGraph &N : allGraphs()) {
    if (N.G.Nodes.size() < 2)
      continue;
    for (size_t I = 0; I < N.G.Nodes.size(); ++I)
      for (size_t J = 0; J < N.G.Nodes[I].Args.size(); ++J) {
        const ArgValue &Was = N.G.Nodes[I].Args[J].second;
        if (Was.K == ArgValue::Kind::NodeRef)
          continue;
        const std::string Source = N.G.Nodes[I == 0 ? 1 : 0].Id;
        SCOPED_TRACE(N.Path + ": " + N.G.Nodes[I].Id + "." + N.G.Nodes[I].Args[J].first);
        Graph B = N.G;
        B.Nodes[I].Args[J].second = nodeRef(Source);
        std::vector<Edit> D = expectRoundTrip(N.G, B);
        ASSERT_EQ(D.size(), 1u);
        EXPECT_EQ(int(D[0].Value.K), int(ArgValue::Kind::NodeRef));
        EXPECT_EQ(D[0].Value.Ref, Source);
        // And back to the constant: one edit that gives the old value again.
        std::string Why;
        std::optional<std::vector<Edit>> Back = diff(B, N.G, Why);
        ASSERT_TRUE(Back && Back->size() == 1) << Why;
        EXPECT_TRUE(sameValue((*Back)[0].Value, Was));
        ++Checked;
      }
  }
  EXPECT_GE(Checked, 200u);
}

TEST(DiffTest, EveryArgumentAtOnce) {
  for (const NamedGraph &N : allGraphs()) {
    SCOPED_TRACE(N.Path);
    Graph B = N.G;
    size_t Args = 0;
    for (Node &Nd : B.Nodes)
      for (auto &[Name, V] : Nd.Args) {
        // Alternately a new value and a rewiring onto the first node (kept out of itself).
        if (Args % 2 == 0 || B.Nodes.size() < 2 || &Nd == &B.Nodes[0])
          V = changed(V);
        else
          V = nodeRef(B.Nodes[0].Id);
        ++Args;
      }
    std::vector<Edit> D = expectRoundTrip(N.G, B);
    EXPECT_LE(D.size(), Args); // a reference that stays on node 0 is no edit
    EXPECT_GE(D.size(), Args / 2);
  }
}

TEST(DiffTest, AnArgumentAddedIsAnEdit) {
  for (const NamedGraph &N : allGraphs()) {
    if (N.G.Nodes.empty())
      continue;
    SCOPED_TRACE(N.Path);
    Graph B = N.G;
    ArgValue V;
    V.Numbers = {2};
    V.IsInteger = true;
    B.Nodes.back().Args.emplace_back("added_arg", V);
    std::vector<Edit> D = expectRoundTrip(B, B);
    EXPECT_TRUE(D.empty());
    std::string Why;
    std::optional<std::vector<Edit>> There = diff(N.G, B, Why);
    ASSERT_TRUE(There && There->size() == 1) << Why;
    EXPECT_EQ((*There)[0].Arg, "added_arg");
    EXPECT_EQ(editText((*There)[0]), "set " + B.Nodes.back().Id + ".added_arg=2");
    EXPECT_TRUE(sameGraph(applied(N.G, *There), B));
    // The way back removes an argument: that needs texcc.
    EXPECT_FALSE(diff(B, N.G, Why).has_value());
    EXPECT_EQ(Why, "argument '" + B.Nodes.back().Id + ".added_arg' removed");
  }
}

/// What an edit cannot express, on every graph: each refused with its reason.
TEST(DiffTest, RefusesWhatNeedsTexcc) {
  struct Case {
    const char *What;
    std::function<std::string(Graph &)> Change; // returns the expected reason ("" skips)
  };
  const std::vector<Case> Cases = {
      {"node removed", [](Graph &G) -> std::string {
         if (G.Nodes.empty())
           return "";
         std::string Id = G.Nodes.back().Id;
         G.Nodes.pop_back();
         return "node '" + Id + "' removed";
       }},
      {"node added", [](Graph &G) -> std::string {
         if (G.Nodes.empty())
           return "";
         Node N = G.Nodes.back();
         N.Id += "_copy";
         G.Nodes.push_back(N);
         return "node '" + N.Id + "' added";
       }},
      {"function changed", [](Graph &G) -> std::string {
         if (G.Nodes.empty())
           return "";
         std::string Was = G.Nodes[0].Fn;
         G.Nodes[0].Fn += "_other";
         return "node '" + G.Nodes[0].Id + "' calls '" + Was + "_other' instead of '" + Was + "'";
       }},
      {"nodes reordered", [](Graph &G) -> std::string {
         if (G.Nodes.size() < 2)
           return "";
         std::swap(G.Nodes[0], G.Nodes[1]);
         return "the nodes' order changed ('" + G.Nodes[0].Id + "' where '" + G.Nodes[1].Id +
                "' was)";
       }},
      {"source added", [](Graph &G) {
         G.Sources.push_back("other.cl");
         return std::string("the sources changed");
       }},
      {"image added", [](Graph &G) {
         G.Images.emplace_back("other_image", "other.png");
         return std::string("the images changed");
       }},
      {"material added", [](Graph &G) {
         Material M;
         M.Name = "other_material";
         M.Root.Type = "diffuse";
         G.Materials.push_back(M);
         return std::string("the materials changed");
       }},
      {"material input changed", [](Graph &G) -> std::string {
         for (Material &M : G.Materials)
           if (!M.Root.Inputs.empty()) {
             M.Root.Inputs[0].second = changed(M.Root.Inputs[0].second);
             return "material '" + M.Name + "' changed";
           }
         return "";
       }},
      {"argument removed", [](Graph &G) -> std::string {
         for (Node &N : G.Nodes)
           if (!N.Args.empty()) {
             std::string Name = N.Args.back().first;
             N.Args.pop_back();
             return "argument '" + N.Id + "." + Name + "' removed";
           }
         return "";
       }},
      {"argument baked", [](Graph &G) -> std::string {
         for (Node &N : G.Nodes)
           for (auto &[Name, V] : N.Args)
             if (V.K == ArgValue::Kind::Number && !V.Bake) {
               V.Bake = true;
               return "argument '" + N.Id + "." + Name + "' baked (the shape code changes)";
             }
         return "";
       }},
  };
  std::map<std::string, unsigned> Seen;
  for (const NamedGraph &N : allGraphs())
    for (const Case &C : Cases) {
      SCOPED_TRACE(N.Path + ": " + C.What);
      Graph B = N.G;
      std::string Expected = C.Change(B);
      if (Expected.empty())
        continue;
      std::string Why;
      EXPECT_FALSE(diff(N.G, B, Why).has_value());
      EXPECT_EQ(Why, Expected);
      EXPECT_FALSE(sameGraph(N.G, B));
      ++Seen[C.What];
    }
  for (const Case &C : Cases)
    EXPECT_GE(Seen[C.What], 5u) << C.What;
}

TEST(DiffTest, EditText) {
  Edit E;
  E.Node = "t";
  E.Arg = "gain";
  E.Value.Numbers = {0.25};
  EXPECT_EQ(editText(E), "set t.gain=0.25");
  E.Value = nodeRef("b");
  EXPECT_EQ(editText(E), R"(set t.gain={"node":"b"})");
  E.Value = ArgValue();
  E.Value.K = ArgValue::Kind::Vector;
  E.Value.Numbers = {1, 2};
  E.Value.IsInteger = true;
  EXPECT_EQ(editText(E), "set t.gain=[1,2]");
  EXPECT_EQ(editText(rewireEdit("mask.a", "noise", "grain")), "rewire mask.a.noise=grain");
}

const char *SmallGraph = R"({"texcc": 1, "nodes": [
  {"id": "n", "fn": "fbm3", "args": {"p": {"attr": "ObjectPos"}, "scale": 4.0, "octaves": 6}},
  {"id": "a", "fn": "leaf", "args": {"x": 1}},
  {"id": "b", "fn": "leaf", "args": {"x": 2}},
  {"id": "s", "fn": "add", "args": {"a": {"node": "a"}, "b": {"node": "n"}}}],
  "materials": {"one": {"bsdf": "diffuse", "color": {"node": "s"}}}})";

/// The saved graph's edits, validated and applied by the editor: its graph is then the saved
/// one, and its args.bin that of a fresh compile of it.
TEST(DiffTest, EditorAppliesADiff) {
  DiagnosticSink D;
  std::optional<Graph> Old = parse(SmallGraph, D);
  ASSERT_TRUE(Old) << text(D);
  Graph New = *Old;
  New.findNode("n")->Args[1].second.Numbers = {7.5};
  New.findNode("s")->Args[0].second = nodeRef("b");
  New.findNode("s")->Args[1].second = changed(nodeRef("n")); // back to a constant
  std::string Why;
  std::optional<std::vector<Edit>> Edits = diff(*Old, New, Why);
  ASSERT_TRUE(Edits && Edits->size() == 3) << Why;
  GraphEditor Ed(*Old, stdSigs(), CompileOptions());
  ASSERT_TRUE(Ed.init(D)) << text(D);
  for (const Edit &E : *Edits)
    ASSERT_TRUE(Ed.apply(E, D)) << editText(E) << ": " << text(D);
  EXPECT_TRUE(sameGraph(Ed.graph(), New));
  // A fresh compile of the saved graph with the kernel's function ids (the editor pins them).
  CompileOptions Pinned;
  for (size_t Id = 0; Id < Ed.compiled().FunctionsById.size(); ++Id)
    if (!Ed.compiled().FunctionsById[Id].empty())
      Pinned.FixedFunctionIds[Ed.compiled().FunctionsById[Id]] = unsigned(Id);
  std::optional<CompiledGraph> Fresh = compileGraph(New, stdSigs(), Pinned, D);
  ASSERT_TRUE(Fresh) << text(D);
  EXPECT_EQ(Ed.compiled().ArgsBin, Fresh->ArgsBin);
}

/// A refused edit leaves the editor as it was: its graph and its args.bin.
TEST(DiffTest, EditorRefusalChangesNothing) {
  DiagnosticSink D;
  std::optional<Graph> Old = parse(SmallGraph, D);
  ASSERT_TRUE(Old) << text(D);
  GraphEditor Ed(*Old, stdSigs(), CompileOptions());
  ASSERT_TRUE(Ed.init(D)) << text(D);
  const std::vector<uint8_t> Bin = Ed.compiled().ArgsBin;
  Edit Wrong; // a vector for a float
  Wrong.Node = "a";
  Wrong.Arg = "x";
  Wrong.Value.K = ArgValue::Kind::Vector;
  Wrong.Value.Numbers = {1, 2};
  Edit Cycle = rewireEdit("a", "x", "s"); // s reads a
  Edit Unknown = rewireEdit("s", "a", "nowhere");
  Edit NoNode = Wrong;
  NoNode.Node = "zz";
  for (const Edit &E : {Wrong, Cycle, Unknown, NoNode}) {
    SCOPED_TRACE(editText(E));
    DiagnosticSink Refused;
    EXPECT_FALSE(Ed.apply(E, Refused));
    EXPECT_TRUE(Refused.hasErrors());
    EXPECT_TRUE(sameGraph(Ed.graph(), *Old));
    EXPECT_EQ(Ed.compiled().ArgsBin, Bin);
  }
}

} // namespace
