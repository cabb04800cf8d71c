// The passes one by one, Cycles-style: build a small graph, run the pass, check the result.

#include "GraphTestUtil.h"

#include <algorithm>
#include <functional>
#include <set>

using namespace texcc::graph;
using namespace texcc::graph::test;

namespace {

std::string leaf(const std::string &Id, double X) {
  return "{\"id\": \"" + Id + "\", \"fn\": \"leaf\", \"args\": {\"x\": " + std::to_string(X) +
         "}}";
}

std::string unary(const std::string &Id, const std::string &Fn, const std::string &Child) {
  return "{\"id\": \"" + Id + "\", \"fn\": \"" + Fn + "\", \"args\": {\"x\": {\"node\": \"" +
         Child + "\"}}}";
}

std::string add(const std::string &Id, const std::string &A, const std::string &B) {
  auto Ref = [](const std::string &R) {
    return R[0] >= '0' && R[0] <= '9' ? R : "{\"node\": \"" + R + "\"}";
  };
  return "{\"id\": \"" + Id + "\", \"fn\": \"add\", \"args\": {\"a\": " + Ref(A) +
         ", \"b\": " + Ref(B) + "}}";
}

std::string emissionOf(const std::string &Node) {
  return "{\"m\": {\"bsdf\": \"emission\", \"color\": 1, \"strength\": {\"node\": \"" + Node +
         "\"}}}";
}

std::vector<std::string> programIds(const CompiledGraph &CG, unsigned Material = 0) {
  std::vector<std::string> Ids;
  for (const Instruction &In : CG.Materials[Material].Program)
    Ids.push_back(CG.Nodes[In.Node].Id);
  return Ids;
}

std::vector<std::string> nodeIds(const CompiledGraph &CG) {
  std::vector<std::string> Ids;
  for (const CompiledNode &N : CG.Nodes)
    Ids.push_back(N.Id);
  return Ids;
}

/// A chain: leaf -> neg -> neg ... (Length nodes in all).
std::string chainGraph(unsigned Length) {
  std::vector<std::string> Nodes = {leaf("n0", 1)};
  for (unsigned I = 1; I < Length; ++I)
    Nodes.push_back(unary("n" + std::to_string(I), "neg", "n" + std::to_string(I - 1)));
  return graphJson(Nodes, emissionOf("n" + std::to_string(Length - 1)));
}

/// A balanced binary tree of add nodes with distinct leaves at depth Depth.
std::string treeGraph(unsigned Depth) {
  std::vector<std::string> Nodes;
  unsigned Leaves = 0;
  std::function<std::string(unsigned, const std::string &)> Build =
      [&](unsigned Level, const std::string &Id) {
        if (Level == Depth) {
          Nodes.push_back(leaf(Id, Leaves++));
          return Id;
        }
        std::string A = Build(Level + 1, Id + "a"), B = Build(Level + 1, Id + "b");
        Nodes.push_back(add(Id, A, B));
        return Id;
      };
  Build(0, "t");
  return graphJson(Nodes, emissionOf("t"));
}

CompiledGraph upToSlots(const std::string &Json, unsigned Limit = 32,
                        std::ostream *Log = nullptr) {
  CompiledGraph CG = resolved(Json);
  removeUnreachableNodes(CG, nullptr);
  mergeIdenticalNodes(CG, nullptr);
  assignFunctionIds(CG, stdSigs(), CompileOptions(), nullptr);
  orderPrograms(CG, nullptr);
  allocateStackSlots(CG, Limit, Log);
  return CG;
}

TEST(RemoveUnreachable, DropsNodesNoMaterialReaches) {
  CompiledGraph CG = resolved(graphJson(
      {leaf("a", 1), leaf("v", 2), unary("u", "neg", "v"), unary("b", "neg", "a")},
      emissionOf("b")));
  ASSERT_EQ(CG.Nodes.size(), 4u);
  std::ostringstream Log;
  removeUnreachableNodes(CG, &Log);
  EXPECT_EQ(nodeIds(CG), (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(CG.Nodes[1].Args[0].NodeIndex, 0u);
  EXPECT_EQ(CG.Materials[0].Outputs[0].Node, 1u);
  EXPECT_EQ(Log.str(), "remove-unused: removed node 'v' (no material reaches it)\n"
                       "remove-unused: removed node 'u' (no material reaches it)\n");
}

TEST(MergeIdentical, MergesTwinsAfterMergingChildren) {
  // q2 and r2 differ only in which twin leaf they read; after p/q merge they are twins too.
  CompiledGraph CG = resolved(graphJson(
      {add("q2", "p", "1"), leaf("p", 1), leaf("q", 1), add("r2", "q", "1"), leaf("z", 2)},
      R"({"m": {"bsdf": "blend", "mask": {"node": "q2"},
        "a": {"bsdf": "glossy", "color": 1, "roughness": {"node": "r2"}},
        "b": {"bsdf": "emission", "color": 1, "strength": {"node": "z"}}}})"));
  ASSERT_EQ(CG.Materials[0].Outputs.size(), 3u);
  std::ostringstream Log;
  mergeIdenticalNodes(CG, &Log);
  EXPECT_EQ(nodeIds(CG), (std::vector<std::string>{"q2", "p", "z"}));
  EXPECT_EQ(CG.Nodes[0].MergedIds, std::vector<std::string>{"r2"});
  EXPECT_EQ(CG.Nodes[1].MergedIds, std::vector<std::string>{"q"});
  EXPECT_EQ(CG.Nodes[0].Args[0].NodeIndex, 1u);
  EXPECT_EQ(CG.findNode("r2"), 0);
  EXPECT_EQ(CG.findNode("q"), 1);
  // The two outputs that named q2 and r2 are one now; the BSDF inputs follow.
  const CompiledMaterial &M = CG.Materials[0];
  ASSERT_EQ(M.Outputs.size(), 2u);
  EXPECT_EQ(M.Bsdf.Inputs[0].Output, 0u);
  EXPECT_EQ(M.Bsdf.Children[0].second.Inputs[1].Output, 0u);
  EXPECT_EQ(M.Bsdf.Children[1].second.Inputs[1].Output, 1u);
  EXPECT_EQ(Log.str(),
            "merge-identical: merged node 'q' into 'p' (same function 'leaf', same arguments)\n"
            "merge-identical: merged node 'r2' into 'q2' (same function 'add', same "
            "arguments)\n");
}

TEST(MergeIdentical, KeepsNodesThatDiffer) {
  CompiledGraph CG = resolved(R"({"texcc": 1, "nodes": [
    {"id": "a", "fn": "leaf", "args": {"x": 1}},
    {"id": "b", "fn": "leaf", "args": {"x": 1.0000001}},
    {"id": "c", "fn": "neg", "args": {"x": 1}},
    {"id": "d", "fn": "leaf", "args": {"x": {"attr": "AO"}}},
    {"id": "e", "fn": "mix3", "args": {"a": {"node": "a"}, "b": 0, "t": 0}},
    {"id": "f", "fn": "mix3", "args": {"a": 0, "b": {"node": "a"}, "t": 0}},
    {"id": "s", "fn": "add", "args": {"a": {"node": "b"}, "b": {"node": "c"}}},
    {"id": "s2", "fn": "add", "args": {"a": {"node": "d"}, "b": 1}}],
    "materials": {"m": {"bsdf": "blend", "mask": {"node": "s"},
      "a": {"bsdf": "diffuse", "color": {"node": "e"}},
      "b": {"bsdf": "blend", "mask": {"node": "s2"},
        "a": {"bsdf": "diffuse", "color": {"node": "f"}},
        "b": {"bsdf": "diffuse", "color": 1}}}}})");
  mergeIdenticalNodes(CG, nullptr);
  EXPECT_EQ(CG.Nodes.size(), 8u);
}

