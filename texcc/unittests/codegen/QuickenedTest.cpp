// The quickened opcodes of the interp kernel: the interp backend's table (most frequent
// patterns first, capped, opcodes after the function ids; no other backend has one), args.bin's
// opcode words, the kernel's table applied by the graph library's live edits (which never
// choose), layout.json round trip and the reader's checks.

#include "texcc/Codegen/Backend.h"
#include "texcc/Codegen/Quickening.h"
#include "texcc/Graph/Edit.h"

#include "../graph/GraphTestUtil.h"

using namespace texcc::graph;
using namespace texcc::graph::test;
namespace cg = texcc::codegen;

namespace {

/// Functions of every parameter kind the patterns tell apart (float, float3, int).
const SignatureMap &costSigs() {
  static const SignatureMap S = sigs(R"([
    {"name": "lite", "return": "float", "cost": 5, "params": [{"name": "x", "type": "float"},
      {"name": "k", "type": "float"}]},
    {"name": "pair", "return": "float", "cost": 9, "params": [{"name": "a", "type": "float"},
      {"name": "b", "type": "float"}]},
    {"name": "col", "return": "float3", "cost": 40, "params": [{"name": "t", "type": "float"},
      {"name": "c", "type": "float3"}]},
    {"name": "wide", "return": "float3", "cost": 12, "params": [{"name": "v", "type": "float3"}]},
    {"name": "heavy", "return": "float", "cost": 5000, "params": [{"name": "x", "type": "float"}]},
    {"name": "octv", "return": "float", "cost": 5000, "params": [{"name": "x", "type": "float"},
      {"name": "n", "type": "int"}]},
    {"name": "unknown", "return": "float", "params": [{"name": "x", "type": "float"}]}
  ])");
  return S;
}

std::string lite(const std::string &Id, const std::string &From, double K = 1) {
  std::string X = From.empty() ? R"({"attr": "AO"})" : R"({"node": ")" + From + "\"}";
  return R"({"id": ")" + Id + R"(", "fn": "lite", "args": {"x": )" + X +
         ", \"k\": " + std::to_string(K) + "}}";
}

std::string unaryNode(const std::string &Id, const std::string &Fn, const std::string &From) {
  return R"({"id": ")" + Id + R"(", "fn": ")" + Fn + R"(", "args": {"x": {"node": ")" + From +
         "\"}}}";
}

std::string strengthOf(const std::string &Node) {
  return R"({"m": {"bsdf": "emission", "color": 1, "strength": {"node": ")" + Node + "\"}}}";
}

/// A pattern's sources as layout.json spells them.
std::vector<std::string> spelled(const std::vector<ArgumentSource> &Sources) {
  std::vector<std::string> S;
  for (const ArgumentSource &A : Sources)
    S.push_back(spellSource(A));
  return S;
}

/// The fnId words of material M's program in args.bin.
std::vector<uint32_t> opcodes(const CompiledGraph &CG, size_t M = 0) {
  std::vector<uint32_t> W;
  uint32_t At = 4 * CG.Materials[M].ProgramWordOffset;
  for (uint32_t I = 0; I < word(CG.ArgsBin, At); ++I)
    W.push_back(word(CG.ArgsBin, At + 8 + 12 * I));
  return W;
}

/// Compiled as texcc compiles for Mode: the graph library's passes, then the backend's
/// finishGraph (interp chooses at most Max quickened opcodes).
CompiledGraph quickened(const std::string &Json, unsigned Max = 8,
                        cg::Mode Mode = cg::Mode::Interp) {
  CompiledGraph CG = compiled(Json, CompileOptions(), costSigs());
  cg::BackendOptions O;
  O.MaxQuickened = Max;
  cg::backendFor(Mode, cg::Target::OpenCL).finishGraph(CG, O, nullptr);
  return CG;
}

/// E: a live editor of Json's graph started with the kernel's table Table, as texrender's live
/// editor is (the graph library applies the table and never chooses). Fails the test when the
/// graph does not parse or compile (call it in ASSERT_NO_FATAL_FAILURE).
void startEditor(const std::string &Json, std::vector<QuickenedOp> Table,
                 std::optional<GraphEditor> &E) {
  DiagnosticSink D;
  std::optional<Graph> G = parse(Json, D);
  ASSERT_TRUE(G) << text(D);
  CompileOptions Kernel;
  Kernel.Quickened = std::move(Table);
  E.emplace(*G, costSigs(), Kernel);
  ASSERT_TRUE(E->init(D)) << text(D);
}

