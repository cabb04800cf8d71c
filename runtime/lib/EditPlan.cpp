#include "texrender/EditPlan.h"

namespace texrender {

EditAction planEdit(const EditFacts &F, const KernelCapabilities &Caps, const TierState &S) {
  if (!Caps.ReEncodes)
    return EditAction::Regenerate; // the values are literals of the kernel
  // An interp fallback has a case for every node's function, so a compiled edit needs no new
  // one (unless a node of a function outside the graph became live, F.NeedsFunction); what it
  // may need is more value-stack slots than it was built with, more outputs than
  // any kernel of this layout has, or an attribute case its decoder lacks.
  const bool FallbackRuns = Caps.InterpFallback && S.Tier != TierPolicy::Shape && !F.Spill &&
                            F.StackSlots <= S.FallbackSlots && F.MaxOutputs <= Caps.MaxOutputs &&
                            !F.NeedsAttributeCase && !F.NeedsFunction;
  // A kernel built with value-stack headroom also holds a deeper stack.
  const bool HeadroomRuns = Caps.StackHeadroom && F.NeedsOnlyStackSlots && !F.Spill &&
                            F.StackSlots <= S.KernelStackSlots;
  if (F.NeedsRebuild && !FallbackRuns && !HeadroomRuns)
    return EditAction::Regenerate;
  // A shape-keyed kernel runs the edited graph exactly when its shapes are unchanged: a value
  // edit that merges or splits identical nodes changes them, a rewiring onto an equal
  // structure does not.
  const bool Structural = Caps.ShapeKeyed && F.ShapeChanged ? *F.ShapeChanged : F.Structural;
  if ((!Structural && !F.NeedsRebuild) || Caps.WiringIsData)
    return EditAction::Upload;
  if (Caps.InterpFallback && S.Tier == TierPolicy::Interp)
    return EditAction::Upload;
  // The fallback may still be building (neither kernel was cached): then the edit regenerates
  // in the foreground, as with --tier=shape.
  if (Caps.InterpFallback && S.Tier == TierPolicy::Auto)
    return S.FallbackSlots ? EditAction::SwitchShapes : EditAction::Regenerate;
  return EditAction::Regenerate;
}

const char *editActionName(EditAction A) {
  switch (A) {
  case EditAction::Upload:
    return "upload";
  case EditAction::Regenerate:
    return "regenerate";
  case EditAction::SwitchShapes:
    return "switch-shapes";
  }
  return "?";
}

} // namespace texrender
