// The superinstruction pass: which adjacent pairs fuse (a single reader, light functions),
// the table (most frequent first, capped, dead entries dropped, opcodes after the function ids),
// args.bin's opcode words, the kernel's table applied by live edits, layout.json round trip.
// Also the quickened opcodes (same machinery: a table of patterns, opcodes after the
// superinstructions', applied by live edits).

#include "texcc/Graph/Edit.h"

#include "GraphTestUtil.h"

using namespace texcc::graph;
using namespace texcc::graph::test;

namespace {

/// Light functions (cost 5..40) and a heavy one (cost 5000).
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

CompileOptions fusing(unsigned Max = 8) {
  CompileOptions O;
  O.MaxSuperinstructions = Max;
  return O;
}

/// The fnId words of material M's program in args.bin.
std::vector<uint32_t> opcodes(const CompiledGraph &CG, size_t M = 0) {
  std::vector<uint32_t> W;
  uint32_t At = 4 * CG.Materials[M].ProgramWordOffset;
  for (uint32_t I = 0; I < word(CG.ArgsBin, At); ++I)
    W.push_back(word(CG.ArgsBin, At + 8 + 12 * I));
  return W;
}

TEST(Superinstructions, ChainFusesPairsGreedily) {
  // a -> b -> c -> d -> e: (a, b) and (c, d) fuse, e is left alone.
  CompiledGraph CG = compiled(graphJson({lite("a", "", 1), lite("b", "a", 2), lite("c", "b", 3),
                                         lite("d", "c", 4), lite("e", "d", 5)},
                                        strengthOf("e")),
                              fusing(), costSigs());
  ASSERT_EQ(CG.Superinstructions.size(), 1u);
  const Superinstruction &S = CG.Superinstructions[0];
  EXPECT_EQ(S.Opcode, CG.FunctionsById.size()); // after the function ids
  EXPECT_EQ(S.First, "lite");
  EXPECT_EQ(S.Second, "lite");
  EXPECT_EQ(S.Param, 0u);
  EXPECT_EQ(fedParamName(CG, S), "x");
  std::vector<int> Marks;
  for (const Instruction &In : CG.Materials[0].Program)
    Marks.push_back(In.Super);
  EXPECT_EQ(Marks, (std::vector<int>{0, -1, 0, -1, -1}));
  EXPECT_EQ(opcodes(CG), (std::vector<uint32_t>{1, 0, 1, 0, 0}));
}

TEST(Superinstructions, OffByDefault) {
  CompiledGraph CG = compiled(graphJson({lite("a", ""), lite("b", "a", 2)}, strengthOf("b")),
                              CompileOptions(), costSigs());
  EXPECT_TRUE(CG.Superinstructions.empty());
  EXPECT_EQ(opcodes(CG), (std::vector<uint32_t>{0, 0}));
}

TEST(Superinstructions, ASecondReaderOrAnOutputKeepsTheValueOnTheStack) {
  // a is read by b and by c; b is an output of m as well as read by c.
  CompiledGraph CG = compiled(
      graphJson({lite("a", ""), lite("b", "a", 2),
                 R"({"id": "c", "fn": "pair", "args": {"a": {"node": "b"}, "b": {"node": "a"}}})"},
                R"({"m": {"bsdf": "blend", "mask": {"node": "b"},
                    "a": {"bsdf": "emission", "color": 1, "strength": {"node": "c"}},
                    "b": {"bsdf": "diffuse", "color": 1}}})"),
      fusing(), costSigs());
  EXPECT_TRUE(CG.Superinstructions.empty());
  for (const Instruction &In : CG.Materials[0].Program)
    EXPECT_EQ(In.Super, -1);
}

TEST(Superinstructions, ReadTwiceByTheSecondIsNotFused) {
  CompiledGraph CG = compiled(
      graphJson({lite("a", ""),
                 R"({"id": "p", "fn": "pair", "args": {"a": {"node": "a"}, "b": {"node": "a"}}})"},
                strengthOf("p")),
      fusing(), costSigs());
  EXPECT_TRUE(CG.Superinstructions.empty());
}