TEST(Quickened, MostFrequentPatternsFirstCapped) {
  // a and b are lite(attr AO, const), p pair(slot, slot), e lite(slot, const).
  const std::string Json = graphJson(
      {lite("a", "", 1), lite("b", "", 2),
       R"({"id": "p", "fn": "pair", "args": {"a": {"node": "a"}, "b": {"node": "b"}}})",
       lite("e", "p", 5)},
      strengthOf("e"));
  CompiledGraph CG = quickened(Json);
  ASSERT_EQ(CG.Quickened.size(), 3u);
  const unsigned First = static_cast<unsigned>(CG.FunctionsById.size());
  EXPECT_EQ(CG.Quickened[0].Opcode, First);
  EXPECT_EQ(CG.Quickened[0].Fn, "lite");
  EXPECT_EQ(spelled(CG.Quickened[0].Sources), (std::vector<std::string>{"attr:AO", "const"}));
  EXPECT_EQ(CG.Quickened[1].Fn, "pair");
  EXPECT_EQ(spelled(CG.Quickened[1].Sources), (std::vector<std::string>{"slot", "slot"}));
  EXPECT_EQ(CG.Quickened[2].Fn, "lite");
  EXPECT_EQ(spelled(CG.Quickened[2].Sources), (std::vector<std::string>{"slot", "const"}));
  EXPECT_EQ(opcodes(CG), (std::vector<uint32_t>{First, First, First + 1, First + 2}));
  CompiledGraph One = quickened(Json, 1);
  ASSERT_EQ(One.Quickened.size(), 1u);
  EXPECT_EQ(spelled(One.Quickened[0].Sources), (std::vector<std::string>{"attr:AO", "const"}));
  EXPECT_EQ(opcodes(One), (std::vector<uint32_t>{First, First, 1, 0}));
  // The table is chooseQuickened's; 0 chooses none, and only the interp backend quickens.
  EXPECT_EQ(cg::chooseQuickened(compiled(Json, CompileOptions(), costSigs()), 3), CG.Quickened);
  EXPECT_TRUE(cg::chooseQuickened(CG, 0).empty());
  for (cg::Mode M : {cg::Mode::Inline, cg::Mode::Wavefront, cg::Mode::Shape}) {
    CompiledGraph Other = quickened(Json, 8, M);
    EXPECT_TRUE(Other.Quickened.empty()) << cg::modeName(M);
    EXPECT_EQ(opcodes(Other), (std::vector<uint32_t>{0, 0, 1, 0})) << cg::modeName(M);
  }
}

TEST(Quickened, IntConstantsArePartOfThePattern) {
  // Two octv nodes with n = 3 and one with n = 5: two patterns, the int a literal in the case.
  const std::string Json = graphJson(
      {R"({"id": "p", "fn": "octv", "args": {"x": {"attr": "AO"}, "n": 3}})",
       R"({"id": "q", "fn": "octv", "args": {"x": {"node": "p"}, "n": 5}})",
       R"({"id": "r", "fn": "octv", "args": {"x": {"node": "q"}, "n": 3}})",
       R"({"id": "s", "fn": "pair", "args": {"a": {"node": "r"}, "b": {"node": "p"}}})"},
      strengthOf("s"));
  CompiledGraph CG = quickened(Json);
  std::vector<std::vector<std::string>> Octv;
  for (const QuickenedOp &Q : CG.Quickened)
    if (Q.Fn == "octv")
      Octv.push_back(spelled(Q.Sources));
  EXPECT_EQ(Octv, (std::vector<std::vector<std::string>>{{"attr:AO", "int:3"},
                                                          {"slot", "int:5"},
                                                          {"slot", "int:3"}}));
  // A live edit of n (the fast path, a value patched in place) to a value no entry has runs
  // the plain case, with no new kernel; to a value an entry has, that entry's opcode.
  std::optional<GraphEditor> E;
  ASSERT_NO_FATAL_FAILURE(startEditor(Json, CG.Quickened, E));
  DiagnosticSink D;
  auto QuickOf = [&](const std::string &Id) {
    const CompiledGraph &C = E->compiled();
    for (const Instruction &In : C.Materials[0].Program)
      if (C.Nodes[In.Node].Id == Id)
        return In.Quick >= 0 ? spellSource(C.Quickened[In.Quick].Sources.back()) : std::string("plain");
    return std::string("absent");
  };
  EXPECT_EQ(QuickOf("q"), "int:5");
  ASSERT_TRUE(E->setArgument("q", "n", "4", D)) << text(D);
  EXPECT_EQ(QuickOf("q"), "plain");
  EXPECT_FALSE(E->needsRebuild());
  ASSERT_TRUE(E->setArgument("q", "n", "3", D)) << text(D);
  EXPECT_EQ(QuickOf("q"), "int:3");
  EXPECT_FALSE(E->needsRebuild());
}