TEST(OrderPrograms, ChildrenFirstHeavierChildFirst) {
  // root = add(light, heavy): heavy (2 slots) is evaluated first although it is argument b.
  CompiledGraph CG = resolved(graphJson({leaf("light", 1), leaf("h1", 2), leaf("h2", 3),
                                         add("heavy", "h1", "h2"), add("root", "light", "heavy")},
                                        emissionOf("root")));
  assignFunctionIds(CG, stdSigs(), CompileOptions(), nullptr);
  std::vector<unsigned> Need = slotNeeds(CG);
  EXPECT_EQ(Need[CG.findNode("light")], 1u);
  EXPECT_EQ(Need[CG.findNode("heavy")], 2u);
  EXPECT_EQ(Need[CG.findNode("root")], 2u);
  std::ostringstream Log;
  orderPrograms(CG, &Log);
  EXPECT_EQ(programIds(CG), (std::vector<std::string>{"h1", "h2", "heavy", "light", "root"}));
  EXPECT_NE(Log.str().find("order: material 'm': 3. 'heavy' (needs 2 slots)\n"),
            std::string::npos);
  allocateStackSlots(CG, 32, nullptr);
  EXPECT_EQ(CG.StackSlots, 2u);
}

TEST(OrderPrograms, SharedChildIsEvaluatedOnce) {
  CompiledGraph CG = upToSlots(graphJson(
      {leaf("s", 1), unary("a", "neg", "s"), add("b", "s", "1"), add("r", "a", "b")},
      emissionOf("r")));
  std::vector<std::string> P = programIds(CG);
  ASSERT_EQ(P.size(), 4u);
  EXPECT_EQ(P.front(), "s");
  EXPECT_EQ(P.back(), "r");
  EXPECT_EQ(CG.StackSlots, 2u);
}

