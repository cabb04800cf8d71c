// GraphEditor: a parameter edit changes args.bin only at that argument's bytes; structural
// edits recompile; needsRebuild says when the kernel cannot run the result.

#include "texcc/Graph/Edit.h"

#include "GraphTestUtil.h"

using namespace texcc::graph;
using namespace texcc::graph::test;

namespace {

const char *EditGraph = R"({"texcc": 1, "nodes": [
  {"id": "n", "fn": "fbm3", "args": {"p": {"attr": "ObjectPos"}, "scale": 4.0, "octaves": 6}},
  {"id": "r", "fn": "ramp", "args": {"t": {"node": "n"},
    "stops": [[0, 0.35, 0.12, 0.05], [1, 0.6, 0.3, 0.1]], "count": 2}},
  {"id": "m", "fn": "mix3", "args": {"a": {"node": "r"}, "b": [0.1, 0.2, 0.3], "t": 0.5}},
  {"id": "a", "fn": "leaf", "args": {"x": 1}},
  {"id": "a2", "fn": "leaf", "args": {"x": 1}},
  {"id": "s", "fn": "add", "args": {"a": {"node": "a"}, "b": {"node": "a2"}}},
  {"id": "u", "fn": "neg", "args": {"x": 3}},
  {"id": "x", "fn": "add", "args": {"a": 1, "b": 2}},
  {"id": "y", "fn": "add", "args": {"a": 3, "b": 4}},
  {"id": "xy", "fn": "add", "args": {"a": {"node": "x"}, "b": {"node": "y"}}}],
  "materials": {
    "one": {"bsdf": "blend", "mask": {"node": "s"},
      "a": {"bsdf": "diffuse", "color": {"node": "m"}},
      "b": {"bsdf": "glossy", "color": 1, "roughness": {"node": "n"}}},
    "two": {"bsdf": "emission", "color": 1, "strength": {"node": "x"}}}})";

GraphEditor makeEditor() {
  DiagnosticSink D;
  auto G = parse(EditGraph, D);
  EXPECT_TRUE(G) << text(D);
  GraphEditor E(*G, stdSigs(), CompileOptions());
  EXPECT_TRUE(E.init(D)) << text(D);
  return E;
}

/// The byte offsets where two buffers differ.
std::vector<uint32_t> changedBytes(const std::vector<uint8_t> &A, const std::vector<uint8_t> &B) {
  EXPECT_EQ(A.size(), B.size());
  std::vector<uint32_t> Changed;
  for (size_t I = 0; I < std::min(A.size(), B.size()); ++I)
    if (A[I] != B[I])
      Changed.push_back(static_cast<uint32_t>(I));
  return Changed;
}

/// Every changed byte lies in [Begin, Begin + Size).
void expectOnlyIn(const std::vector<uint32_t> &Changed, uint32_t Begin, uint32_t Size) {
  EXPECT_FALSE(Changed.empty());
  for (uint32_t B : Changed) {
    EXPECT_GE(B, Begin);
    EXPECT_LT(B, Begin + Size);
  }
}

const CompiledArg &argOf(const CompiledGraph &CG, const std::string &Node,
                         const std::string &Arg) {
  const CompiledNode &N = CG.Nodes[CG.findNode(Node)];
  for (const CompiledArg &A : N.Args)
    if (A.Name == Arg)
      return A;
  ADD_FAILURE() << Node << "." << Arg;
  return N.Args.front();
}

uint32_t argByte(const CompiledGraph &CG, const std::string &Node, const std::string &Arg) {
  const CompiledNode &N = CG.Nodes[CG.findNode(Node)];
  return parameterBlockStart(N, N.RecordOffset) + argOf(CG, Node, Arg).BlockOffset;
}

TEST(GraphEditor, ScalarEditChangesOnlyItsBytes) {
  GraphEditor E = makeEditor();
  std::vector<uint8_t> Before = E.compiled().ArgsBin;
  DiagnosticSink D;
  ASSERT_TRUE(E.setArgument("n", "scale", "0.5", D)) << text(D);
  std::vector<uint32_t> Changed = changedBytes(Before, E.compiled().ArgsBin);
  expectOnlyIn(Changed, argByte(E.compiled(), "n", "scale"), 4);
  EXPECT_EQ(floatAt(E.compiled().ArgsBin, argByte(E.compiled(), "n", "scale")), 0.5f);
  EXPECT_FALSE(E.needsRebuild());
  // The graph is updated too.
  EXPECT_EQ(E.graph().findNode("n")->Args[1].second.Numbers, std::vector<double>{0.5});
}

