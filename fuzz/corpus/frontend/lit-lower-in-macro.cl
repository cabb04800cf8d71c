// readAttr inside a user macro's body is lowered in the body.
// RUN: texcc-fe %s | FileCheck %s

// CHECK: {{^}}#define NORMAL_Y (texcc_attr_Normal(texcc_ctx).y)
#define NORMAL_Y (readAttr("Normal").y)
float f(void) { return NORMAL_Y * NORMAL_Y; }
