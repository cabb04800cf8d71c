// The backends' registry and policies: every mode name parses to its backend and back, the host
// target takes the host backend whatever the mode, and the interp-only machinery (hoisting in
// the interpreter, the interpreter's user code) is asked of the backend; its quickened opcodes
// (interp's finishGraph) are QuickenedTest's.
#include "texcc/Codegen/Backend.h"

#include <gtest/gtest.h>

using namespace texcc;
using namespace texcc::codegen;

namespace {

TEST(Backend, RegistryNamesRoundTrip) {
  for (const char *Name : {"interp", "inline", "wavefront", "shape"}) {
    std::optional<Mode> M = parseMode(Name);
    ASSERT_TRUE(M) << Name;
    EXPECT_STREQ(modeName(*M), Name);
    EXPECT_STREQ(backendFor(*M, Target::OpenCL).name(), Name);
  }
  EXPECT_FALSE(parseMode("host"));
  EXPECT_FALSE(parseMode("Interp"));
  EXPECT_EQ(modeNameList(), "interp, inline, wavefront or shape");
}

TEST(Backend, HostTargetWhateverTheMode) {
  for (Mode M : {Mode::Interp, Mode::Inline, Mode::Wavefront, Mode::Shape}) {
    const Backend &B = backendFor(M, Target::Host);
    EXPECT_STREQ(B.name(), "host");
    EXPECT_FALSE(B.interprets());
    EXPECT_FALSE(B.writesInterpreter());
    EXPECT_FALSE(B.hoists(BackendOptions()));
  }
}

TEST(Backend, InterpreterMachineryBelongsToInterp) {
  BackendOptions O;
  O.MaxQuickened = 5;
  for (Mode M : {Mode::Interp, Mode::Inline, Mode::Wavefront, Mode::Shape}) {
    const Backend &B = backendFor(M, Target::OpenCL);
    CodegenOptions CO;
    B.configureCodegen(CO, O);
    const bool Interp = M == Mode::Interp;
    EXPECT_EQ(CO.InterpHoists, Interp) << B.name();
    EXPECT_EQ(B.interprets(), Interp) << B.name();
    // Shape mode writes the interp kernel too, as its fallback.
    EXPECT_EQ(B.writesInterpreter(), Interp || M == Mode::Shape) << B.name();
    // The front end hoists for the backends that read hoisted values: interp and shape.
    EXPECT_EQ(B.hoists(O), Interp || M == Mode::Shape) << B.name();
  }
  O.NoHoist = true;
  CodegenOptions CO;
  backendFor(Mode::Interp, Target::OpenCL).configureCodegen(CO, O);
  EXPECT_FALSE(CO.InterpHoists);
  EXPECT_FALSE(backendFor(Mode::Shape, Target::OpenCL).hoists(O));
}

} // namespace
