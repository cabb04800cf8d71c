// The live-edit planner (EditPlan.h) without a device: every row of docs/modes.md's "What an
// edit costs" for every kind of kernel texrender runs, from capabilities as the backends write
// them into layout.json (asked of the backends, one per column of the table) and the facts
// the graph library reports about the edited graph. No mode names: the planner never sees one.
#include "texcc/Codegen/Backend.h"
#include "texrender/EditPlan.h"
#include "texrender/Error.h"
#include "texrender/Layout.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace texrender;

namespace {

/// The kernels of docs/modes.md's edit-cost table, by what their backend publishes.
enum class Kernel { Interp, Inline, Wavefront, Shape };
constexpr Kernel Interp = Kernel::Interp, Inline = Kernel::Inline,
                 Wavefront = Kernel::Wavefront, Shape = Kernel::Shape;

/// What the backend of K writes into layout.json (texcc/lib/codegen/Backend.cpp, the one table):
/// the planner's input, read here from the backends themselves.
KernelCapabilities caps(Kernel K) {
  using texcc::codegen::Mode;
  const Mode M = K == Kernel::Interp   ? Mode::Interp
                 : K == Kernel::Inline ? Mode::Inline
                 : K == Kernel::Wavefront ? Mode::Wavefront
                                          : Mode::Shape;
  texcc::codegen::CodegenOptions Opts;
  Opts.EvalMode = M;
  return texcc::codegen::backendFor(M, texcc::codegen::Target::OpenCL)
      .capabilities(texcc::graph::CompiledGraph{}, Opts);
}

const char *plan(Kernel K, const EditFacts &F, TierState S = {TierPolicy::Auto, 8, 8}) {
  return editActionName(planEdit(F, caps(K), S));
}

/// A parameter value: nothing about the wiring or the kernel changes.
EditFacts valueEdit() {
  EditFacts F;
  F.StackSlots = 2;
  F.ShapeChanged = false;
  return F;
}

/// A rewiring onto another node of a function the kernel has, that changes the shapes.
EditFacts rewire() {
  EditFacts F = valueEdit();
  F.Structural = true;
  F.ShapeChanged = true;
  return F;
}

/// The edited graph needs one thing the kernel was not made for.
EditFacts needing(bool OnlyStack, unsigned Slots, unsigned Outputs = 1, bool Attribute = false) {
  EditFacts F = rewire();
  F.NeedsRebuild = true;
  F.NeedsOnlyStackSlots = OnlyStack;
  F.StackSlots = Slots;
  F.MaxOutputs = Outputs;
  F.NeedsAttributeCase = Attribute;
  return F;
}

} // namespace

// Row 1: a parameter value.
TEST(EditPlan, ValueEdit) {
  EXPECT_STREQ(plan(Interp, valueEdit()), "upload");
  EXPECT_STREQ(plan(Inline, valueEdit()), "regenerate"); // the value is a literal
  EXPECT_STREQ(plan(Wavefront, valueEdit()), "upload");
  for (TierPolicy T : {TierPolicy::Auto, TierPolicy::Interp, TierPolicy::Shape})
    EXPECT_STREQ(plan(Shape, valueEdit(), {T, 8, 8}), "upload");
}

// Row 1, shape mode: a baked argument is a literal of the shape code, so its edit is a new shape.
TEST(EditPlan, BakedArgumentInShapeMode) {
  EditFacts F = valueEdit();
  F.Structural = true; // the argument is {"value": v, "bake": true}
  F.ShapeChanged = true;
  EXPECT_STREQ(plan(Shape, F, {TierPolicy::Auto, 8, 0}), "switch-shapes");
  EXPECT_STREQ(plan(Shape, F, {TierPolicy::Interp, 8, 0}), "upload");
  EXPECT_STREQ(plan(Shape, F, {TierPolicy::Shape, 0, 0}), "regenerate");
  // auto, but the fallback is still building: the edit regenerates in the foreground.
  EXPECT_STREQ(plan(Shape, F, {TierPolicy::Auto, 0, 0}), "regenerate");
}

// Row 2: a rewiring onto any node of the graph.
TEST(EditPlan, Rewire) {
  EXPECT_STREQ(plan(Interp, rewire()), "upload"); // the wiring is data
  EXPECT_STREQ(plan(Inline, rewire()), "regenerate");
  EXPECT_STREQ(plan(Wavefront, rewire()), "regenerate"); // the wiring is code (the launches)
  EXPECT_STREQ(plan(Shape, rewire()), "switch-shapes");   // tiered: interp fallback meanwhile
  EXPECT_STREQ(plan(Shape, rewire(), {TierPolicy::Shape, 0, 0}), "regenerate");
  EXPECT_STREQ(plan(Shape, rewire(), {TierPolicy::Interp, 8, 0}), "upload");
}

// Row 2, shape mode: no build when every material keeps its shape key.
TEST(EditPlan, RewireKeepingTheShapes) {
  EditFacts F = rewire();
  F.ShapeChanged = false;
  EXPECT_STREQ(plan(Shape, F), "upload");
  EXPECT_STREQ(plan(Shape, F, {TierPolicy::Shape, 0, 0}), "upload");
  // A layout without kernel.shapeHash: the JSON-level wiring change decides.
  F.ShapeChanged.reset();
  EXPECT_STREQ(plan(Shape, F), "switch-shapes");
}

