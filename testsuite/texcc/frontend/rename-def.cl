// A function definition is renamed with the file's prefix (its stem, then '_').
// RUN: texcc-fe %s | FileCheck %s

// CHECK: {{^}}TEXCC_FN float rename_def_shade(TEXCC_CTX_PARAM, float x) {
float shade(float x) {
  return x * 0.5f;
}
