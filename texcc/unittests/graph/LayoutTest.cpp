// Argument layout (OpenCL alignment), the args.bin encoding (decoded back here, per
// docs/abi.md), layout.json, and reading signatures back from it.

#include "GraphTestUtil.h"

#include <nlohmann/json.hpp>

using namespace texcc::graph;
using namespace texcc::graph::test;

namespace {

const SignatureMap &layoutSigs() {
  static const SignatureMap S = sigs(R"([
    {"name": "all", "return": "float4", "params": [{"name": "a", "type": "float"},
      {"name": "b", "type": "float3"}, {"name": "c", "type": "float2"},
      {"name": "d", "type": "int"}, {"name": "e", "type": "float4"},
      {"name": "arr", "type": "__global const float3*"}, {"name": "s", "type": "sam2D"}]},
    {"name": "leaf", "return": "float", "params": [{"name": "x", "type": "float"}]},
    {"name": "none", "return": "float2", "params": []},
    {"name": "ws", "return": "float", "params": [{"name": "w", "type": "__global const int*"},
      {"name": "v", "type": "float"}]}
  ])");
  return S;
}

const char *AllGraph = R"({"texcc": 1, "images": {"i0": "a.png", "i1": "b.png"}, "nodes": [
  {"id": "l", "fn": "leaf", "args": {"x": {"attr": "AO"}}},
  {"id": "n", "fn": "all", "args": {"a": 0.5, "b": {"node": "l"}, "c": [1, 2], "d": -7,
    "e": {"attr": "AO"}, "arr": [[1, 2, 3], [4, 5, 6], [7, 8, 9]], "s": {"image": "i1"}}},
  {"id": "z", "fn": "none"},
  {"id": "w", "fn": "ws", "args": {"w": [3, -4, 5], "v": {"node": "l"}}}],
  "materials": {"m": {"bsdf": "blend", "mask": {"node": "w"},
    "a": {"bsdf": "diffuse", "color": {"node": "n"}},
    "b": {"bsdf": "glossy", "color": 0.5, "roughness": {"node": "l"}}},
    "plain": {"bsdf": "mirror", "color": [1, 1, 1]},
    "n2": {"bsdf": "emission", "color": {"node": "n"}, "strength": 2}}})";

TEST(Layout, ParameterOffsetsFollowOpenCLAlignment) {
  uint32_t Block = 0;
  std::vector<uint32_t> Off = parameterOffsets(layoutSigs().at("all"), Block);
  EXPECT_EQ(Off, (std::vector<uint32_t>{0, 16, 32, 40, 48, 64, 72}));
  EXPECT_EQ(Block, 80u);
  EXPECT_EQ(sizeOf(ValueType{BaseType::Float3, false}), 16u);
  EXPECT_EQ(alignOf(ValueType{BaseType::Float3, false}), 16u);
  EXPECT_EQ(sizeOf(ValueType{BaseType::Float4, true}), 8u);
  EXPECT_EQ(alignOf(ValueType{BaseType::Float4, true}), 4u);
  EXPECT_EQ(parameterOffsets(layoutSigs().at("none"), Block), std::vector<uint32_t>{});
  EXPECT_EQ(Block, 0u);
}

TEST(Layout, RecordsAndArraysAre16Aligned) {
  CompiledGraph CG = compiled(AllGraph, CompileOptions(), layoutSigs());
  ASSERT_EQ(CG.Nodes.size(), 3u); // z is unused
  EXPECT_EQ(CG.ProgramWords, (2 + 3 * 3 + 3) + (2 + 0 + 0) + (2 + 3 * 2 + 1));
  EXPECT_EQ(CG.RecordsOffset, 112u); // 25 words = 100 bytes, 16-aligned
  EXPECT_EQ(CG.ArgsBin.size() % 16, 0u);
  const CompiledNode &N = CG.Nodes[CG.findNode("n")];
  EXPECT_EQ(N.RecordSize, 32u + 80u);
  for (const CompiledNode &X : CG.Nodes) {
    EXPECT_EQ(X.RecordOffset % 16, 0u) << X.Id;
    EXPECT_GE(X.RecordOffset, CG.RecordsOffset);
    for (const CompiledArg &A : X.Args) {
      if (A.Type.IsGlobalArray) {
        EXPECT_EQ(A.ArrayByteOffset % 16, 0u);
      }
    }
  }
  EXPECT_EQ(N.Args[5].ArrayCount, 3u);
  EXPECT_EQ(CG.Nodes[CG.findNode("w")].Args[0].ArrayByteOffset,
            N.Args[5].ArrayByteOffset + 3 * 16);
}

