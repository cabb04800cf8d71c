// A constant `for` nested in a charged `for` (no other loop between them) is charged there, once,
// and carries no charge of its own: the outer loop is charged, per iteration of its own, 1 plus
// the nested loop's whole count. A perfect constant nest (voronoi's 3x3x3 search) is one charge
// of 3 * (1 + 3 * (1 + 3)) = 39, what its three separate charges added up to; a constant loop
// nested in a span-charged loop multiplies the span (texcc_loop_charge_nest). A loop inside a
// `while`, or inside a loop that ticks, keeps its own charge.
// RUN: texcc-fe %s | FileCheck %s

float f(int n, int k) {
  float s = 0.0f;
  // CHECK: {{^}}  for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 39u, __LINE__), dz = texcc_bad ? (1) : (-1); dz <= 1; ++dz) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  // CHECK-NEXT: {{^}}    for (int dy = -1; dy <= 1; ++dy)
  // CHECK-NEXT: {{^}}      for (int dx = -1; dx <= 1; ++dx)
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx)
        s += (float)(dx + dy + dz);
  // Two constant loops in one body, one under an `if` (charged whether it runs or not):
  // 4 * (1 + 2 + 5) = 32.
  // CHECK: {{^}}  for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 32u, __LINE__), i = texcc_bad ? (3) : (0); i < 4; ++i) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else {
  // CHECK-NEXT: {{^}}    for (int j = 0; j < 2; ++j)
  // CHECK: {{^}}    if (k > i)
  // CHECK-NEXT: {{^}}      for (int j = 5; j > 0; --j)
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 2; ++j)
      s += 1.0f;
    if (k > i)
      for (int j = 5; j > 0; --j)
        s += 2.0f;
  }
  // A constant loop in a span-charged loop: the span times 1 + 3.
  // CHECK: {{^}}  if (!texcc_loop_charge_nest(texcc_ctx, (long)(n) - (long)(0), 4u, __LINE__)) {} else for (int i = 0; i < n; ++i)
  // CHECK-NEXT: {{^}}    for (int j = 0; j < 3; ++j)
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < 3; ++j)
      s += 1.0f;
  // A span-charged loop in a constant one is charged at its own entry (its span is known
  // there), and so is the constant loop inside it (charged by it, 2 * (1 + 2) = 6 per entry).
  // CHECK: {{^}}  for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 3u, __LINE__), i = texcc_bad ? (2) : (0); i < 3; ++i) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  // CHECK-NEXT: {{^}}    if (!texcc_loop_charge_nest(texcc_ctx, (long)(n) - (long)(0), 3u, __LINE__)) {} else for (int j = 0; j < n; ++j)
  // CHECK-NEXT: {{^}}      for (int l = 0; l < 2; ++l)
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < n; ++j)
      for (int l = 0; l < 2; ++l)
        s += 1.0f;
  // Inside a `while` (which may run the loop any number of times per outer iteration): its own
  // charge.
  // CHECK: {{^}}  for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 2u, __LINE__), i = texcc_bad ? (1) : (0); i < 2; ++i) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  // CHECK-NEXT: {{^}}    while ((s < 100.0f) && texcc_loop_continues(texcc_ctx, __LINE__))
  // CHECK-NEXT: {{^}}      for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 3u, __LINE__), j = texcc_bad ? (2) : (0); j < 3; ++j) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  for (int i = 0; i < 2; ++i)
    while (s < 100.0f)
      for (int j = 0; j < 3; ++j)
        s += 1.0f;
  // Inside a loop that ticks (its body writes its counter): its own charge, and the ticking
  // loop's own nested loop is charged at that loop, not at the constant loop around it.
  // CHECK: {{^}}  for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 2u, __LINE__), i = texcc_bad ? (1) : (0); i < 2; ++i) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  // CHECK-NEXT: {{^}}    for (int j = 0; (j < 10) && texcc_loop_continues(texcc_ctx, __LINE__); ++j) {
  // CHECK-NEXT: {{^}}      for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 3u, __LINE__), l = texcc_bad ? (2) : (0); l < 3; ++l) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 10; ++j) {
      for (int l = 0; l < 3; ++l)
        s += 1.0f;
      j += k;
    }
  // A nest whose whole count would pass 2^32 - 1: each loop charges itself.
  // CHECK: {{^}}  for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 100000u, __LINE__), i = texcc_bad ? (99999) : (0); i < 100000; ++i) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  // CHECK-NEXT: {{^}}    for (int texcc_bad = texcc_loop_charge_once(texcc_ctx, 100000u, __LINE__), j = texcc_bad ? (99999) : (0); j < 100000; ++j) if (texcc_bad) texcc_loop_fault(texcc_ctx, texcc_bad); else
  for (int i = 0; i < 100000; ++i)
    for (int j = 0; j < 100000; ++j)
      s += 1.0f;
  return s;
}
