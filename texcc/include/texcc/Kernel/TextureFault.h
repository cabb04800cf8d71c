#ifndef TEXCC_KERNEL_TEXTUREFAULT_H
#define TEXCC_KERNEL_TEXTUREFAULT_H

// The texture kernels' fault record (docs/abi.md "Faults", docs/reliability.md "User code") in
// words: the first safety check of user code that tripped (a loop past its budget, a __global
// array read out of bounds). texrender and texcc-eval both print it, each followed by where it
// happened in its own terms (a pixel, a grid point). No LLVM.

#include "texcc/Kernel/Manifest.h"

#include <cstdint>
#include <string>
#include <string_view>

namespace texcc {

/// "texture node 'ID' (FILE:LINE): WHAT" for the fault record Words (TEXCC_FAULT_WORDS words,
/// texcc_abi.h; its kind is not TEXCC_FAULT_NONE). The node and its function's file (the name
/// only) come from the output folder's manifest (layout.json) and args.bin (ArgsBin, for an
/// instruction index of a material's program); "?" where they do not say.
std::string describeTextureFault(const int32_t *Words, const kernel::Manifest &M,
                                 std::string_view ArgsBin);

} // namespace texcc

#endif
