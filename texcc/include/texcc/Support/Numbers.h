#ifndef TEXCC_SUPPORT_NUMBERS_H
#define TEXCC_SUPPORT_NUMBERS_H

// Whether a number read as a double (JSON, --set, OBJ) fits the 32-bit type it is stored in.
// One definition for every reader: the range checks used to be written out at each place, and
// two were wrong (-2147483648 was "outside the 32-bit int range"; 3.4028235e38, FLT_MAX as
// printed with 8 digits, "did not fit in a float").

#include <cmath>

namespace texcc {

/// V rounds to a finite float: |V| is below 2^128 - 2^103, the midpoint between FLT_MAX and
/// 2^128 (round-to-nearest-even takes that midpoint to infinity). False for NaN and Inf.
inline bool fitsInFloat(double V) { return std::fabs(V) < 0x1.ffffffp127; }

/// V is an integer in [-2^31, 2^31 - 1].
inline bool fitsInInt32(double V) {
  return V == std::floor(V) && V >= -2147483648.0 && V <= 2147483647.0;
}

} // namespace texcc

#endif
