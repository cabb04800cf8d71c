/* footprint.cl: probes of bump's step and offset directions for testsuite/bump/
 * bump-footprint.test and bump-frame.test (footprint.py).
 *   aboutHit(k)   float   k |WorldPos - Q|^2, Q the unmoved hit recomputed from its UV (UV is
 *                         never moved) on footprint.py's plane: 0 at the hit, k e^2 at both
 *                         moved positions, e the bump step
 *   tiltTan(nb)   float3  tan of the angle between nb (the bumped normal) and the hit's
 *                         Normal, in every channel */
float aboutHit(float k) {
  float3 p = readAttr("WorldPos");
  float2 uv = readAttr("TexCoord0");
  float3 q = (float3)(4.0f * uv.x - 2.0f, 0.0f, 4.0f * uv.y - 2.0f);
  float3 d = p - q;
  return k * dot(d, d);
}

float3 tiltTan(float3 nb) {
  float3 n = readAttr("Normal");
  float c = dot(nb, n);
  float s = length(nb - c * n);
  return (float3)(s / c);
}

/*   alongX(k)     float   k ((WorldPos - Q).x)^2: 0 at the hit, k (e o.x)^2 at a position moved
 *                         by e o; its bump shows the offset directions' x components
 *   tiltXZ(nb)    float3  |x| and |z| of nb (a bump of footprint.py's plane, normal +y) over its
 *                         y component: the tangents of its tilt along x and along z */
float alongX(float k) {
  float3 p = readAttr("WorldPos");
  float2 uv = readAttr("TexCoord0");
  float d = p.x - (4.0f * uv.x - 2.0f);
  return k * d * d;
}

float3 tiltXZ(float3 nb) { return (float3)(fabs(nb.x) / nb.y, fabs(nb.z) / nb.y, 0.0f); }