TEST(StackSlots, ChainOf100NeedsAtMostTwo) {
  CompiledGraph CG = upToSlots(chainGraph(100));
  ASSERT_EQ(CG.Materials[0].Program.size(), 100u);
  EXPECT_LE(CG.StackSlots, 2u);
  // Each result takes the slot its argument frees.
  for (const Instruction &In : CG.Materials[0].Program)
    EXPECT_EQ(In.ResultSlot, 0u);
}

TEST(StackSlots, BalancedTreeOfDepthDNeedsAtMostDPlusOne) {
  for (unsigned D = 1; D <= 8; ++D) {
    CompiledGraph CG = upToSlots(treeGraph(D));
    ASSERT_EQ(CG.Nodes.size(), (2u << D) - 1) << "depth " << D;
    EXPECT_LE(CG.StackSlots, D + 1) << "depth " << D;
    EXPECT_EQ(CG.StackSlots, D + 1) << "depth " << D; // and that is the exact peak
    EXPECT_FALSE(CG.Spill);
  }
}

TEST(StackSlots, SpillsOverTheLimit) {
  CompiledGraph CG = upToSlots(treeGraph(4), 4);
  EXPECT_EQ(CG.StackSlots, 5u);
  EXPECT_EQ(CG.StackLimit, 4u);
  EXPECT_TRUE(CG.Spill);
  CG = upToSlots(treeGraph(4), 5);
  EXPECT_FALSE(CG.Spill);
}

/// Replays a program and checks that no live value is overwritten before its last reader and
/// that outputs survive to the end.
void expectValidAllocation(const CompiledGraph &CG) {
  for (const CompiledMaterial &M : CG.Materials) {
    std::map<unsigned, unsigned> Holder; // slot -> node
    for (const Instruction &In : M.Program) {
      for (const CompiledArg &A : CG.Nodes[In.Node].Args) {
        if (A.Src != CompiledArg::Source::Node)
          continue;
        bool Found = false;
        for (const auto &[Slot, Node] : Holder)
          Found |= Node == A.NodeIndex;
        EXPECT_TRUE(Found) << "node " << CG.Nodes[In.Node].Id << " reads a clobbered value";
      }
      Holder[In.ResultSlot] = In.Node;
    }
    for (const MaterialOutput &O : M.Outputs) {
      EXPECT_EQ(Holder[O.Slot], O.Node);
      EXPECT_LT(O.Slot, M.StackSlots);
    }
  }
}