/// Reads args.bin back per docs/abi.md and compares with the compiled graph.
void expectDecodesTo(const CompiledGraph &CG) {
  const std::vector<uint8_t> &Bin = CG.ArgsBin;
  for (const CompiledMaterial &M : CG.Materials) {
    uint32_t W = 4 * M.ProgramWordOffset;
    ASSERT_EQ(word(Bin, W), M.Program.size());
    ASSERT_EQ(word(Bin, W + 4), M.Outputs.size());
    W += 8;
    std::map<unsigned, unsigned> SlotOf;
    for (const Instruction &In : M.Program) {
      const CompiledNode &N = CG.Nodes[In.Node];
      EXPECT_EQ(word(Bin, W), N.FnId);
      EXPECT_EQ(word(Bin, W + 4), In.ResultSlot);
      uint32_t Record = word(Bin, W + 8);
      EXPECT_EQ(Record % 16, 0u);
      W += 12;
      uint32_t Block = Record + (4 * N.Args.size() + 15) / 16 * 16;
      for (size_t P = 0; P < N.Args.size(); ++P) {
        const CompiledArg &A = N.Args[P];
        uint32_t Src = word(Bin, Record + 4 * static_cast<uint32_t>(P));
        uint32_t At = Block + A.BlockOffset;
        switch (A.Src) {
        case CompiledArg::Source::Node:
          EXPECT_EQ(Src >> 30, 1u);
          EXPECT_EQ(Src & 0xFFFF, SlotOf.at(A.NodeIndex));
          EXPECT_EQ((Src >> 29) & 1, A.Broadcast ? 1u : 0u);
          EXPECT_EQ(word(Bin, At), 0u);
          break;
        case CompiledArg::Source::Attribute:
          EXPECT_EQ(Src >> 30, 2u);
          EXPECT_EQ(static_cast<int>(Src & 0xFFFF), A.AttrId);
          EXPECT_EQ((Src >> 29) & 1, A.Broadcast ? 1u : 0u);
          break;
        case CompiledArg::Source::Constant:
          EXPECT_EQ(Src, 0u);
          if (A.Type.IsGlobalArray) {
            uint32_t Offset = word(Bin, At), Count = word(Bin, At + 4);
            EXPECT_EQ(Offset, A.ArrayByteOffset);
            EXPECT_EQ(Count, A.ArrayCount);
            unsigned Comp = componentCount(A.Type.Base);
            uint32_t Stride = sizeOf(ValueType{A.Type.Base, false});
            for (unsigned E = 0; E < Count; ++E)
              for (unsigned C = 0; C < Comp; ++C) {
                uint32_t Where = Offset + E * Stride + 4 * C;
                if (A.Type.Base == BaseType::Int)
                  EXPECT_EQ(static_cast<int32_t>(word(Bin, Where)), A.Values[E * Comp + C]);
                else
                  EXPECT_EQ(floatAt(Bin, Where), static_cast<float>(A.Values[E * Comp + C]));
              }
          } else {
            for (size_t C = 0; C < A.Values.size(); ++C) {
              uint32_t Where = At + 4 * static_cast<uint32_t>(C);
              if (A.Type.Base == BaseType::Int || A.Type.Base == BaseType::Sampler)
                EXPECT_EQ(static_cast<int32_t>(word(Bin, Where)), A.Values[C]);
              else
                EXPECT_EQ(floatAt(Bin, Where), static_cast<float>(A.Values[C]));
            }
          }
          break;
        }
      }
      SlotOf[In.Node] = In.ResultSlot;
    }
    for (const MaterialOutput &O : M.Outputs) {
      EXPECT_EQ(word(Bin, W), O.Slot);
      EXPECT_EQ(SlotOf.at(O.Node), O.Slot);
      W += 4;
    }
  }
}

