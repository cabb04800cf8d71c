// runFrontend on in-memory sources (FrontendOptions::VirtualFiles): rewriting, signatures,
// call graph, diagnostics.
#include "texcc/Frontend/Frontend.h"

#include "gtest/gtest.h"

using namespace texcc;
using namespace texcc::frontend;

namespace {

struct FrontendRun {
  llvm::Expected<FrontendResult> Result;
  std::string Diags;
};

FrontendRun runOn(const std::map<std::string, std::string> &Files,
          const std::set<std::string> &Textures = {}) {
  FrontendOptions Opts;
  Opts.VirtualFiles = Files;
  std::vector<std::string> Sources;
  for (const auto &F : Files)
    Sources.push_back(F.first);
  std::string Diags;
  llvm::raw_string_ostream OS(Diags);
  auto R = runFrontend(Sources, Textures, Opts, OS);
  OS.flush();
  return {std::move(R), Diags};
}

TEST(FrontendTest, PreludeGivesEachAttributeItsType) {
  FrontendRun R = runOn({{"types.cl", "float f(void) {\n"
                              "  float3 n = readAttr(\"Normal\");\n"
                              "  float2 uv = readAttr(\"TexCoord0\");\n"
                              "  float ao = readAttr(\"AO\");\n"
                              "  int frame = readSetting(\"Frame\");\n"
                              "  return n.x + uv.y + ao + frame;\n"
                              "}\n"}});
  ASSERT_TRUE(bool(R.Result)) << R.Diags;
  EXPECT_EQ(R.Diags, "");
}

TEST(FrontendTest, MismatchIsReportedAtTheUsersLine) {
  FrontendRun R = runOn({{"bad.cl", "float f(void) {\n  float2 n = readAttr(\"Normal\");\n  return n.x;\n}\n"}});
  ASSERT_FALSE(bool(R.Result));
  llvm::consumeError(R.Result.takeError());
  EXPECT_NE(R.Diags.find("bad.cl:2:10: error: initializing"), std::string::npos) << R.Diags;
}

TEST(FrontendTest, PrefixesAreUniqueAndSanitized) {
  FrontendRun R = runOn({{"dir1/my-noise.cl", "float f(void) { return 1.0f; }\n"},
                 {"dir2/my-noise.cl", "float f(void) { return 2.0f; }\n"},
                 {"3d.cl", "float f(void) { return 3.0f; }\n"}});
  ASSERT_TRUE(bool(R.Result)) << R.Diags;
  ASSERT_EQ(R.Result->Sources.size(), 3u);
  EXPECT_EQ(R.Result->Sources[0].Prefix, "_3d_");
  EXPECT_EQ(R.Result->Sources[1].Prefix, "my_noise_");
  EXPECT_EQ(R.Result->Sources[2].Prefix, "my_noise2_");
  EXPECT_EQ(R.Result->Sources[2].Functions.at("f"), "my_noise2_f");
}

TEST(FrontendTest, RewritesDefinitionsCallsAndApi) {
  FrontendRun R = runOn({{"n.cl", "float g(float x) { return x; }\n"
                          "float f(void) { return g(readAttr(\"AO\")) + sin(1.0f); }\n"}});
  ASSERT_TRUE(bool(R.Result)) << R.Diags;
  EXPECT_EQ(R.Result->Sources[0].Text,
            "TEXCC_FN float n_g(TEXCC_CTX_PARAM, float x) { return x; }\n"
            "TEXCC_FN float n_f(TEXCC_CTX_PARAM) { return n_g(TEXCC_CTX_ARG, texcc_attr_AO(texcc_ctx)) + "
            "sin(1.0f); }\n");
}

TEST(FrontendTest, MarksDeclarationsInlineButNotMacroMadeOrNoinlineOnes) {
  FrontendRun R = runOn({{"m.cl", "#define DEF(n) float n(void) { return 1.0f; }\n"
                                  "DEF(one)\n"
                                  "float later(float x);\n"
                                  "__attribute__((noinline)) float slow(float x) { return x; }\n"
                                  "float later(float x) { return slow(x) + one(); }\n"}});
  ASSERT_TRUE(bool(R.Result)) << R.Diags;
  const std::string &T = R.Result->Sources[0].Text;
  EXPECT_NE(T.find("\nDEF(m_one)\n"), std::string::npos) << T;
  EXPECT_NE(T.find("\nTEXCC_FN float m_later(TEXCC_CTX_PARAM, float x);\n"), std::string::npos) << T;
  EXPECT_NE(T.find("\n__attribute__((noinline)) float m_slow("), std::string::npos) << T;
  EXPECT_NE(T.find("\nTEXCC_FN float m_later(TEXCC_CTX_PARAM, float x) {"), std::string::npos) << T;
}

TEST(FrontendTest, CollectsSignatureAndCallTree) {
  FrontendRun R = runOn({{"wood.cl", "float grain(float3 p) { return readAttr(\"AO\") * p.x; }\n"
                             "float unused(void) { return readSetting(\"Time\"); }\n"
                             "float4 wood(float3 p, __global const float4 *stops, sam2D img) {\n"
                             "  return stops[0] * grain(p) + tex2D(img, readAttr(\"TexCoord0\"));\n"
                             "}\n"}},
                {"wood", "missing"});
  ASSERT_TRUE(bool(R.Result)) << R.Diags;
  const FrontendResult &F = *R.Result;
  ASSERT_EQ(F.Textures.count("missing"), 0u);
  const graph::FunctionSignature &S = F.Textures.at("wood");
  EXPECT_EQ(S.RenamedName, "wood_wood");
  EXPECT_EQ(S.File, "wood.cl");
  EXPECT_EQ(S.Return, graph::BaseType::Float4);
  ASSERT_EQ(S.Params.size(), 3u);
  EXPECT_EQ(S.Params[0].Name, "p");
  EXPECT_EQ(S.Params[0].Type, (graph::ValueType{graph::BaseType::Float3, false}));
  EXPECT_EQ(S.Params[1].Type, (graph::ValueType{graph::BaseType::Float4, true}));
  EXPECT_EQ(S.Params[2].Type, (graph::ValueType{graph::BaseType::Sampler, false}));
  EXPECT_EQ(S.Attributes, (std::vector<std::string>{"AO", "TexCoord0"}));
  EXPECT_TRUE(S.Settings.empty());
  EXPECT_EQ(F.Reachable.at("wood"), (std::set<std::string>{"wood_grain", "wood_wood"}));
  const TranslatedSource &T = F.Sources[0];
  EXPECT_EQ(T.Calls.at("wood_wood"), (std::set<std::string>{"wood_grain"}));
  EXPECT_TRUE(T.Calls.at("wood_unused").empty());
  EXPECT_EQ(T.Definitions.size(), 3u);
}

TEST(FrontendTest, CostCountsStatementsLoopTripsAndCallees) {
  // Cost (superinstructions fuse only light functions): every statement and expression counts
  // 1 (implicit casts and parentheses 0), times the trips of the loops around it (constant
  // bounds: the count; otherwise 8), and a call adds the callee's cost.
  FrontendRun R = runOn(
      {{"cost.cl", "float one(float x) { return (x); }\n"
                   "float two(float x) { return one(x) + one(x); }\n"
                   "float loop10(float x) { float s = 0.0f; for (int i = 0; i < 10; ++i) s += x; return s; }\n"
                   "float loop20(float x) { float s = 0.0f; for (int i = 0; i < 20; ++i) s += x; return s; }\n"
                   "float loopDown(float x) { float s = 0.0f; for (int i = 20; i > 0; i -= 2) s += x; return s; }\n"
                   "float loopN(float x, int n) { float s = 0.0f; for (int i = 0; i < n; ++i) s += x; return s; }\n"
                   "float callIn(float x) { float s = 0.0f; for (int i = 0; i < 10; ++i) s += one(x); return s; }\n"}},
      {"one", "two", "loop10", "loop20", "loopDown", "loopN", "callIn"});
  ASSERT_TRUE(bool(R.Result)) << R.Diags;
  auto Cost = [&](const char *F) { return R.Result->Textures.at(F).Cost; };
  EXPECT_EQ(Cost("one"), 3u); // { return x; }: compound, return, x
  // { return one(x) + one(x); }: compound, return, +, 2 calls, 2 callee names, 2 x; 2 x one.
  EXPECT_EQ(Cost("two"), 9u + 2 * Cost("one"));
  const unsigned PerTrip = (Cost("loop20") - Cost("loop10")) / 10;
  EXPECT_EQ(PerTrip, 8u); // i < 10 (3), ++i (2), s += x (3)
  // 20, 18, ..., 2: ten trips, each one more for i -= 2 (3) than for ++i (2).
  EXPECT_EQ(Cost("loopDown"), Cost("loop10") + 10);
  EXPECT_EQ(Cost("loop10") - Cost("loopN"), 2 * PerTrip); // an unknown count: 8 trips
  // one(x) in the loop: 10 x (call, callee name, x, and one's cost) in place of x.
  EXPECT_EQ(Cost("callIn"), Cost("loop10") + 10 * (2 + Cost("one")));
}

TEST(FrontendTest, RecordsDefinedMacros) {
  FrontendRun R = runOn({{"m.cl", "#define A 1\n#define B(x) (x)\n#undef A\nfloat f(void) { return B(1.0f); }\n"}});
  ASSERT_TRUE(bool(R.Result)) << R.Diags;
  EXPECT_EQ(R.Result->Sources[0].DefinedMacros, (std::vector<std::string>{"A", "B"}));
}

TEST(FrontendTest, ReportsEveryRestriction) {
  FrontendRun R = runOn({{"r.cl", "float f(float x) { return f(x); }\n"
                          "float g(__global float *p) { p[0] = 1.0f; return readAttr(\"Nope\"); }\n"}});
  ASSERT_FALSE(bool(R.Result));
  EXPECT_EQ(llvm::toString(R.Result.takeError()), "3 errors in texture sources");
  EXPECT_NE(R.Diags.find("r.cl:1:27: error: recursion is not allowed in texture code: 'f' -> 'f'"),
            std::string::npos)
      << R.Diags;
  EXPECT_NE(R.Diags.find("r.cl:2:30: error: cannot write through __global pointer 'p'"),
            std::string::npos)
      << R.Diags;
  EXPECT_NE(R.Diags.find("r.cl:2:59: error: unknown attribute 'Nope'"), std::string::npos)
      << R.Diags;
}

TEST(FrontendTest, MissingFileIsAnError) {
  FrontendOptions Opts;
  std::string Diags;
  llvm::raw_string_ostream OS(Diags);
  auto R = runFrontend({"/nonexistent/x.cl"}, {}, Opts, OS);
  ASSERT_FALSE(bool(R));
  EXPECT_NE(llvm::toString(R.takeError()).find("cannot open '/nonexistent/x.cl'"),
            std::string::npos);
}

} // namespace

