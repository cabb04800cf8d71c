#ifndef TEXRENDER_ERROR_H
#define TEXRENDER_ERROR_H

// texrender reports every failure as an Error whose what() is one line: the reason first,
// naming the file (and JSON path) or the OpenCL call concerned. A failed kernel build adds
// the build log after that first line.

#include <stdexcept>
#include <string>

namespace texrender {

class Error : public std::runtime_error {
public:
  explicit Error(const std::string &Msg) : std::runtime_error(Msg) {}
};

} // namespace texrender

#endif
