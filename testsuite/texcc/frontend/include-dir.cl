// -I adds an include directory for parsing.
// RUN: texcc-fe %s -I %inputs/frontend/include | FileCheck %s

#include "gain.h"
// CHECK: {{^}}TEXCC_FN float include_dir_f(TEXCC_CTX_PARAM) { return GAIN_FROM_HEADER; }
float f(void) { return GAIN_FROM_HEADER; }