TEST(Superinstructions, OnlyLightFunctionsFuse) {
  // heavy -> lite and lite -> heavy stay apart; a function of unknown cost (0) is not light.
  CompiledGraph CG =
      compiled(graphJson({lite("a", ""), unaryNode("h", "heavy", "a"), lite("b", "h"),
                          unaryNode("u", "unknown", "b"), lite("c", "u")},
                         strengthOf("c")),
               fusing(), costSigs());
  EXPECT_TRUE(CG.Superinstructions.empty());
  CompileOptions Loose = fusing();
  Loose.LightCost = 5000;
  CG = compiled(graphJson({lite("a", ""), unaryNode("h", "heavy", "a")}, strengthOf("h")), Loose,
                costSigs());
  ASSERT_EQ(CG.Superinstructions.size(), 1u);
  EXPECT_EQ(CG.Superinstructions[0].Second, "heavy");
}

TEST(Superinstructions, MostFrequentFirstCappedAndDeadEntriesDropped) {
  // Material m1: lite -> lite three times (six nodes); m2: lite -> col.t once, and a chain
  // lite -> lite -> col where (lite, lite) wins the overlap, so (lite, col.t) fuses in m2 only.
  std::vector<std::string> Nodes;
  for (int I = 0; I < 3; ++I) {
    std::string A = "a" + std::to_string(I), B = "b" + std::to_string(I);
    Nodes.push_back(lite(A, "", 10 + I));
    Nodes.push_back(lite(B, A, 20 + I));
  }
  Nodes.push_back(R"({"id": "s", "fn": "pair", "args": {"a": {"node": "b0"}, "b": {"node": "b1"}}})");
  Nodes.push_back(R"({"id": "s2", "fn": "pair", "args": {"a": {"node": "s"}, "b": {"node": "b2"}}})");
  Nodes.push_back(lite("q", "", 30));
  Nodes.push_back(R"({"id": "k", "fn": "col", "args": {"t": {"node": "q"}, "c": [1, 2, 3]}})");
  std::string Materials = R"({"m1": {"bsdf": "emission", "color": 1, "strength": {"node": "s2"}},
                              "m2": {"bsdf": "diffuse", "color": {"node": "k"}}})";
  CompiledGraph CG = compiled(graphJson(Nodes, Materials), fusing(), costSigs());
  ASSERT_EQ(CG.Superinstructions.size(), 2u);
  EXPECT_EQ(CG.Superinstructions[0].Second, "lite"); // three times
  EXPECT_EQ(CG.Superinstructions[1].Second, "col");  // once
  EXPECT_EQ(CG.Superinstructions[0].Opcode, CG.FunctionsById.size());
  EXPECT_EQ(CG.Superinstructions[1].Opcode, CG.FunctionsById.size() + 1);
  CG = compiled(graphJson(Nodes, Materials), fusing(1), costSigs());
  ASSERT_EQ(CG.Superinstructions.size(), 1u);
  EXPECT_EQ(CG.Superinstructions[0].Second, "lite");

  // a -> b -> w: (a, b) takes b, so (b, w) never fuses and is not in the table.
  CG = compiled(graphJson({lite("a", ""), lite("b", "a", 2),
                           R"({"id": "w", "fn": "col", "args": {"t": {"node": "b"}, "c": [1, 1, 1]}})"},
                          R"({"m": {"bsdf": "diffuse", "color": {"node": "w"}}})"),
                fusing(), costSigs());
  ASSERT_EQ(CG.Superinstructions.size(), 1u);
  EXPECT_EQ(CG.Superinstructions[0].Second, "lite");
}

TEST(Superinstructions, BroadcastPairsFuse) {
  // A float feeding a float3 parameter (the source word's broadcast bit is set).
  CompiledGraph CG =
      compiled(graphJson({lite("a", ""), R"({"id": "w", "fn": "wide", "args": {"v": {"node": "a"}}})"},
                         R"({"m": {"bsdf": "diffuse", "color": {"node": "w"}}})"),
               fusing(), costSigs());
  ASSERT_EQ(CG.Superinstructions.size(), 1u);
  EXPECT_TRUE(CG.Nodes[CG.findNode("w")].Args[0].Broadcast);
}

TEST(Superinstructions, AFixedTableIsAppliedWhereItsPairsOccur) {
  // The kernel's table (live edits): used as given, opcodes and all, nothing else chosen.
  CompileOptions Opts;
  Opts.Superinstructions = {{7, "lite", "col", 0}, {9, "pair", "lite", 0}};
  Opts.MaxSuperinstructions = 8; // ignored: the table is given
  CompiledGraph CG = compiled(
      graphJson({lite("a", ""), lite("b", "a", 2),
                 R"({"id": "w", "fn": "col", "args": {"t": {"node": "b"}, "c": [1, 1, 1]}})"},
                R"({"m": {"bsdf": "diffuse", "color": {"node": "w"}}})"),
      Opts, costSigs());
  EXPECT_EQ(CG.Superinstructions, Opts.Superinstructions); // unused entries stay
  EXPECT_EQ(opcodes(CG), (std::vector<uint32_t>{0, 7, 1}));
}