namespace {

FrontendRun hoistingRun(const std::string &Code, const std::set<std::string> &Constant) {
  FrontendOptions Opts;
  Opts.VirtualFiles = {{"h.cl", Code}};
  Opts.HoistableParams = {{"f", Constant}};
  std::string Diags;
  llvm::raw_string_ostream OS(Diags);
  auto R = runFrontend({"h.cl"}, {"f"}, Opts, OS);
  OS.flush();
  return {std::move(R), Diags};
}

std::vector<std::string> hoistedNames(const FrontendResult &R) {
  std::vector<std::string> Names;
  for (const graph::HoistedValue &V : R.Textures.at("f").Hoisted)
    Names.push_back(V.Name);
  return Names;
}

} // namespace

TEST(FrontendTest, HoistsOnlyDeclarationsOfConstantParametersSpelledInTheFile) {
  const std::string Code = "#define DECL(v, e) float v = e;\n"
                           "float f(float3 p, float a, float b) {\n"
                           "  float c = cos(a);\n"       // hoisted
                           "  DECL(d, sin(a))\n"         // made by a macro: stays
                           "  float e = sin(b);\n"       // b is not constant: stays
                           "  float g = fmax(c, 0.5f);\n" // reads hoisted c: hoisted
                           "  if (p.x > 0.0f) {\n"
                           "    float h = cos(a);\n"     // not at the top level: stays
                           "    return h;\n"
                           "  }\n"
                           "  return c + d + e + g + p.y;\n"
                           "}\n";
  FrontendRun R = hoistingRun(Code, {"a"});
  ASSERT_TRUE(bool(R.Result)) << R.Diags;
  EXPECT_EQ(hoistedNames(*R.Result), (std::vector<std::string>{"c", "g"}));
  EXPECT_EQ(R.Result->Textures.at("f").HoistedFrom, std::vector<unsigned>{1});
  const TranslatedSource &S = R.Result->Sources.at(0);
  ASSERT_EQ(S.Hoisted.count("h_f"), 1u);
  const std::string &Text = S.Hoisted.at("h_f");
  EXPECT_NE(Text.find("void texcc_uniform_h_f(float a, float *texcc_out_c, float *texcc_out_g)"),
            std::string::npos) << Text;
  EXPECT_NE(Text.find("texcc_hoisted_h_f(TEXCC_CTX_PARAM, float3 p, float a, float b, float c, "
                      "float g)"),
            std::string::npos) << Text;
  // render() puts them after the definition only when asked (shape code).
  EXPECT_EQ(S.render().find("texcc_hoisted_h_f"), std::string::npos);
  EXPECT_NE(S.render({}, {"h_f"}).find("texcc_hoisted_h_f"), std::string::npos);

  // With no parameter known constant (every other mode), nothing is hoisted.
  FrontendRun None = hoistingRun(Code, {});
  ASSERT_TRUE(bool(None.Result)) << None.Diags;
  EXPECT_TRUE(None.Result->Textures.at("f").Hoisted.empty());
  EXPECT_TRUE(None.Result->Sources.at(0).Hoisted.empty());
}
