/* blender/normal_map.cl: Blender's Normal Map node in Tangent Space (Cycles, Blender 5.0).
 *
 *   float3 blNormalMap(float3 color, float strength, float3 axisX, float3 axisY, float3 axisZ)
 *                        the perturbed normal (world space, unit) of the hit: the colour in the
 *                        frame of the mesh's UV tangent (Tangent, TangentSign) and the shading
 *                        normal (Normal), turned back on a back face (Backfacing)
 *   float3 blNormalMapFrame(float3 color, float strength, float3 normal, float3 tangent,
 *                           float tangentSign, float backfacing, float3 axisX, float3 axisY,
 *                           float3 axisZ)
 *                        the same with the frame as arguments (what the Cycles fixtures
 *                        compare: a bake's plane has one known frame)
 *
 * As Cycles' svm_node_normal_map: the colour (linear; a normal map image is Non-Color) maps to
 * c = 2 (color - 0.5); Strength scales its tangent-plane part, c.xy * strength, and moves
 * c.z from 1 towards itself, mix(1, c.z, clamp(strength, 0, 1)); the normal is
 * normalize(c.x T + c.y B + c.z N) with B = tangentSign * cross(N, T), formed in the object's
 * own space (axisX..Z: the object-to-world matrix's columns, which the exporter passes) and
 * turned into world space as a normal, as Cycles does: under a non-uniform scale the result
 * is not the world-space frame's. On a back face (the ray
 * hit the side the triangle's winding faces away from) Cycles builds the frame with the
 * normal of the winding's side and turns the result; texrender's Normal faces the ray, so N is
 * turned first and the result after. A zero result is the shading normal.
 *
 * The tangent is the mesh's MikkTSpace tangent when its OBJ file gives one (vtan; the Blender
 * exporter writes Blender's), interpolated across the triangle as Cycles interpolates it, and
 * like the sign divided by the interpolated normal's length, so that with the unit Normal the
 * frame is Cycles' own (neither normalized); without one, dP/du of the triangle's UVs and the
 * sign of their orientation (docs/abi.md "Attribute ids").
 *
 * Parameters (Blender's defaults):
 *
 *   | name        | type   | default        | meaning                                       |
 *   |-------------|--------|----------------|-----------------------------------------------|
 *   | color       | float3 | 0.5, 0.5, 1    | the tangent-space normal, 0..1 per axis        |
 *   | strength    | float  | 1              | 0: the shading normal; above 1 exaggerates     |
 *   | normal      | float3 | Normal         | unit shading normal, facing the ray            |
 *   | tangent     | float3 | Tangent        | UV tangent, in the unit normal's units         |
 *   | tangentSign | float  | TangentSign    | bitangent sign (times the same scale)          |
 *   | backfacing  | float  | Backfacing     | 1 on a back face, else 0                       |
 *   | axisX       | float3 | 1, 0, 0        | object-to-world matrix's first column (X axis) |
 *   | axisY       | float3 | 0, 1, 0        | its second column                              |
 *   | axisZ       | float3 | 0, 0, 1        | its third column                               |
 */

float3 blNormalMapFrame(float3 color, float strength, float3 normal, float3 tangent,
                        float tangentSign, float backfacing, float3 axisX, float3 axisY,
                        float3 axisZ) {
  float3 c = 2.0f * (color - (float3)(0.5f));
  c.x *= strength;
  c.y *= strength;
  c.z = mix(1.0f, c.z, clamp(strength, 0.0f, 1.0f));
  /* The object's inverse, row by row (r / det): its transpose turns object normals into
   * world ones. A singular matrix: the world frame as it is. */
  float3 r0 = cross(axisY, axisZ), r1 = cross(axisZ, axisX), r2 = cross(axisX, axisY);
  float det = dot(axisX, r0);
  if (!(fabs(det) > 1e-20f)) {
    axisX = r0 = (float3)(1.0f, 0.0f, 0.0f);
    axisY = r1 = (float3)(0.0f, 1.0f, 0.0f);
    axisZ = r2 = (float3)(0.0f, 0.0f, 1.0f);
    det = 1.0f;
  }
  /* Into object space: the normal by the matrix's transpose, the tangent by its inverse
   * with its length kept (as texrender kept it into world space, scene.md "Tangents"). */
  const float3 nw = backfacing > 0.5f ? -normal : normal;
  const float3 n = normalize((float3)(dot(axisX, nw), dot(axisY, nw), dot(axisZ, nw)));
  float3 t = (float3)(dot(r0, tangent), dot(r1, tangent), dot(r2, tangent));
  const float lt = length(t);
  if (lt > 0.0f)
    t *= length(tangent) / lt;
  const float3 b = tangentSign * cross(n, t);
  const float3 ro = c.x * t + c.y * b + c.z * n;
  /* Back to world space as a normal (the inverse's transpose). */
  float3 r = (ro.x * r0 + ro.y * r1 + ro.z * r2) / det;
  const float len = length(r);
  if (!(len > 0.0f))
    return normal;
  r /= len;
  return backfacing > 0.5f ? -r : r;
}

float3 blNormalMap(float3 color, float strength, float3 axisX, float3 axisY, float3 axisZ) {
  return blNormalMapFrame(color, strength, readAttr("Normal"), readAttr("Tangent"),
                          readAttr("TangentSign"), readAttr("Backfacing"), axisX, axisY, axisZ);
}
