// readAttr's argument must be a string literal.
// RUN: not texcc-fe %s 2>&1 | FileCheck %s

float f(__constant char *name) {
  // CHECK: err-nonliteral-attr.cl:[[@LINE+1]]:19: error: argument to 'readAttr' must be a string literal
  return readAttr(name);
}