TEST(Encoding, RoundTrip) {
  CompiledGraph CG = compiled(AllGraph, CompileOptions(), layoutSigs());
  expectDecodesTo(CG);
  const CompiledNode &N = CG.Nodes[CG.findNode("n")];
  uint32_t Block = parameterBlockStart(N, N.RecordOffset);
  EXPECT_EQ(floatAt(CG.ArgsBin, Block + 0), 0.5f);                         // a
  EXPECT_EQ(floatAt(CG.ArgsBin, Block + 36), 2.0f);                        // c.y
  EXPECT_EQ(static_cast<int32_t>(word(CG.ArgsBin, Block + 40)), -7);       // d
  EXPECT_EQ(word(CG.ArgsBin, Block + 72), 1u);                             // s: image 1
  EXPECT_EQ(word(CG.ArgsBin, N.RecordOffset + 4 * 1), (1u << 30) | (1u << 29) |
                                                          word(CG.ArgsBin, 8 + 4)); // b: bcast
  EXPECT_EQ(word(CG.ArgsBin, N.RecordOffset + 4 * 4), (2u << 30) | (1u << 29) | 6u); // e: AO
  // float3 array elements take 16 bytes; the fourth float is zero.
  EXPECT_EQ(floatAt(CG.ArgsBin, N.Args[5].ArrayByteOffset + 16), 4.0f);
  EXPECT_EQ(floatAt(CG.ArgsBin, N.Args[5].ArrayByteOffset + 12), 0.0f);
}

TEST(Encoding, RandomGraphsRoundTrip) {
  unsigned Seed = 7;
  auto Next = [&](unsigned N) {
    Seed = Seed * 1103515245u + 12345u;
    return (Seed >> 16) % N;
  };
  for (int Round = 0; Round < 30; ++Round) {
    std::string Nodes = "{\"id\": \"l0\", \"fn\": \"leaf\", \"args\": {\"x\": 1}}";
    unsigned Count = 1 + Next(20);
    for (unsigned I = 1; I < Count; ++I) {
      std::string Prev = "{\"node\": \"l" + std::to_string(Next(I)) + "\"}";
      if (Next(2))
        Nodes += ", {\"id\": \"l" + std::to_string(I) +
                 "\", \"fn\": \"leaf\", \"args\": {\"x\": " +
                 (Next(2) ? Prev : std::to_string(I * 0.25)) + "}}";
      else
        Nodes += ", {\"id\": \"l" + std::to_string(I) +
                 "\", \"fn\": \"all\", \"args\": {\"a\": " + Prev + ", \"b\": " + Prev +
                 ", \"c\": [" + std::to_string(I) + ", 1], \"d\": " + std::to_string(I) +
                 ", \"e\": {\"attr\": \"AO\"}, \"arr\": [[" + std::to_string(I) +
                 ", 0, 1]], \"s\": {\"image\": \"i\"}}}";
    }
    std::string Json = "{\"texcc\": 1, \"images\": {\"i\": \"i.png\"}, \"nodes\": [" + Nodes +
                       "], \"materials\": {\"m\": {\"bsdf\": \"diffuse\", \"color\": {\"node\": "
                       "\"l" + std::to_string(Count - 1) + "\"}}, \"k\": {\"bsdf\": \"glossy\", "
                       "\"color\": 1, \"roughness\": {\"node\": \"l" +
                       std::to_string(Next(Count)) + "\"}}}}";
    DiagnosticSink D;
    auto G = parse(Json, D);
    ASSERT_TRUE(G) << text(D);
    auto CG = compileGraph(*G, layoutSigs(), CompileOptions(), D);
    if (!CG) // a float4 'all' node read by a float: a type error; skip this round
      continue;
    expectDecodesTo(*CG);
  }
}