// Row 2, interp: unless the edit needs more than the kernel has.
TEST(EditPlan, InterpNeedsMoreThanTheKernel) {
  EXPECT_STREQ(plan(Interp, needing(true, 6), {TierPolicy::Auto, 0, 8}), "upload"); // headroom
  EXPECT_STREQ(plan(Interp, needing(true, 9), {TierPolicy::Auto, 0, 8}), "regenerate");
  EditFacts Spilling = needing(true, 6);
  Spilling.Spill = true;
  EXPECT_STREQ(plan(Interp, Spilling, {TierPolicy::Auto, 0, 8}), "regenerate");
  EXPECT_STREQ(plan(Interp, needing(false, 2, 4)), "regenerate");       // more outputs
  EXPECT_STREQ(plan(Interp, needing(false, 2, 1, true)), "regenerate"); // an attribute case
  EXPECT_STREQ(plan(Interp, needing(false, 2)), "regenerate"); // e.g. wires a hoisted parameter
}

// Row 2, shape: the interp fallback runs what its value stack, outputs and decoder hold.
TEST(EditPlan, ShapeFallbackHeadroom) {
  KernelCapabilities C = caps(Shape);
  C.MaxOutputs = 2;
  auto P = [&](const EditFacts &F, TierState S) { return editActionName(planEdit(F, C, S)); };
  EXPECT_STREQ(P(needing(true, 6), {TierPolicy::Auto, 8, 0}), "switch-shapes");
  EXPECT_STREQ(P(needing(true, 6), {TierPolicy::Interp, 8, 0}), "upload");
  EXPECT_STREQ(P(needing(true, 9), {TierPolicy::Auto, 8, 0}), "regenerate");
  EXPECT_STREQ(P(needing(false, 2, 3), {TierPolicy::Auto, 8, 0}), "regenerate");
  EXPECT_STREQ(P(needing(false, 2, 2), {TierPolicy::Auto, 8, 0}), "switch-shapes");
  EXPECT_STREQ(P(needing(false, 2, 1, true), {TierPolicy::Auto, 8, 0}), "regenerate");
  EXPECT_STREQ(P(needing(true, 6), {TierPolicy::Shape, 8, 0}), "regenerate");
}

// Row 3: a node of a function no kernel of the layout has a case for (a layout whose functions
// list lacks it; set and rewire reach only the graph's nodes) regenerates in every mode, under
// every tier policy: the interp fallback and the headroom have no case for it either.
TEST(EditPlan, NewFunction) {
  EditFacts F = needing(false, 2);
  F.NeedsFunction = true;
  for (Kernel K : {Interp, Inline, Wavefront, Shape})
    for (TierPolicy T : {TierPolicy::Auto, TierPolicy::Interp, TierPolicy::Shape})
      EXPECT_STREQ(plan(K, F, {T, 8, 8}), "regenerate")
          << static_cast<int>(K) << " " << tierPolicyName(T);
  // The same edit without the new function: the shape fallback would have run it.
  F.NeedsFunction = false;
  EXPECT_STREQ(plan(Shape, F), "switch-shapes");
}

// Wavefront and inline have neither headroom nor a fallback.
TEST(EditPlan, NoHeadroomElsewhere) {
  for (Kernel M : {Inline, Wavefront}) {
    EXPECT_STREQ(plan(M, needing(true, 6), {TierPolicy::Auto, 8, 8}), "regenerate") << static_cast<int>(M);
    EXPECT_STREQ(plan(M, needing(false, 2, 1, true), {TierPolicy::Auto, 8, 8}), "regenerate") << static_cast<int>(M);
  }
}

namespace {

/// Loads a layout.json of Text (with an empty args.bin) from a folder of its own.
texrender::Layout loadText(const std::string &Text) {
  namespace fs = std::filesystem;
  fs::path Dir = fs::temp_directory_path() / ("texrender-editplan-" + std::to_string(::getpid()));
  fs::create_directories(Dir);
  std::ofstream(Dir / "layout.json") << Text;
  std::ofstream(Dir / "args.bin") << "";
  struct Remove {
    fs::path D;
    ~Remove() { fs::remove_all(D); }
  } R{Dir};
  return loadLayout(Dir.string());
}

} // namespace

// The layout reader gives the planner its capabilities and the regeneration its options.
TEST(EditPlan, LayoutCapabilitiesAndCompileOptions) {
  Layout L = loadText(R"({"texcc": 1, "mode": "wavefront", "maxOutputs": 3,
      "compileOptions": ["--mode=wavefront", "-I/abs/inc", "-DK=2"],
      "kernel": {"source": "proctex.cl", "entry": "texcc_wf_outputs"}, "materials": [],
      "capabilities": {"reEncodes": true, "maxOutputs": 3}})");
  EXPECT_EQ(L.CompileOptions, (std::vector<std::string>{"--mode=wavefront", "-I/abs/inc", "-DK=2"}));
  EXPECT_TRUE(L.Caps.ReEncodes);
  EXPECT_FALSE(L.Caps.WiringIsData);
  EXPECT_EQ(L.Caps.MaxOutputs, 3u);
  // A layout from a texcc before compileOptions: a regeneration passes the mode.
  Layout Old = loadText(
      R"({"texcc": 1, "mode": "inline", "kernel": {"source": "proctex.cl"}, "materials": [],
          "capabilities": {"reEncodes": false}})");
  EXPECT_EQ(Old.CompileOptions, std::vector<std::string>{"--mode=inline"});
  EXPECT_FALSE(Old.Caps.ReEncodes);
}

TEST(EditPlan, MalformedCompileOptions) {
  for (const char *CO : {R"("-DK=2")", R"(["-DK=2", 3])"}) {
    try {
      loadText(std::string(R"({"texcc": 1, "mode": "interp", "compileOptions": )") + CO +
               R"(, "kernel": {"source": "proctex.cl"}, "materials": []})");
      FAIL() << "no error for " << CO;
    } catch (const Error &E) {
      EXPECT_NE(std::string(E.what()).find("/compileOptions: expected an array of strings"),
                std::string::npos)
          << E.what();
    }
  }
}