TEST(StackSlots, OutputsStayLiveToTheEnd) {
  CompiledGraph CG = upToSlots(graphJson(
      {leaf("m", 1), leaf("x", 2), unary("y", "neg", "x"), unary("z", "neg", "y"),
       R"({"id": "c", "fn": "mix3", "args": {"a": {"node": "z"}, "b": 1, "t": {"node": "m"}}})"},
      R"({"mat": {"bsdf": "blend", "mask": {"node": "m"},
        "a": {"bsdf": "diffuse", "color": {"node": "c"}},
        "b": {"bsdf": "emission", "color": 1, "strength": {"node": "y"}}}})"));
  const CompiledMaterial &M = CG.Materials[0];
  ASSERT_EQ(M.Outputs.size(), 3u);
  EXPECT_NE(M.Outputs[0].Slot, M.Outputs[1].Slot);
  EXPECT_NE(M.Outputs[1].Slot, M.Outputs[2].Slot);
  EXPECT_NE(M.Outputs[0].Slot, M.Outputs[2].Slot);
  EXPECT_EQ(M.StackSlots, 3u);
  expectValidAllocation(CG);
}

TEST(StackSlots, PeakIsOverAllMaterialsAndLogged) {
  std::ostringstream Log;
  CompiledGraph CG = upToSlots(graphJson({leaf("a", 1), leaf("b", 2), add("s", "a", "b")},
                                         R"({"one": {"bsdf": "emission", "color": 1,
                                              "strength": {"node": "a"}},
                                             "two": {"bsdf": "emission", "color": 1,
                                              "strength": {"node": "s"}}})"),
                               32, &Log);
  EXPECT_EQ(CG.Materials[0].StackSlots, 1u);
  EXPECT_EQ(CG.Materials[1].StackSlots, 2u);
  EXPECT_EQ(CG.StackSlots, 2u);
  EXPECT_EQ(Log.str(), "stack-slots: material 'one': 'a' -> slot 0\n"
                       "stack-slots: material 'two': 'a' -> slot 0\n"
                       "stack-slots: material 'two': 'b' -> slot 1\n"
                       "stack-slots: material 'two': 's' -> slot 0\n"
                       "stack-slots: peak 2 slots over 2 materials; limit 32: private\n");
  EXPECT_FALSE(CG.Spill);
}

TEST(StackSlots, RandomDagsAllocateValidly) {
  // Deterministic pseudo-random DAGs with shared children and several materials.
  unsigned Seed = 12345;
  auto Next = [&](unsigned N) {
    Seed = Seed * 1103515245u + 12345u;
    return (Seed >> 16) % N;
  };
  for (int Round = 0; Round < 50; ++Round) {
    std::vector<std::string> Nodes;
    unsigned Count = 2 + Next(40);
    for (unsigned I = 0; I < Count; ++I) {
      std::string Id = "n" + std::to_string(I);
      if (I < 2 || Next(4) == 0)
        Nodes.push_back(leaf(Id, I));
      else if (Next(2))
        Nodes.push_back(unary(Id, "neg", "n" + std::to_string(Next(I))));
      else
        Nodes.push_back(add(Id, "n" + std::to_string(Next(I)), "n" + std::to_string(Next(I))));
    }
    std::string Mats = "{";
    for (int M = 0; M < 3; ++M)
      Mats += std::string(M ? "," : "") + "\"m" + std::to_string(M) +
              "\": {\"bsdf\": \"blend\", \"mask\": {\"node\": \"n" +
              std::to_string(Next(Count)) + "\"}, \"a\": {\"bsdf\": \"diffuse\", \"color\": " +
              "{\"node\": \"n" + std::to_string(Next(Count)) + "\"}}, \"b\": {\"bsdf\": " +
              "\"emission\", \"color\": 1, \"strength\": {\"node\": \"n" +
              std::to_string(Count - 1) + "\"}}}";
    CompiledGraph CG = upToSlots(graphJson(Nodes, Mats + "}"));
    expectValidAllocation(CG);
    computeWavefrontOrder(CG, nullptr);
    layoutArguments(CG, nullptr);
    encodeArgsBin(CG);
    // Every instruction's record holds the slots of its node's children in that material.
    for (const CompiledMaterial &M : CG.Materials) {
      std::map<unsigned, unsigned> SlotOf;
      for (const Instruction &In : M.Program) {
        const CompiledNode &N = CG.Nodes[In.Node];
        for (size_t A = 0; A < N.Args.size(); ++A) {
          if (N.Args[A].Src == CompiledArg::Source::Node) {
            EXPECT_EQ(word(CG.ArgsBin, In.RecordOffset + 4 * A) & 0xFFFF,
                      SlotOf.at(N.Args[A].NodeIndex));
          }
        }
        SlotOf[In.Node] = In.ResultSlot;
      }
    }
  }
}