TEST(LayoutJson, GraphPartAndSignaturesRoundTrip) {
  CompiledGraph CG = compiled(AllGraph, CompileOptions(), layoutSigs());
  nlohmann::json J = nlohmann::json::parse(layoutJson(CG));
  EXPECT_EQ(J["texcc"], 1);
  EXPECT_EQ(J["stackSlots"], CG.StackSlots);
  EXPECT_EQ(J["spill"], false);
  EXPECT_EQ(J["maxOutputs"], 3);
  EXPECT_EQ(J["argsBin"]["size"], CG.ArgsBin.size());
  EXPECT_EQ(J["argsBin"]["recordsOffset"], 112);
  EXPECT_EQ(J["attributes"], (nlohmann::json{"AO"}));
  EXPECT_EQ(J["images"][1]["name"], "i1");
  EXPECT_EQ(J["images"][1]["index"], 1);
  const nlohmann::json &N = J["nodes"][CG.findNode("n")];
  EXPECT_EQ(N["record"]["offset"], CG.Nodes[CG.findNode("n")].RecordOffset);
  EXPECT_EQ(N["args"][1]["source"], "node");
  EXPECT_EQ(N["args"][1]["broadcast"], true);
  EXPECT_EQ(N["args"][1]["offset"], 16);
  EXPECT_EQ(N["args"][3]["value"], (nlohmann::json{-7}));
  EXPECT_EQ(N["args"][5]["array"]["count"], 3);
  EXPECT_EQ(N["args"][6]["image"], "i1");
  EXPECT_EQ(J["materials"][0]["bsdf"]["type"], "blend");
  EXPECT_EQ(J["materials"][0]["bsdf"]["b"]["color"]["const"], (nlohmann::json{0.5, 0.5, 0.5}));
  EXPECT_EQ(J["materials"][1]["outputs"].size(), 0u);
  bool Found = false;
  for (const auto &F : J["functions"])
    if (F["name"] == "all") {
      Found = true;
      EXPECT_EQ(F["blockSize"], 80);
      EXPECT_EQ(F["params"][4]["offset"], 48);
      EXPECT_EQ(F["params"][5]["type"], "__global const float3*");
    }
  EXPECT_TRUE(Found);

  SignatureMap Back;
  std::map<std::string, unsigned> Ids;
  std::string Error;
  ASSERT_TRUE(readLayoutSignatures(layoutJson(CG), Back, Ids, Error)) << Error;
  // Every node's function, the dead node z's 'none' too, after the live ones.
  ASSERT_EQ(Back.size(), 4u);
  EXPECT_EQ(Ids.at("none"), 3u);
  for (const auto &[Name, Sig] : Back) {
    const FunctionSignature &Orig = layoutSigs().at(Name);
    EXPECT_EQ(Sig.Return, Orig.Return);
    ASSERT_EQ(Sig.Params.size(), Orig.Params.size());
    for (size_t I = 0; I < Sig.Params.size(); ++I) {
      EXPECT_EQ(Sig.Params[I].Name, Orig.Params[I].Name);
      EXPECT_EQ(Sig.Params[I].Type, Orig.Params[I].Type);
    }
    EXPECT_EQ(CG.FunctionsById.at(Ids.at(Name)), Name);
  }
  EXPECT_FALSE(readLayoutSignatures("{", Back, Ids, Error));
  EXPECT_NE(Error.find("malformed layout.json"), std::string::npos);
}

TEST(Types, SpellingsRoundTrip) {
  for (BaseType B : {BaseType::Float, BaseType::Float2, BaseType::Float3, BaseType::Float4,
                     BaseType::Int, BaseType::Sampler}) {
    ValueType T{B, false};
    EXPECT_EQ(parseSpelling(spelling(T)), T);
    if (B != BaseType::Sampler) {
      ValueType A{B, true};
      EXPECT_EQ(parseSpelling(spelling(A)), A) << spelling(A);
    }
  }
  EXPECT_EQ(spelling(ValueType{BaseType::Float4, true}), "__global const float4*");
  EXPECT_FALSE(parseSpelling("double"));
  EXPECT_TRUE(isAssignable(BaseType::Float, ValueType{BaseType::Float3, false}));
  EXPECT_FALSE(isAssignable(BaseType::Float3, ValueType{BaseType::Float, false}));
  EXPECT_FALSE(isAssignable(BaseType::Float2, ValueType{BaseType::Float3, false}));
  EXPECT_FALSE(isAssignable(BaseType::Float, ValueType{BaseType::Float, true}));
}

TEST(Signature, AttributeTableIsAbiOrder) {
  const char *Names[] = {"WorldPos", "ObjectPos", "Normal",      "GeomNormal", "Tangent",
                         "TexCoord0", "AO",       "ViewDir",     "TangentSign", "Backfacing"};
  ASSERT_EQ(attributeTable().size(), 10u);
  for (int I = 0; I < 10; ++I)
    EXPECT_EQ(attributeId(Names[I]), I);
  EXPECT_EQ(attributeTable()[5].second, BaseType::Float2);
  EXPECT_EQ(attributeTable()[6].second, BaseType::Float);
  EXPECT_EQ(attributeTable()[8].second, BaseType::Float);
  EXPECT_EQ(attributeTable()[9].second, BaseType::Float);
  EXPECT_EQ(attributeId("Nope"), -1);
  ASSERT_EQ(settingTable().size(), 3u);
  EXPECT_EQ(settingTable()[1].second, BaseType::Int);
}

} // namespace

