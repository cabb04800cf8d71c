// Unsuffixed floating literals are single precision in texture code, without a warning.
// RUN: texcc-fe %s 2>&1 >/dev/null | FileCheck %s --allow-empty --check-prefix=DIAG --implicit-check-not=warning:
// RUN: texcc-fe %s | FileCheck %s
// DIAG-NOT: error:

// CHECK: {{^}}TEXCC_FN float float_literal_no_warning_halve(TEXCC_CTX_PARAM, float x) { return x * 0.5; }
float halve(float x) { return x * 0.5; }
