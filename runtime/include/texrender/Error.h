#ifndef TEXRENDER_ERROR_H
#define TEXRENDER_ERROR_H

// texrender reports every failure as an Error whose what() is one line: the reason first,
// naming the file (and JSON path) or the OpenCL call concerned. A failed kernel build adds
// the build log after that first line. What a message quotes is bounded (texcc::boundedMessage):
// a 200 MB name in a graph is not a 200 MB error line.

#include "texcc/Support/Text.h"

#include <stdexcept>
#include <string>

namespace texrender {

class Error : public std::runtime_error {
public:
  explicit Error(const std::string &Msg) : std::runtime_error(texcc::boundedMessage(Msg)) {}
};

/// A runtime fault of user texture code that the kernels reported: a loop past its budget, an
/// out-of-bounds array read (Renderer::checkTextureFaults), a non-finite texture value under
/// --check-nan. A batch render stops with it; a watch session reports it and goes back to the
/// last good kernel and graph (docs/live.md).
class TextureFault : public Error {
public:
  using Error::Error;
};

} // namespace texrender

#endif