TEST(Quickened, BroadcastAndTheKernelsTableOnALiveEdit) {
  EXPECT_TRUE(compiled(graphJson({lite("a", "")}, strengthOf("a")), CompileOptions(), costSigs())
                  .Quickened.empty()); // the graph library chooses none
  const std::string Json =
      graphJson({lite("a", ""), lite("b", "", 2),
                 R"({"id": "w", "fn": "wide", "args": {"v": {"node": "a"}}})",
                 R"({"id": "p", "fn": "pair", "args": {"a": {"node": "a"}, "b": {"node": "b"}}})"},
                R"({"m": {"bsdf": "diffuse", "color": {"node": "w"}},
                    "n": {"bsdf": "emission", "color": 1, "strength": {"node": "p"}}})");
  CompiledGraph CG = quickened(Json);
  bool SawBroadcast = false;
  for (const QuickenedOp &Q : CG.Quickened)
    SawBroadcast |= Q.Fn == "wide" && spelled(Q.Sources) == std::vector<std::string>{"slot.x"};
  EXPECT_TRUE(SawBroadcast);
  // A live edit compiles with the kernel's table: an instruction whose pattern changed (p.b
  // rewired from b to a constant) runs its function's plain opcode; the others keep theirs.
  std::optional<GraphEditor> E;
  ASSERT_NO_FATAL_FAILURE(startEditor(Json, CG.Quickened, E));
  DiagnosticSink D;
  EXPECT_EQ(E->compiled().Quickened, CG.Quickened);
  ASSERT_TRUE(E->setArgument("p", "b", "0.5", D)) << text(D);
  const CompiledGraph &After = E->compiled();
  for (const CompiledMaterial &M : After.Materials)
    for (const Instruction &In : M.Program)
      if (After.Nodes[In.Node].Id == "p")
        EXPECT_EQ(In.Quick, -1);
      else
        EXPECT_GE(In.Quick, 0) << After.Nodes[In.Node].Id;
  EXPECT_FALSE(E->needsRebuild());
}

TEST(Quickened, AnEditorKeepsTheTablesItStartedWith) {
  // An editor given the kernel's table keeps it: a rewiring that makes other patterns the most
  // frequent must not choose cases the kernel lacks (the graph library never chooses).
  const std::string Json = graphJson(
      {lite("a", ""), lite("b", "", 2), unaryNode("h", "heavy", "a"),
       R"({"id": "p", "fn": "pair", "args": {"a": {"node": "h"}, "b": {"node": "b"}}})"},
      strengthOf("p"));
  std::optional<GraphEditor> E;
  ASSERT_NO_FATAL_FAILURE(startEditor(Json, quickened(Json, 1).Quickened, E));
  DiagnosticSink D;
  const std::vector<QuickenedOp> Quick = E->compiled().Quickened;
  ASSERT_EQ(Quick.size(), 1u);
  ASSERT_TRUE(E->rewire("p", "a", "b", D)) << text(D);
  ASSERT_TRUE(E->rewire("h", "x", "b", D)) << text(D);
  EXPECT_EQ(E->compiled().Quickened, Quick);
  EXPECT_FALSE(E->needsRebuild());
}