TEST(Superinstructions, LiveEditEmitsPlainOpcodesWhereARewiringBreaksAPair) {
  // m1: a -> b -> p; m2 needs two slots (c and d live together), so the rewiring below fits
  // the kernel's value stack.
  const std::string Json = graphJson(
      {lite("a", ""), lite("b", "a", 2),
       R"({"id": "p", "fn": "pair", "args": {"a": {"node": "b"}, "b": 0.5}})", lite("c", "", 3),
       lite("d", "", 4), R"({"id": "q", "fn": "pair", "args": {"a": {"node": "c"}, "b": {"node": "d"}}})"},
      R"({"m1": {"bsdf": "emission", "color": 1, "strength": {"node": "p"}},
          "m2": {"bsdf": "emission", "color": 1, "strength": {"node": "q"}}})");
  // What texcc chose: lite -> lite.x (a, b) and lite -> pair.b (d, q); lite -> pair.a (b, p)
  // lost to (a, b) and was dropped.
  CompiledGraph Kernel = compiled(Json, fusing(), costSigs());
  ASSERT_EQ(Kernel.Superinstructions.size(), 2u);
  EXPECT_EQ(Kernel.StackSlots, 2u);
  EXPECT_EQ(opcodes(Kernel, 0), (std::vector<uint32_t>{2, 0, 1}));
  EXPECT_EQ(opcodes(Kernel, 1), (std::vector<uint32_t>{0, 3, 1}));

  DiagnosticSink D;
  auto G = parse(Json, D);
  ASSERT_TRUE(G) << text(D);
  CompileOptions Opts;
  std::string Error;
  SignatureMap Sigs;
  std::string Layout = layoutJson(Kernel);
  ASSERT_TRUE(readLayoutSignatures(Layout, Sigs, Opts.FixedFunctionIds, Error)) << Error;
  ASSERT_TRUE(readLayoutSuperinstructions(Layout, Opts.Superinstructions, Error)) << Error;
  EXPECT_EQ(Opts.Superinstructions, Kernel.Superinstructions);
  EXPECT_EQ(Sigs.at("lite").Cost, 5u);
  GraphEditor E(*G, Sigs, Opts);
  ASSERT_TRUE(E.init(D)) << text(D);
  EXPECT_EQ(E.compiled().ArgsBin, Kernel.ArgsBin);

  // p.b reads a too: a has two readers, so (a, b) runs as two plain instructions; m2 keeps
  // its superinstruction.
  ASSERT_TRUE(E.rewire("p", "b", "a", D)) << text(D);
  EXPECT_FALSE(E.needsRebuild());
  EXPECT_EQ(opcodes(E.compiled(), 0), (std::vector<uint32_t>{0, 0, 1}));
  EXPECT_EQ(opcodes(E.compiled(), 1), (std::vector<uint32_t>{0, 3, 1}));
  // Back to a constant: the pair fuses again with the kernel's opcode.
  ASSERT_TRUE(E.setArgument("p", "b", "0.5", D)) << text(D);
  EXPECT_EQ(opcodes(E.compiled(), 0), (std::vector<uint32_t>{2, 0, 1}));
}

TEST(Superinstructions, ATableOpcodeIsNeverGivenToAFunction) {
  CompiledGraph CG = resolved(graphJson({lite("a", ""), unaryNode("h", "heavy", "a")},
                                        strengthOf("h")),
                              costSigs());
  CompileOptions Opts;
  Opts.FixedFunctionIds = {{"lite", 0}};
  Opts.Superinstructions = {{1, "lite", "lite", 0}};
  assignFunctionIds(CG, costSigs(), Opts, nullptr);
  EXPECT_EQ(CG.Nodes[CG.findNode("h")].FnId, 2u);
}

TEST(Superinstructions, LayoutWithoutATableReadsAsEmpty) {
  std::vector<Superinstruction> T;
  std::string Error;
  EXPECT_TRUE(readLayoutSuperinstructions(R"({"functions": []})", T, Error));
  EXPECT_TRUE(T.empty());
  EXPECT_FALSE(readLayoutSuperinstructions(R"({"superinstructions": [{"opcode": 1}]})", T, Error));
  EXPECT_NE(Error.find("malformed layout.json"), std::string::npos);
}