TEST(GraphEditor, IntAndVectorEdits) {
  GraphEditor E = makeEditor();
  DiagnosticSink D;
  std::vector<uint8_t> Before = E.compiled().ArgsBin;
  ASSERT_TRUE(E.setArgument("n", "octaves", "3", D)) << text(D);
  expectOnlyIn(changedBytes(Before, E.compiled().ArgsBin), argByte(E.compiled(), "n", "octaves"),
               4);
  EXPECT_EQ(word(E.compiled().ArgsBin, argByte(E.compiled(), "n", "octaves")), 3u);
  Before = E.compiled().ArgsBin;
  ASSERT_TRUE(E.setArgument("m", "b", "[1,0,0]", D)) << text(D);
  expectOnlyIn(changedBytes(Before, E.compiled().ArgsBin), argByte(E.compiled(), "m", "b"), 12);
  Before = E.compiled().ArgsBin;
  ASSERT_TRUE(E.setArgument("m", "b", "0.25", D)) << text(D); // broadcast
  expectOnlyIn(changedBytes(Before, E.compiled().ArgsBin), argByte(E.compiled(), "m", "b"), 12);
  EXPECT_EQ(floatAt(E.compiled().ArgsBin, argByte(E.compiled(), "m", "b") + 8), 0.25f);
}

TEST(GraphEditor, ArrayEditOfTheSameLengthChangesOnlyTheElements) {
  GraphEditor E = makeEditor();
  DiagnosticSink D;
  std::vector<uint8_t> Before = E.compiled().ArgsBin;
  ASSERT_TRUE(E.setArgument("r", "stops", "[[0,0.3,0.1,0.05],[1,0.6,0.3,0.1]]", D)) << text(D);
  const CompiledArg &Stops = argOf(E.compiled(), "r", "stops");
  expectOnlyIn(changedBytes(Before, E.compiled().ArgsBin), Stops.ArrayByteOffset, 2 * 16);
  EXPECT_FALSE(E.needsRebuild());
}

TEST(GraphEditor, ArrayOfAnotherLengthReLaysOut) {
  GraphEditor E = makeEditor();
  DiagnosticSink D;
  size_t Size = E.compiled().ArgsBin.size();
  ASSERT_TRUE(E.setArgument("r", "stops", "[[0,0,0,0],[0.5,1,1,1],[1,1,1,1]]", D)) << text(D);
  EXPECT_EQ(argOf(E.compiled(), "r", "stops").ArrayCount, 3u);
  EXPECT_EQ(E.compiled().ArgsBin.size(), Size + 16);
  EXPECT_FALSE(E.needsRebuild());
}

TEST(GraphEditor, EditOfAMergedTwinSplitsIt) {
  GraphEditor E = makeEditor();
  ASSERT_EQ(E.compiled().findNode("a2"), E.compiled().findNode("a"));
  DiagnosticSink D;
  ASSERT_TRUE(E.setArgument("a2", "x", "2", D)) << text(D);
  EXPECT_NE(E.compiled().findNode("a2"), E.compiled().findNode("a"));
  EXPECT_FALSE(E.needsRebuild()); // add(a, a2) needs 2 slots, as the 'one' program did
}

TEST(GraphEditor, BadValuesAreErrorsAndChangeNothing) {
  GraphEditor E = makeEditor();
  std::vector<uint8_t> Before = E.compiled().ArgsBin;
  DiagnosticSink D;
  EXPECT_FALSE(E.setArgument("n", "octaves", "2.5", D));
  EXPECT_FALSE(E.setArgument("n", "scale", "[1,", D));
  EXPECT_FALSE(E.setArgument("m", "b", "[1,0]", D));
  EXPECT_FALSE(E.setArgument("nn", "scale", "1", D));
  EXPECT_FALSE(E.setArgument("n", "scal", "1", D));
  EXPECT_EQ(text(D),
            "n.octaves:1:1: error: node 'n': argument 'octaves' expects int, got a number "
            "(2.5 is not an int) [/nodes/0/args/octaves]\n"
            "n.scale:1:4: error: expected a value or ']', got end of file\n"
            "m.b:1:1: error: node 'm': argument 'b' expects float3, got a vector of 2 numbers "
            "[1, 0] [/nodes/2/args/b]\n"
            "error: unknown node 'nn'; did you mean 'n'?\n"
            "n.scal:1:1: error: node 'n': unknown argument 'scal' for 'fbm3'; did you mean "
            "'scale'? [/nodes/0/args/scal]\n");
  EXPECT_EQ(E.compiled().ArgsBin, Before);
}

