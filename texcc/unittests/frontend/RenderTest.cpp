// TranslatedSource::render: #line framing, macro hygiene, omitted definitions.
#include "texcc/Frontend/Frontend.h"

#include "gtest/gtest.h"

using namespace texcc::frontend;

namespace {

TranslatedSource translate(const std::string &Code) {
  FrontendOptions Opts;
  Opts.VirtualFiles["k.cl"] = Code;
  std::string Diags;
  llvm::raw_string_ostream OS(Diags);
  auto R = runFrontend({"k.cl"}, {}, Opts, OS);
  EXPECT_TRUE(bool(R)) << OS.str();
  if (!R) {
    llvm::consumeError(R.takeError());
    return {};
  }
  return R->Sources[0];
}

TEST(RenderTest, FramesWithLineAndUndef) {
  TranslatedSource T = translate("#define K 2.0f\nfloat f(void) { return K; }\n");
  EXPECT_EQ(T.render(), "#line 1 \"k.cl\"\n"
                        "#define K 2.0f\n"
                        "TEXCC_FN float k_f(TEXCC_CTX_PARAM) { return K; }\n"
                        "#undef K\n");
}

TEST(RenderTest, OmitsUnkeptDefinitionsAndKeepsLineNumbers) {
  TranslatedSource T = translate("float a(void) { return 1.0f; }\n"
                                 "float b(void) {\n"
                                 "  return 2.0f;\n"
                                 "}\n"
                                 "float c(void) { return 3.0f; }\n");
  EXPECT_EQ(T.render({"k_a", "k_c"}), "#line 1 \"k.cl\"\n"
                                      "TEXCC_FN float k_a(TEXCC_CTX_PARAM) { return 1.0f; }\n"
                                      "\n#line 4 \"k.cl\"\n"
                                      "\n"
                                      "TEXCC_FN float k_c(TEXCC_CTX_PARAM) { return 3.0f; }\n");
  // An empty Keep keeps everything.
  EXPECT_NE(T.render().find("k_b"), std::string::npos);
}

TEST(RenderTest, PredefinedMacrosAreDefinedAndUndefined) {
  TranslatedSource T;
  T.Path = "p.cl";
  T.Text = "float x;\n";
  T.Predefined = {{"N", "4"}};
  EXPECT_EQ(T.render(), "#define N 4\n#line 1 \"p.cl\"\nfloat x;\n#undef N\n");
}

TEST(RenderTest, QuotesPathsInLineDirectives) {
  TranslatedSource T;
  T.Path = "a\"b\\c.cl";
  T.Text = "\n";
  EXPECT_EQ(T.render(), "#line 1 \"a\\\"b\\\\c.cl\"\n\n");
}

} // namespace