CompileOptions quickening(unsigned Max = 8) {
  CompileOptions O;
  O.MaxQuickened = Max;
  return O;
}

TEST(Quickened, MostFrequentPatternsFirstCapped) {
  // a and b are lite(attr AO, const), p pair(slot, slot), e lite(slot, const).
  const std::string Json = graphJson(
      {lite("a", "", 1), lite("b", "", 2),
       R"({"id": "p", "fn": "pair", "args": {"a": {"node": "a"}, "b": {"node": "b"}}})",
       lite("e", "p", 5)},
      strengthOf("e"));
  CompiledGraph CG = compiled(Json, quickening(), costSigs());
  ASSERT_EQ(CG.Quickened.size(), 3u);
  const unsigned First = static_cast<unsigned>(CG.FunctionsById.size());
  EXPECT_EQ(CG.Quickened[0].Opcode, First);
  EXPECT_EQ(CG.Quickened[0].Fn, "lite");
  EXPECT_EQ(CG.Quickened[0].Sources, (std::vector<std::string>{"attr:AO", "const"}));
  EXPECT_EQ(CG.Quickened[1].Fn, "pair");
  EXPECT_EQ(CG.Quickened[1].Sources, (std::vector<std::string>{"slot", "slot"}));
  EXPECT_EQ(CG.Quickened[2].Fn, "lite");
  EXPECT_EQ(CG.Quickened[2].Sources, (std::vector<std::string>{"slot", "const"}));
  EXPECT_EQ(opcodes(CG), (std::vector<uint32_t>{First, First, First + 1, First + 2}));
  CompiledGraph One = compiled(Json, quickening(1), costSigs());
  ASSERT_EQ(One.Quickened.size(), 1u);
  EXPECT_EQ(One.Quickened[0].Sources, (std::vector<std::string>{"attr:AO", "const"}));
  EXPECT_EQ(opcodes(One), (std::vector<uint32_t>{First, First, 1, 0}));
}

TEST(Quickened, SuperinstructionPairsHaveTheirOwnPatterns) {
  // a -> b fuses (both light): the pair's pattern is both halves' sources, the fed parameter
  // "fed"; its opcode (after the superinstruction's) replaces the superinstruction's in
  // args.bin, and b, the second half, has none of its own. Heavy h never fuses.
  CompileOptions O = fusing();
  O.MaxQuickened = 8;
  CompiledGraph CG = compiled(
      graphJson({lite("a", ""), lite("b", "a", 2), unaryNode("h", "heavy", "b")},
                strengthOf("h")),
      O, costSigs());
  ASSERT_EQ(CG.Superinstructions.size(), 1u);
  ASSERT_EQ(CG.Quickened.size(), 2u);
  const unsigned First = static_cast<unsigned>(CG.FunctionsById.size() + 1);
  EXPECT_EQ(CG.Quickened[0].Opcode, First);
  EXPECT_EQ(CG.Quickened[0].Fn, "lite");
  EXPECT_EQ(CG.Quickened[0].Sources, (std::vector<std::string>{"attr:AO", "const"}));
  EXPECT_EQ(CG.Quickened[0].Second, "lite");
  EXPECT_EQ(CG.Quickened[0].Param, 0u);
  EXPECT_EQ(CG.Quickened[0].SecondSources, (std::vector<std::string>{"fed", "const"}));
  EXPECT_EQ(CG.Quickened[1].Fn, "heavy");
  EXPECT_TRUE(CG.Quickened[1].Second.empty());
  std::vector<int> Quick;
  for (const Instruction &In : CG.Materials[0].Program)
    Quick.push_back(In.Quick);
  EXPECT_EQ(Quick, (std::vector<int>{0, -1, 1}));
  EXPECT_EQ(CG.Materials[0].Program[0].Super, 0); // still a superinstruction: b is skipped
  const uint32_t Plain = CG.Nodes[CG.Materials[0].Program[1].Node].FnId;
  EXPECT_EQ(opcodes(CG), (std::vector<uint32_t>{First, Plain, First + 1}));
}