TEST(GraphEditor, RewireRecompiles) {
  GraphEditor E = makeEditor();
  DiagnosticSink D;
  ASSERT_TRUE(E.rewire("m", "t", "n", D)) << text(D);
  EXPECT_EQ(argOf(E.compiled(), "m", "t").Src, CompiledArg::Source::Node);
  EXPECT_EQ(argOf(E.compiled(), "m", "t").NodeIndex,
            static_cast<unsigned>(E.compiled().findNode("n")));
  EXPECT_FALSE(E.needsRebuild());
}

TEST(GraphEditor, RewireIntoACycleIsAnError) {
  GraphEditor E = makeEditor();
  std::vector<uint8_t> Before = E.compiled().ArgsBin;
  DiagnosticSink D;
  EXPECT_FALSE(E.rewire("a", "x", "s", D));
  EXPECT_NE(text(D).find("cycle in the node graph: 'a' -> 's' -> 'a'"), std::string::npos)
      << text(D);
  EXPECT_EQ(E.compiled().ArgsBin, Before);
  EXPECT_EQ(E.graph().findNode("a")->Args[0].second.K, ArgValue::Kind::Number);
}

TEST(GraphEditor, DeadNodesFunctionNeedsNoRebuild) {
  // 'neg' only the dead node u names: it has an id (after the live functions) and the
  // interpreter a case, so wiring u in is a re-encoding with the same ids.
  GraphEditor E = makeEditor();
  const CompiledGraph &Before = E.compiled();
  ASSERT_EQ(Before.findNode("u"), -1);
  ASSERT_EQ(Before.FunctionsById.size(), 6u);
  EXPECT_EQ(Before.FunctionsById[5], "neg");
  EXPECT_EQ(Before.Signatures.count("neg"), 1u);
  EXPECT_EQ(Before.liveFunctions().count("neg"), 0u);
  std::vector<std::string> Ids = Before.FunctionsById;
  DiagnosticSink D;
  ASSERT_TRUE(E.rewire("s", "b", "u", D)) << text(D);
  EXPECT_FALSE(E.needsRebuild());
  EXPECT_FALSE(E.needsFunction());
  EXPECT_EQ(E.compiled().Nodes[E.compiled().findNode("u")].FnId, 5u);
  EXPECT_EQ(E.compiled().FunctionsById, Ids);
}

TEST(GraphEditor, NewFunctionNeedsARebuild) {
  // A kernel made without 'neg' (its ids pinned without it): wiring in a node of it needs a
  // new kernel.
  DiagnosticSink D;
  auto G = parse(EditGraph, D);
  ASSERT_TRUE(G) << text(D);
  CompileOptions Opts;
  Opts.FixedFunctionIds = {{"fbm3", 0}, {"ramp", 1}, {"mix3", 2}, {"leaf", 3}, {"add", 4}};
  GraphEditor E(*G, stdSigs(), Opts);
  ASSERT_TRUE(E.init(D)) << text(D);
  ASSERT_TRUE(E.rewire("s", "b", "u", D)) << text(D);
  EXPECT_TRUE(E.needsRebuild());
  EXPECT_TRUE(E.needsFunction()); // no fallback either (EditPlan: docs/modes.md's third row)
  EXPECT_FALSE(E.needsOnlyStackSlots()); // no headroom has a case for 'neg'
  ASSERT_GE(E.compiled().findNode("u"), 0);
  EXPECT_GE(E.compiled().Nodes[E.compiled().findNode("u")].FnId, 5u);
  ASSERT_TRUE(E.rewire("s", "b", "a2", D)) << text(D); // back onto a function it has
  EXPECT_FALSE(E.needsFunction());
}