TEST(Quickened, LayoutRoundTrip) {
  CompiledGraph CG = quickened(graphJson({lite("a", ""), lite("b", "a", 2)}, strengthOf("b")));
  ASSERT_FALSE(CG.Quickened.empty());
  std::vector<QuickenedOp> T;
  std::string Error;
  ASSERT_TRUE(readLayoutQuickened(layoutJson(CG), T, Error)) << Error;
  EXPECT_EQ(T, CG.Quickened);
  T.clear();
  // A layout.json around the fields under test (the kernel manifest's required ones).
  auto Manifest = [](const std::string &Fields) {
    return R"({"texcc": 1, "mode": "interp", "kernel": {}, "materials": [], "capabilities": {})" +
           (Fields.empty() ? std::string() : ", " + Fields) + "}";
  };
  EXPECT_TRUE(readLayoutQuickened(Manifest(""), T, Error)); // an older layout.json: none
  EXPECT_TRUE(T.empty());
  EXPECT_FALSE(readLayoutQuickened(Manifest(R"("quickened": [{"opcode": 1}])"), T, Error));
  EXPECT_NE(Error.find("malformed layout.json"), std::string::npos);
  // Entries that would make the editor write an opcode the kernel runs wrongly.
  auto Bad = [&](const std::string &Entry) {
    std::vector<QuickenedOp> Table;
    std::string Why;
    EXPECT_FALSE(readLayoutQuickened(
        Manifest(R"("functions": [{"id": 0, "name": "lite", "params": [{"type": "float"}, {"type": "float"}]},
                          {"id": 3, "name": "octv", "params": [{"type": "float"}, {"type": "int"}]}],
            "superinstructions": [{"opcode": 1, "first": "lite", "second": "lite", "paramIndex": 0}],
            "quickened": [)" + Entry + "]"),
        Table, Why));
    return Why;
  };
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "gone", "sources": []})"),
            "/quickened/0: function 'gone' is not in /functions");
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "lite", "sources": ["const"]})"),
            "/quickened/0: 1 sources for the 2 parameters of 'lite'");
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "lite", "sources": ["const", "attr:Nope"]})"),
            "/quickened/0: source 'attr:Nope' of parameter 1 of 'lite' (expected const, slot, "
            "slot.x, attr:Name, attr:Name.x)");
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "lite", "sources": ["const", "int:3"]})"),
            "/quickened/0: source 'int:3' of parameter 1 of 'lite' (expected const, slot, "
            "slot.x, attr:Name, attr:Name.x)");
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "octv", "sources": ["const", "int:3x"]})"),
            "/quickened/0: source 'int:3x' of parameter 1 of 'octv' (expected const, slot, "
            "slot.x, attr:Name, attr:Name.x or int:N)");
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "octv", "sources": ["const", "int:4294967296"]})"),
            "/quickened/0: source 'int:4294967296' of parameter 1 of 'octv' (expected const, "
            "slot, slot.x, attr:Name, attr:Name.x or int:N)");
  EXPECT_EQ(Bad(R"({"opcode": 1, "function": "lite", "sources": ["const", "slot.x"]})"),
            "/quickened/0: opcode 1 is already a function id, a superinstruction's or another "
            "entry's");
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "lite", "sources": ["const", "fed"]})"),
            "/quickened/0: source 'fed' of parameter 1 of 'lite' (expected const, slot, "
            "slot.x, attr:Name, attr:Name.x)");
  // And the entries it takes: an int value; a quickened superinstruction of an older texcc
  // (superinstructions were removed: edits never encode it) is left out, its opcode taken.
  std::vector<QuickenedOp> Good;
  ASSERT_TRUE(readLayoutQuickened(
      Manifest(R"("functions": [{"id": 0, "name": "lite", "params": [{"type": "float"}, {"type": "float"}]},
                        {"id": 3, "name": "octv", "params": [{"type": "float"}, {"type": "int"}]}],
          "superinstructions": [{"opcode": 1, "first": "lite", "second": "lite", "paramIndex": 0}],
          "quickened": [{"opcode": 2, "function": "octv", "sources": ["slot", "int:-2"]},
                        {"opcode": 4, "function": "lite", "sources": ["attr:AO", "const"],
                         "second": {"function": "lite", "paramIndex": 0,
                                    "sources": ["fed", "slot.x"]}}])"),
      Good, Error))
      << Error;
  ASSERT_EQ(Good.size(), 1u);
  EXPECT_EQ(spellSource(Good[0].Sources.back()), "int:-2");
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "lite", "sources": ["const", "const"],
                    "second": {"function": "lite", "paramIndex": 0, "sources": ["fed", "const"]}},
                   {"opcode": 2, "function": "lite", "sources": ["const", "slot"]})"),
            "/quickened/1: opcode 2 is already a function id, a superinstruction's or another "
            "entry's");
}

TEST(Quickened, SourcesSpellAndParseBack) {
  // The one place the layout.json text is read and written: every kind round-trips, typed.
  for (const char *Text : {"const", "int:0", "int:-2147483648", "int:2147483647", "slot", "slot.x",
                           "attr:AO", "attr:Normal.x", "attr:TexCoord0"}) {
    ArgumentSource S;
    ASSERT_TRUE(parseSource(Text, S)) << Text;
    EXPECT_EQ(spellSource(S), Text);
  }
  ArgumentSource S;
  ASSERT_TRUE(parseSource("attr:Normal.x", S));
  EXPECT_EQ(S.K, ArgumentSource::Kind::Attribute);
  EXPECT_EQ(S.AttrId, attributeId("Normal"));
  EXPECT_TRUE(S.Broadcast);
  ASSERT_TRUE(parseSource("int:-7", S));
  EXPECT_EQ(S.K, ArgumentSource::Kind::IntValue);
  EXPECT_EQ(S.Value, -7);
  for (const char *Bad : {"", "int:", "int:3x", "int:2147483648", "attr:Nope", "slot.y", "fed",
                          "const.x", "Slot"})
    EXPECT_FALSE(parseSource(Bad, S)) << Bad;
}

} // namespace
