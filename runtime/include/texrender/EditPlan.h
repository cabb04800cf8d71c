#ifndef TEXRENDER_EDITPLAN_H
#define TEXRENDER_EDITPLAN_H

// What a live edit costs, as a pure function of what the graph library says about the edited
// graph, what the kernel in use can absorb (Layout::Caps, from layout.json) and the renderer's
// tier state: no device, no mode names (docs/modes.md, "What an edit costs").

#include "texrender/Layout.h"
#include "texrender/TextureTiers.h"

#include <optional>

namespace texrender {

/// The edited graph, as the graph library's GraphEditor sees it after the edit.
struct EditFacts {
  /// The edit changes the wiring (a rewiring, a constant over a node or attribute input, a set
  /// to {"attr": ...} or {"node": ...}).
  bool Structural = false;
  /// Shape-keyed kernels: whether graph::shapeHash of the edited graph differs from the kernel's
  /// (std::nullopt: a layout without kernel.shapeHash; Structural decides).
  std::optional<bool> ShapeChanged;
  /// GraphEditor::needsRebuild(): the kernel this layout was made for cannot run the graph.
  bool NeedsRebuild = false;
  /// GraphEditor::needsOnlyStackSlots(): only a deeper value stack is missing.
  bool NeedsOnlyStackSlots = false;
  /// GraphEditor::needsAttributeCase(): an argument reads an attribute the decoder has no case for.
  bool NeedsAttributeCase = false;
  /// GraphEditor::needsFunction(): a live node's function has no case in any kernel of the
  /// layout (docs/modes.md's third row; set and rewire reach only the graph's nodes, whose
  /// functions the interpreter has).
  bool NeedsFunction = false;
  /// The edited graph's value stack spills, its depth and its outputs per material.
  bool Spill = false;
  unsigned StackSlots = 0;
  unsigned MaxOutputs = 1;
};

/// The renderer's side: the tier policy and the value stacks of the programs it has built.
struct TierState {
  TierPolicy Tier = TierPolicy::Shape;
  /// The interp fallback's value-stack slots; 0 while it is not built.
  unsigned FallbackSlots = 0;
  /// The stack slots the kernel was built with (headroom included).
  unsigned KernelStackSlots = 0;
};

enum class EditAction {
  Upload,       ///< re-encode args.bin with the graph library, upload; no build
  Regenerate,   ///< run texcc again (compileOptions replayed), build, render
  SwitchShapes, ///< upload for the interp fallback now; texcc and the new kernel in the background
};

EditAction planEdit(const EditFacts &F, const KernelCapabilities &Caps, const TierState &S);

/// "upload" | "regenerate" | "switch-shapes" (tests, logs).
const char *editActionName(EditAction A);

} // namespace texrender

#endif