TEST(Quickened, IntConstantsArePartOfThePattern) {
  // Two octv nodes with n = 3 and one with n = 5: two patterns, the int a literal in the case.
  const std::string Json = graphJson(
      {R"({"id": "p", "fn": "octv", "args": {"x": {"attr": "AO"}, "n": 3}})",
       R"({"id": "q", "fn": "octv", "args": {"x": {"node": "p"}, "n": 5}})",
       R"({"id": "r", "fn": "octv", "args": {"x": {"node": "q"}, "n": 3}})",
       R"({"id": "s", "fn": "pair", "args": {"a": {"node": "r"}, "b": {"node": "p"}}})"},
      strengthOf("s"));
  CompiledGraph CG = compiled(Json, quickening(), costSigs());
  std::vector<std::vector<std::string>> Octv;
  for (const QuickenedOp &Q : CG.Quickened)
    if (Q.Fn == "octv")
      Octv.push_back(Q.Sources);
  EXPECT_EQ(Octv, (std::vector<std::vector<std::string>>{{"attr:AO", "int:3"},
                                                          {"slot", "int:5"},
                                                          {"slot", "int:3"}}));
  // A live edit of n (the fast path, a value patched in place) to a value no entry has runs
  // the plain case, with no new kernel; to a value an entry has, that entry's opcode.
  DiagnosticSink D;
  std::optional<Graph> G = parse(Json, D);
  ASSERT_TRUE(G) << text(D);
  CompileOptions Kernel;
  Kernel.Quickened = CG.Quickened;
  GraphEditor E(*G, costSigs(), Kernel);
  ASSERT_TRUE(E.init(D)) << text(D);
  auto QuickOf = [&](const std::string &Id) {
    const CompiledGraph &C = E.compiled();
    for (const Instruction &In : C.Materials[0].Program)
      if (C.Nodes[In.Node].Id == Id)
        return In.Quick >= 0 ? C.Quickened[In.Quick].Sources.back() : std::string("plain");
    return std::string("absent");
  };
  EXPECT_EQ(QuickOf("q"), "int:5");
  ASSERT_TRUE(E.setArgument("q", "n", "4", D)) << text(D);
  EXPECT_EQ(QuickOf("q"), "plain");
  EXPECT_FALSE(E.needsRebuild());
  ASSERT_TRUE(E.setArgument("q", "n", "3", D)) << text(D);
  EXPECT_EQ(QuickOf("q"), "int:3");
  EXPECT_FALSE(E.needsRebuild());
}

TEST(Quickened, BroadcastAndTheKernelsTableOnALiveEdit) {
  EXPECT_TRUE(compiled(graphJson({lite("a", "")}, strengthOf("a")), fusing(), costSigs())
                  .Quickened.empty()); // off unless asked for
  const std::string Json =
      graphJson({lite("a", ""), lite("b", "", 2),
                 R"({"id": "w", "fn": "wide", "args": {"v": {"node": "a"}}})",
                 R"({"id": "p", "fn": "pair", "args": {"a": {"node": "a"}, "b": {"node": "b"}}})"},
                R"({"m": {"bsdf": "diffuse", "color": {"node": "w"}},
                    "n": {"bsdf": "emission", "color": 1, "strength": {"node": "p"}}})");
  CompiledGraph CG = compiled(Json, quickening(), costSigs());
  bool SawBroadcast = false;
  for (const QuickenedOp &Q : CG.Quickened)
    SawBroadcast |= Q.Fn == "wide" && Q.Sources == std::vector<std::string>{"slot.x"};
  EXPECT_TRUE(SawBroadcast);
  // A live edit compiles with the kernel's table: an instruction whose pattern changed (p.b
  // rewired from b to a constant) runs its function's plain opcode; the others keep theirs.
  DiagnosticSink D;
  std::optional<Graph> G = parse(Json, D);
  ASSERT_TRUE(G) << text(D);
  CompileOptions Kernel;
  Kernel.Quickened = CG.Quickened;
  Kernel.Superinstructions = CG.Superinstructions;
  GraphEditor E(*G, costSigs(), Kernel);
  ASSERT_TRUE(E.init(D)) << text(D);
  EXPECT_EQ(E.compiled().Quickened, CG.Quickened);
  ASSERT_TRUE(E.setArgument("p", "b", "0.5", D)) << text(D);
  const CompiledGraph &After = E.compiled();
  for (const CompiledMaterial &M : After.Materials)
    for (const Instruction &In : M.Program)
      if (After.Nodes[In.Node].Id == "p")
        EXPECT_EQ(In.Quick, -1);
      else if (In.Super < 0)
        EXPECT_GE(In.Quick, 0) << After.Nodes[In.Node].Id;
  EXPECT_FALSE(E.needsRebuild());
}

