// A user function called but defined in no part of this file is an error: files are renamed
// separately, so a call cannot reach another file's function.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float elsewhere(float x);
float f(float x) {
  // CHECK: err-undefined-callee.cl:[[@LINE+1]]:10: error: function 'elsewhere' is called but not defined in '{{.*}}err-undefined-callee.cl'
  return elsewhere(x);
}
