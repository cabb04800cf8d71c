/* wood.cl: growth rings of a log (the wood example's own node; the noise and the colour ramp
 * come from the texture library, ../../textures/).
 *
 * A log grows in rings around its axis. The ring position is the distance of p from the axis
 * line, times the ring density, pushed out and in by a noise so that the rings wobble; inside
 * each ring the light early wood turns into the dark late wood, which ends sharply where the
 * next year's early wood begins.
 *
 * Texture function (graph "fn" name):
 *
 *   float woodRings(float3 p, float3 center, float3 axis, float ringsPerUnit, float noise, float distortion)
 *       t = |p - center projected off the axis| * ringsPerUnit + distortion * noise;
 *       f = fract(t); returns smoothstep(0, 0.75, f) * (1 - smoothstep(0.9, 1, f)):
 *       0 at the start of a ring (early wood), 1 in the late wood, range [0, 1].
 *
 * Parameters:
 *
 *   | name         | type   | default       | range | meaning                                 |
 *   |--------------|--------|---------------|-------|-----------------------------------------|
 *   | p            | float3 | -             | any   | {"attr": "ObjectPos"}                   |
 *   | center       | float3 | (-0.4, 0, -3) | any   | a point on the log's axis               |
 *   | axis         | float3 | (0.15, 0.1, 1) | != 0 | the log's direction (need not be unit)  |
 *   | ringsPerUnit | float  | 9             | > 0   | ring density                            |
 *   | noise        | float  | -             | -1..1 | an fbm3 node: how the rings wobble      |
 *   | distortion   | float  | 1.2           | >= 0  | wobble amplitude, in rings              |
 */

float woodRings(float3 p, float3 center, float3 axis, float ringsPerUnit, float noise,
                float distortion) {
  float len = sqrt(axis.x * axis.x + axis.y * axis.y + axis.z * axis.z);
  float ax = axis.x / len, ay = axis.y / len, az = axis.z / len;
  float dx = p.x - center.x, dy = p.y - center.y, dz = p.z - center.z;
  float along = dx * ax + dy * ay + dz * az;
  float rx = dx - along * ax, ry = dy - along * ay, rz = dz - along * az;
  float t = sqrt(rx * rx + ry * ry + rz * rz) * ringsPerUnit + distortion * noise;
  float f = t - floor(t);
  return smoothstep(0.0f, 0.75f, f) * (1.0f - smoothstep(0.9f, 1.0f, f));
}