TEST(WavefrontOrder, TopologicalOverAllMaterials) {
  CompiledGraph CG = upToSlots(graphJson({leaf("a", 1), leaf("b", 2), add("s", "a", "b"),
                                          unary("t", "neg", "b")},
                                         R"({"one": {"bsdf": "emission", "color": 1,
                                              "strength": {"node": "t"}},
                                             "two": {"bsdf": "emission", "color": 1,
                                              "strength": {"node": "s"}}})"));
  std::ostringstream Log;
  computeWavefrontOrder(CG, &Log);
  ASSERT_EQ(CG.WavefrontOrder.size(), CG.Nodes.size());
  std::vector<unsigned> Position(CG.Nodes.size());
  for (size_t I = 0; I < CG.WavefrontOrder.size(); ++I)
    Position[CG.WavefrontOrder[I]] = static_cast<unsigned>(I);
  for (size_t N = 0; N < CG.Nodes.size(); ++N)
    for (const CompiledArg &A : CG.Nodes[N].Args) {
      if (A.Src == CompiledArg::Source::Node) {
        EXPECT_LT(Position[A.NodeIndex], Position[N]);
      }
    }
  EXPECT_EQ(Log.str(), "wavefront: launch 0: 'b'\nwavefront: launch 1: 't'\n"
                       "wavefront: launch 2: 'a'\nwavefront: launch 3: 's'\n");
}

TEST(FunctionIds, FixedIdsArePinnedOthersTakeFreeOnes) {
  CompiledGraph CG = resolved(graphJson({leaf("a", 1), unary("b", "neg", "a"),
                                         add("c", "a", "b")},
                                        emissionOf("c")));
  CompileOptions Opts;
  Opts.FixedFunctionIds = {{"add", 0}, {"mix3", 1}};
  std::ostringstream Log;
  assignFunctionIds(CG, stdSigs(), Opts, &Log);
  EXPECT_EQ(CG.Nodes[0].FnId, 2u); // leaf
  EXPECT_EQ(CG.Nodes[1].FnId, 3u); // neg
  EXPECT_EQ(CG.Nodes[2].FnId, 0u); // add
  EXPECT_EQ(CG.FunctionsById, (std::vector<std::string>{"add", "", "leaf", "neg"}));
  EXPECT_EQ(Log.str(), "function-ids: 'leaf' gets id 2\nfunction-ids: 'neg' gets id 3\n");
}

TEST(FunctionIds, FunctionsOfDeadNodesGetIdsAfterTheLiveOnes) {
  // d (first in the file) and i are dead; their functions get ids after the live one, in file
  // order, and signatures (the interpreter has a case for each); what they read is not read
  // until they are live, except that the interpreter decodes d's attribute argument.
  const char *Json = R"({"texcc": 1, "images": {"i": "i.png"}, "nodes": [
    {"id": "d", "fn": "neg", "args": {"x": {"attr": "AO"}}},
    {"id": "l", "fn": "leaf", "args": {"x": 1}},
    {"id": "i", "fn": "image", "args": {"img": {"image": "i"}, "uv": [0, 0]}}],
    "materials": {"m": {"bsdf": "emission", "color": 1, "strength": {"node": "l"}}}})";
  CompiledGraph CG = resolved(Json);
  EXPECT_EQ(CG.GraphFunctions, (std::vector<std::string>{"neg", "leaf", "image"}));
  EXPECT_EQ(CG.GraphArgumentAttributes, std::vector<int>{attributeId("AO")});
  removeUnreachableNodes(CG, nullptr);
  ASSERT_EQ(CG.Nodes.size(), 1u);
  EXPECT_EQ(CG.GraphFunctions.size(), 3u);
  std::ostringstream Log;
  assignFunctionIds(CG, stdSigs(), CompileOptions(), &Log);
  EXPECT_EQ(CG.FunctionsById, (std::vector<std::string>{"leaf", "neg", "image"}));
  EXPECT_EQ(CG.Signatures.size(), 3u);
  EXPECT_EQ(CG.liveFunctions(), std::set<std::string>{"leaf"});
  EXPECT_TRUE(CG.Attributes.empty()); // neither AO (d's argument) nor TexCoord0 (image's code)
  EXPECT_TRUE(CG.Settings.empty());
  EXPECT_EQ(Log.str(), "function-ids: 'leaf' gets id 0\n"
                       "function-ids: 'neg' gets id 1 (only dead nodes name it)\n"
                       "function-ids: 'image' gets id 2 (only dead nodes name it)\n");

  // Pinned ids hold for dead nodes' functions too.
  CompiledGraph Pinned = resolved(Json);
  removeUnreachableNodes(Pinned, nullptr);
  CompileOptions Opts;
  Opts.FixedFunctionIds = {{"image", 0}};
  assignFunctionIds(Pinned, stdSigs(), Opts, nullptr);
  EXPECT_EQ(Pinned.FunctionsById, (std::vector<std::string>{"image", "leaf", "neg"}));
}