TEST(GraphEditor, AnAttributeNoArgumentReadNeedsADecoderCase) {
  // The graph's node arguments read ObjectPos only: the interpreter decodes no other
  // attribute, so wiring AO into an argument needs a new kernel; ObjectPos does not.
  GraphEditor E = makeEditor();
  DiagnosticSink D;
  ASSERT_TRUE(E.setArgument("r", "t", R"({"attr": "AO"})", D)) << text(D);
  EXPECT_TRUE(E.needsAttributeCase());
  EXPECT_TRUE(E.needsRebuild());
  EXPECT_FALSE(E.needsFunction());
  EXPECT_FALSE(E.needsOnlyStackSlots());
  ASSERT_TRUE(E.setArgument("r", "t", "0.5", D)) << text(D);
  EXPECT_FALSE(E.needsAttributeCase());
  EXPECT_FALSE(E.needsRebuild());
  ASSERT_TRUE(E.setArgument("m", "a", R"({"attr": "ObjectPos"})", D)) << text(D);
  EXPECT_FALSE(E.needsAttributeCase());
  EXPECT_FALSE(E.needsRebuild());
}

TEST(GraphEditor, MoreStackSlotsNeedARebuild) {
  DiagnosticSink D;
  auto G = parse(R"({"texcc": 1, "nodes": [
    {"id": "l1", "fn": "leaf", "args": {"x": 1}}, {"id": "l2", "fn": "leaf", "args": {"x": 2}},
    {"id": "l3", "fn": "leaf", "args": {"x": 3}}, {"id": "l4", "fn": "leaf", "args": {"x": 4}},
    {"id": "p", "fn": "add", "args": {"a": {"node": "l1"}, "b": {"node": "l2"}}},
    {"id": "q", "fn": "add", "args": {"a": {"node": "l3"}, "b": {"node": "l4"}}},
    {"id": "r", "fn": "add", "args": {"a": {"node": "p"}, "b": {"node": "l1"}}}],
    "materials": {"m": {"bsdf": "emission", "color": 1, "strength": {"node": "r"}}}})",
                 D);
  ASSERT_TRUE(G) << text(D);
  GraphEditor E(*G, stdSigs(), CompileOptions());
  ASSERT_TRUE(E.init(D)) << text(D);
  EXPECT_EQ(E.compiled().StackSlots, 2u);
  ASSERT_TRUE(E.rewire("r", "b", "q", D)) << text(D); // add(add(l1,l2), add(l3,l4))
  EXPECT_EQ(E.compiled().StackSlots, 3u);
  EXPECT_TRUE(E.needsRebuild());
  EXPECT_TRUE(E.needsOnlyStackSlots()); // a kernel with headroom may still run it
  ASSERT_TRUE(E.rewire("r", "b", "l2", D)) << text(D);
  EXPECT_FALSE(E.needsRebuild());
  EXPECT_FALSE(E.needsOnlyStackSlots());
}

TEST(GraphEditor, FunctionIdsStayPinned) {
  GraphEditor E = makeEditor();
  std::vector<std::string> Before = E.compiled().FunctionsById;
  DiagnosticSink D;
  ASSERT_TRUE(E.rewire("s", "b", "u", D)) << text(D);
  for (size_t I = 0; I < Before.size(); ++I) {
    if (!Before[I].empty() && I < E.compiled().FunctionsById.size() &&
        !E.compiled().FunctionsById[I].empty()) {
      EXPECT_EQ(E.compiled().FunctionsById[I], Before[I]);
    }
  }
}

} // namespace

