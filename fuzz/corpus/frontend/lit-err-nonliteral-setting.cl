// readSetting's argument must be a string literal.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

__constant char kName[] = "Time";
float f(void) {
  // CHECK: err-nonliteral-setting.cl:[[@LINE+1]]:22: error: argument to 'readSetting' must be a string literal
  return readSetting(kName);
}