TEST(FunctionIds, CollectsAttributesSettingsAndOutputs) {
  CompiledGraph CG = resolved(R"({"texcc": 1, "images": {"i": "i.png"}, "nodes": [
    {"id": "w", "fn": "weights", "args": {"w": [1], "dirs": [], "n": 0}},
    {"id": "img", "fn": "image", "args": {"img": {"image": "i"}, "uv": {"attr": "TexCoord0"}}},
    {"id": "l", "fn": "leaf", "args": {"x": {"attr": "AO"}}}],
    "materials": {"m": {"bsdf": "blend", "mask": {"node": "w"},
      "a": {"bsdf": "diffuse", "color": {"node": "img"}},
      "b": {"bsdf": "emission", "color": 1, "strength": {"node": "l"}}}}})");
  assignFunctionIds(CG, stdSigs(), CompileOptions(), nullptr);
  EXPECT_EQ(CG.Attributes, (std::vector<std::string>{"AO", "TexCoord0"}));
  EXPECT_EQ(CG.Settings, std::vector<std::string>{"Time"});
  EXPECT_EQ(CG.MaxOutputs, 3u);
  EXPECT_EQ(CG.Signatures.size(), 3u);
}

TEST(RecordCopies, MaterialsWithDifferentChildSlotsGetTheirOwnRecord) {
  // In 'one', y is in slot 0 when x reads it; in 'two' the mask z holds slot 0 to the end,
  // so y lands in slot 1 and x needs a record whose source word says 1.
  CompiledGraph CG = upToSlots(graphJson({leaf("y", 1), unary("x", "neg", "y"), leaf("z", 2)},
                                         R"({"one": {"bsdf": "emission", "color": 1,
                                              "strength": {"node": "x"}},
                                             "two": {"bsdf": "blend", "mask": {"node": "z"},
                                              "a": {"bsdf": "emission", "color": 1,
                                                    "strength": {"node": "x"}},
                                              "b": {"bsdf": "diffuse", "color": 1}}})"));
  computeWavefrontOrder(CG, nullptr);
  std::ostringstream Log;
  layoutArguments(CG, &Log);
  encodeArgsBin(CG);
  const CompiledNode &X = CG.Nodes[CG.findNode("x")];
  ASSERT_EQ(X.RecordCopies.size(), 1u);
  EXPECT_NE(Log.str().find("layout: node 'x': material 'two' reads its arguments from other "
                           "slots: record copy at byte "),
            std::string::npos);
  const Instruction &InOne = CG.Materials[0].Program[1];
  const Instruction &InTwo = CG.Materials[1].Program.back();
  EXPECT_EQ(InOne.RecordOffset, X.RecordOffset);
  EXPECT_EQ(InTwo.RecordOffset, X.RecordCopies[0]);
  EXPECT_EQ(word(CG.ArgsBin, InOne.RecordOffset), (1u << 30) | 0u);
  EXPECT_EQ(word(CG.ArgsBin, InTwo.RecordOffset), (1u << 30) | 1u);
}

} // namespace