TEST(Quickened, AnEditorKeepsTheTablesItStartedWith) {
  // An editor given no tables, only the limits, pins what its first compile chose: a rewiring
  // that makes other patterns the most frequent must not choose cases the kernel lacks.
  const std::string Json = graphJson(
      {lite("a", ""), lite("b", "", 2), unaryNode("h", "heavy", "a"),
       R"({"id": "p", "fn": "pair", "args": {"a": {"node": "h"}, "b": {"node": "b"}}})"},
      strengthOf("p"));
  DiagnosticSink D;
  std::optional<Graph> G = parse(Json, D);
  ASSERT_TRUE(G) << text(D);
  CompileOptions O = fusing();
  O.MaxQuickened = 1;
  GraphEditor E(*G, costSigs(), O);
  ASSERT_TRUE(E.init(D)) << text(D);
  const std::vector<QuickenedOp> Quick = E.compiled().Quickened;
  const std::vector<Superinstruction> Super = E.compiled().Superinstructions;
  ASSERT_EQ(Quick.size(), 1u);
  ASSERT_TRUE(E.rewire("p", "a", "b", D)) << text(D);
  ASSERT_TRUE(E.rewire("h", "x", "b", D)) << text(D);
  EXPECT_EQ(E.compiled().Quickened, Quick);
  EXPECT_EQ(E.compiled().Superinstructions, Super);
  EXPECT_FALSE(E.needsRebuild());
}

TEST(Quickened, LayoutRoundTrip) {
  CompiledGraph CG = compiled(graphJson({lite("a", ""), lite("b", "a", 2)}, strengthOf("b")),
                              quickening(), costSigs());
  ASSERT_FALSE(CG.Quickened.empty());
  std::vector<QuickenedOp> T;
  std::string Error;
  ASSERT_TRUE(readLayoutQuickened(layoutJson(CG), T, Error)) << Error;
  EXPECT_EQ(T, CG.Quickened);
  T.clear();
  EXPECT_TRUE(readLayoutQuickened("{}", T, Error)); // an older layout.json: none
  EXPECT_TRUE(T.empty());
  EXPECT_FALSE(readLayoutQuickened(R"({"quickened": [{"opcode": 1}]})", T, Error));
  EXPECT_NE(Error.find("malformed layout.json"), std::string::npos);
  // Entries that would make the editor write an opcode the kernel runs wrongly.
  auto Bad = [](const std::string &Entry) {
    std::vector<QuickenedOp> Table;
    std::string Why;
    EXPECT_FALSE(readLayoutQuickened(
        R"({"functions": [{"id": 0, "name": "lite", "params": [{"type": "float"}, {"type": "float"}]},
                          {"id": 3, "name": "octv", "params": [{"type": "float"}, {"type": "int"}]}],
            "superinstructions": [{"opcode": 1, "first": "lite", "second": "lite", "paramIndex": 0}],
            "quickened": [)" + Entry + "]}",
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
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "lite", "sources": ["const", "const"],
                    "second": {"function": "lite", "paramIndex": 1, "sources": ["const", "fed"]}})"),
            "/quickened/0: no superinstruction 'lite' -> 'lite' (parameter 1) in "
            "/superinstructions");
  EXPECT_EQ(Bad(R"({"opcode": 2, "function": "lite", "sources": ["const", "const"],
                    "second": {"function": "lite", "paramIndex": 0, "sources": ["slot", "fed"]}})"),
            "/quickened/0: second: source 'slot' of parameter 0 of 'lite' (expected fed)");
  // And the entries it takes: an int value, a pair.
  std::vector<QuickenedOp> Good;
  ASSERT_TRUE(readLayoutQuickened(
      R"({"functions": [{"id": 0, "name": "lite", "params": [{"type": "float"}, {"type": "float"}]},
                        {"id": 3, "name": "octv", "params": [{"type": "float"}, {"type": "int"}]}],
          "superinstructions": [{"opcode": 1, "first": "lite", "second": "lite", "paramIndex": 0}],
          "quickened": [{"opcode": 2, "function": "octv", "sources": ["slot", "int:-2"]},
                        {"opcode": 4, "function": "lite", "sources": ["attr:AO", "const"],
                         "second": {"function": "lite", "paramIndex": 0,
                                    "sources": ["fed", "slot.x"]}}]})",
      Good, Error))
      << Error;
  ASSERT_EQ(Good.size(), 2u);
  EXPECT_EQ(Good[0].Sources.back(), "int:-2");
  EXPECT_EQ(Good[1].Second, "lite");
  EXPECT_EQ(Good[1].SecondSources, (std::vector<std::string>{"fed", "slot.x"}));
}

} // namespace
