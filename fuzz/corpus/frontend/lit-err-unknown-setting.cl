// An unknown setting name is an error at the argument, listing the allowed names.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float f(void) {
  // CHECK: err-unknown-setting.cl:[[@LINE+1]]:25: error: unknown setting 'time'; expected one of CameraPos, Frame, Time
  float t = readSetting("time");
  return t;
}
