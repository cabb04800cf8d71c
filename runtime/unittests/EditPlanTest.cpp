// The live-edit planner (EditPlan.h) without a device: every row of docs/modes.md's "What an
// edit costs" in every mode texrender runs, from the modes' capabilities (Layout.cpp's table)
// and the facts the graph library reports about the edited graph.
#include "texrender/EditPlan.h"
#include "texrender/Error.h"
#include "texrender/Layout.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <unistd.h>

using namespace texrender;

namespace {

KernelCapabilities caps(const char *Mode) {
  std::optional<KernelCapabilities> C = modeCapabilities(Mode);
  EXPECT_TRUE(C) << Mode;
  return C ? *C : KernelCapabilities{};
}

const char *plan(const char *Mode, const EditFacts &F, TierState S = {TierPolicy::Auto, 8, 8}) {
  return editActionName(planEdit(F, caps(Mode), S));
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

TEST(EditPlan, ModesAreTheLayoutsOnly) {
  for (const char *M : {"interp", "inline", "wavefront", "shape"})
    EXPECT_TRUE(modeCapabilities(M)) << M;
  EXPECT_FALSE(modeCapabilities("host")); // texrender runs OpenCL output only
  EXPECT_FALSE(modeCapabilities("Interp"));
}

// Row 1: a parameter value.
TEST(EditPlan, ValueEdit) {
  EXPECT_STREQ(plan("interp", valueEdit()), "upload");
  EXPECT_STREQ(plan("inline", valueEdit()), "regenerate"); // the value is a literal
  EXPECT_STREQ(plan("wavefront", valueEdit()), "upload");
  for (TierPolicy T : {TierPolicy::Auto, TierPolicy::Interp, TierPolicy::Shape})
    EXPECT_STREQ(plan("shape", valueEdit(), {T, 8, 8}), "upload");
}

// Row 1, shape mode: a baked argument is a literal of the shape code, so its edit is a new shape.
TEST(EditPlan, BakedArgumentInShapeMode) {
  EditFacts F = valueEdit();
  F.Structural = true; // the argument is {"value": v, "bake": true}
  F.ShapeChanged = true;
  EXPECT_STREQ(plan("shape", F, {TierPolicy::Auto, 8, 0}), "switch-shapes");
  EXPECT_STREQ(plan("shape", F, {TierPolicy::Interp, 8, 0}), "upload");
  EXPECT_STREQ(plan("shape", F, {TierPolicy::Shape, 0, 0}), "regenerate");
  // auto, but the fallback is still building: the edit regenerates in the foreground.
  EXPECT_STREQ(plan("shape", F, {TierPolicy::Auto, 0, 0}), "regenerate");
}

// Row 2: a rewiring onto any node of the graph.
TEST(EditPlan, Rewire) {
  EXPECT_STREQ(plan("interp", rewire()), "upload"); // the wiring is data
  EXPECT_STREQ(plan("inline", rewire()), "regenerate");
  EXPECT_STREQ(plan("wavefront", rewire()), "regenerate"); // the wiring is code (the launches)
  EXPECT_STREQ(plan("shape", rewire()), "switch-shapes");   // tiered: interp fallback meanwhile
  EXPECT_STREQ(plan("shape", rewire(), {TierPolicy::Shape, 0, 0}), "regenerate");
  EXPECT_STREQ(plan("shape", rewire(), {TierPolicy::Interp, 8, 0}), "upload");
}

// Row 2, shape mode: no build when every material keeps its shape key.
TEST(EditPlan, RewireKeepingTheShapes) {
  EditFacts F = rewire();
  F.ShapeChanged = false;
  EXPECT_STREQ(plan("shape", F), "upload");
  EXPECT_STREQ(plan("shape", F, {TierPolicy::Shape, 0, 0}), "upload");
  // A layout without kernel.shapeHash: the JSON-level wiring change decides.
  F.ShapeChanged.reset();
  EXPECT_STREQ(plan("shape", F), "switch-shapes");
}

// Row 2, interp: unless the edit needs more than the kernel has.
TEST(EditPlan, InterpNeedsMoreThanTheKernel) {
  EXPECT_STREQ(plan("interp", needing(true, 6), {TierPolicy::Auto, 0, 8}), "upload"); // headroom
  EXPECT_STREQ(plan("interp", needing(true, 9), {TierPolicy::Auto, 0, 8}), "regenerate");
  EditFacts Spilling = needing(true, 6);
  Spilling.Spill = true;
  EXPECT_STREQ(plan("interp", Spilling, {TierPolicy::Auto, 0, 8}), "regenerate");
  EXPECT_STREQ(plan("interp", needing(false, 2, 4)), "regenerate");       // more outputs
  EXPECT_STREQ(plan("interp", needing(false, 2, 1, true)), "regenerate"); // an attribute case
  EXPECT_STREQ(plan("interp", needing(false, 2)), "regenerate"); // e.g. wires a hoisted parameter
}

// Row 2, shape: the interp fallback runs what its value stack, outputs and decoder hold.
TEST(EditPlan, ShapeFallbackHeadroom) {
  KernelCapabilities C = caps("shape");
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

// Wavefront and inline have neither headroom nor a fallback.
TEST(EditPlan, NoHeadroomElsewhere) {
  for (const char *M : {"inline", "wavefront"}) {
    EXPECT_STREQ(plan(M, needing(true, 6), {TierPolicy::Auto, 8, 8}), "regenerate") << M;
    EXPECT_STREQ(plan(M, needing(false, 2, 1, true), {TierPolicy::Auto, 8, 8}), "regenerate") << M;
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
      "kernel": {"source": "proctex.cl", "entry": "texcc_wf_outputs"}, "materials": []})");
  EXPECT_EQ(L.CompileOptions, (std::vector<std::string>{"--mode=wavefront", "-I/abs/inc", "-DK=2"}));
  EXPECT_TRUE(L.Caps.ReEncodes);
  EXPECT_FALSE(L.Caps.WiringIsData);
  EXPECT_EQ(L.Caps.MaxOutputs, 3u);
  // A layout from a texcc before compileOptions: a regeneration passes the mode.
  Layout Old = loadText(
      R"({"texcc": 1, "mode": "inline", "kernel": {"source": "proctex.cl"}, "materials": []})");
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
