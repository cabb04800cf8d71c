#ifndef TEXCC_CODEGEN_QUICKENING_H
#define TEXCC_CODEGEN_QUICKENING_H

// The interp backend's choice of quickened opcodes (docs/modes.md): which (function, argument
// sources) patterns get a case of their own. Interp-only policy, so it lives with the interp
// backend; the graph library only encodes with a given table (graph::applyQuickened), which is
// all a live edit needs (it takes the kernel's table from layout.json).

#include "texcc/Graph/Compile.h"

#include <vector>

namespace texcc::codegen {

/// At most Max patterns of the programs' instructions (graph::instructionPattern), the most
/// frequent first (ties in order of first occurrence), numbered after the function ids
/// (CG.FunctionsById.size(), then on). Empty for Max 0.
std::vector<graph::QuickenedOp> chooseQuickened(const graph::CompiledGraph &CG, unsigned Max);

} // namespace texcc::codegen

#endif