namespace {

/// turn(float3 p, float angle, float stretch) with c, s (from angle) and dir (a float3, from
/// stretch) hoisted, as the front end would report them in shape mode.
SignatureMap hoistingSigs() {
  SignatureMap S = sigs(R"([
    {"name": "turn", "return": "float3", "params": [{"name": "p", "type": "float3"},
      {"name": "angle", "type": "float"}, {"name": "stretch", "type": "float"}]}
  ])");
  FunctionSignature &T = S.at("turn");
  T.Hoisted = {{"c", BaseType::Float}, {"s", BaseType::Float}, {"dir", BaseType::Float3}};
  T.HoistedFrom = {1, 2};
  return S;
}

} // namespace

TEST(Layout, HoistedValuesFollowTheParametersInTheBlock) {
  const SignatureMap Sigs = hoistingSigs();
  const FunctionSignature &T = Sigs.at("turn");
  uint32_t Block = 0;
  EXPECT_EQ(parameterOffsets(T, Block), (std::vector<uint32_t>{0, 16, 20}));
  // c at 24, s at 28, dir (16-aligned) at 32; the block covers them: 48.
  EXPECT_EQ(hoistedOffsets(T), (std::vector<uint32_t>{24, 28, 32}));
  EXPECT_EQ(Block, 48u);
  FunctionSignature Plain = T;
  Plain.Hoisted.clear();
  Plain.HoistedFrom.clear();
  parameterOffsets(Plain, Block);
  EXPECT_EQ(Block, 32u);
}

TEST(Layout, ANodeHoistsWhenEveryParameterItReadsIsAnUnbakedConstant) {
  CompiledGraph CG = compiled(R"({"texcc": 1, "nodes": [
    {"id": "k", "fn": "turn", "args": {"p": {"attr": "ObjectPos"}, "angle": 0.5, "stretch": 2}},
    {"id": "w", "fn": "turn", "args": {"p": {"node": "k"}, "angle": {"attr": "AO"}, "stretch": 2}},
    {"id": "b", "fn": "turn", "args": {"p": {"node": "w"}, "angle": {"value": 1, "bake": true},
                                       "stretch": {"value": 3, "bake": true}}},
    {"id": "h", "fn": "turn", "args": {"p": {"node": "b"}, "angle": {"value": 1, "bake": true},
                                       "stretch": 4}}],
    "materials": {"m": {"bsdf": "diffuse", "color": {"node": "h"}}}})",
                              CompileOptions(), hoistingSigs());
  const FunctionSignature &T = CG.Signatures.at("turn");
  EXPECT_TRUE(hoistsUniforms(CG.Nodes[CG.findNode("k")], T));
  EXPECT_FALSE(hoistsUniforms(CG.Nodes[CG.findNode("w")], T)); // angle is an attribute
  EXPECT_FALSE(hoistsUniforms(CG.Nodes[CG.findNode("b")], T)); // all baked: literals
  EXPECT_TRUE(hoistsUniforms(CG.Nodes[CG.findNode("h")], T));  // stretch is not baked
  for (const CompiledNode &N : CG.Nodes)
    EXPECT_EQ(N.RecordSize, 16u + 48u) << N.Id; // the block has room for the hoisted values

  // layout.json lists them, and the live editor reads them back.
  nlohmann::json J = nlohmann::json::parse(layoutJson(CG));
  const auto &H = J["functions"][0]["hoisted"];
  EXPECT_EQ(H["values"][2]["name"], "dir");
  EXPECT_EQ(H["values"][2]["type"], "float3");
  EXPECT_EQ(H["values"][2]["offset"], 32);
  EXPECT_EQ(H["from"], nlohmann::json::parse(R"(["angle", "stretch"])"));
  SignatureMap Back;
  std::map<std::string, unsigned> Ids;
  std::string Error;
  ASSERT_TRUE(readLayoutSignatures(layoutJson(CG), Back, Ids, Error)) << Error;
  ASSERT_EQ(Back.at("turn").Hoisted.size(), 3u);
  EXPECT_EQ(Back.at("turn").Hoisted[2].Type, BaseType::Float3);
  EXPECT_EQ(Back.at("turn").HoistedFrom, (std::vector<unsigned>{1, 2}));
  uint32_t Block = 0;
  parameterOffsets(Back.at("turn"), Block);
  EXPECT_EQ(Block, 48u);
}