// An edit is validated once (GraphEditor::check): a sequence checked whole, each edit against
// the one before, then applied in order, is not validated again, and ends where the same edits
// applied one by one end.
TEST(GraphEditor, CheckedEditsApplyWithoutBeingValidatedAgain) {
  DiagnosticSink D;
  auto set = [&](const std::string &Node, const std::string &Arg, const std::string &Value) {
    Edit E;
    E.Node = Node;
    E.Arg = Arg;
    E.Value = *parseArgValue(Node + "." + Arg, Value, D);
    return E;
  };
  const std::vector<Edit> Edits = {
      set("n", "scale", "0.5"),  // args.bin patched in place
      rewireEdit("m", "t", "n"), // recompiled
      rewireEdit("s", "a", "x"),
      rewireEdit("a", "x", "s"), // a cycle, unless checked after the edit before it
      set("u", "x", "2")};       // a dead node

  GraphEditor Checked = makeEditor(), OneByOne = makeEditor();
  const uint64_t Before = GraphEditor::validations();
  std::vector<CheckedEdit> Sequence;
  for (const Edit &E : Edits) {
    std::optional<CheckedEdit> C =
        Sequence.empty() ? Checked.check(E, D) : Checked.check(Sequence.back(), E, D);
    ASSERT_TRUE(C) << text(D);
    Sequence.push_back(std::move(*C));
  }
  EXPECT_EQ(GraphEditor::validations() - Before, Edits.size());
  EXPECT_TRUE(sameGraph(Checked.graph(), OneByOne.graph())); // checking changes nothing
  DiagnosticSink Alone;
  EXPECT_FALSE(Checked.check(Edits[3], Alone)); // against the graph as it is: the cycle
  const uint64_t Checks = GraphEditor::validations();
  for (CheckedEdit &C : Sequence)
    ASSERT_TRUE(Checked.apply(std::move(C)));
  EXPECT_EQ(GraphEditor::validations(), Checks);
  for (const Edit &E : Edits)
    ASSERT_TRUE(OneByOne.apply(E, D)) << text(D);
  EXPECT_EQ(GraphEditor::validations() - Checks, Edits.size()); // apply(Edit): once each
  EXPECT_TRUE(sameGraph(Checked.graph(), OneByOne.graph()));
  EXPECT_EQ(Checked.compiled().ArgsBin, OneByOne.compiled().ArgsBin);
  EXPECT_EQ(Checked.needsRebuild(), OneByOne.needsRebuild());
}

// A checked edit applies only to the state of the graph it was checked against: checked
// against the initial graph, it is refused once another edit was applied, and nothing changes.
TEST(GraphEditor, ACheckedEditAppliesOnlyToItsState) {
  GraphEditor E = makeEditor();
  DiagnosticSink D;
  std::optional<CheckedEdit> A = E.check(rewireEdit("m", "t", "n"), D);
  std::optional<CheckedEdit> B = E.check(rewireEdit("m", "t", "x"), D);
  ASSERT_TRUE(A && B) << text(D);
  ASSERT_TRUE(E.apply(std::move(*A)));
  std::vector<uint8_t> Bin = E.compiled().ArgsBin;
  EXPECT_FALSE(E.apply(std::move(*B)));
  EXPECT_EQ(E.compiled().ArgsBin, Bin);
  EXPECT_EQ(E.graph().findNode("m")->Args[2].second.Ref, "n");
  EXPECT_EQ(editText(B->edit()), "rewire m.t=x"); // left whole by the refusal
  // A refused check is an error and leaves nothing to apply.
  EXPECT_FALSE(E.check(rewireEdit("a", "x", "s"), D));
  EXPECT_NE(text(D).find("cycle in the node graph"), std::string::npos) << text(D);
}

// An editor over the same graph and signatures (a regenerated kernel) continues the state of
// the one before it, so that the edits checked against that one apply; other signatures do not.
TEST(GraphEditor, ContinueFromTheEditorBefore) {
  GraphEditor Old = makeEditor();
  DiagnosticSink D;
  std::optional<CheckedEdit> C = Old.check(rewireEdit("m", "t", "n"), D);
  ASSERT_TRUE(C) << text(D);
  GraphEditor New(Old.graph(), stdSigs(), CompileOptions());
  ASSERT_TRUE(New.init(D)) << text(D);
  EXPECT_FALSE(New.apply(std::move(*C)));
  SignatureMap Other = stdSigs();
  Other.at("neg").Params[0].Name = "y";
  GraphEditor Renamed(Old.graph(), Other, CompileOptions());
  EXPECT_FALSE(Renamed.continueFrom(Old));
  ASSERT_TRUE(New.continueFrom(Old));
  const uint64_t Before = GraphEditor::validations();
  EXPECT_TRUE(New.apply(std::move(*C)));
  EXPECT_EQ(GraphEditor::validations(), Before);
  EXPECT_EQ(argOf(New.compiled(), "m", "t").Src, CompiledArg::Source::Node);
}
