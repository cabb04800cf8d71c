/* dots.cl: solid polka dots, the custom-node tutorial's new texture (see README.md).
 *
 * Space is cut into cubes of size 1/scale; each cube holds a ball of radius `radius` (in
 * cube units) at its centre. A surface that cuts through the balls shows round dots; the dot
 * edge is antialiased over `blur` cube units.
 *
 * Texture function (graph "fn" name):
 *
 *   float3 polkaDots(float3 p, float scale, float radius, float blur, float3 dotColor, float3 baseColor)
 *
 * Parameters:
 *
 *   | name      | type   | default           | range    | meaning                               |
 *   |-----------|--------|-------------------|----------|---------------------------------------|
 *   | p         | float3 | -                 | any      | {"attr": "ObjectPos"}                 |
 *   | scale     | float  | 5.0               | > 0      | cubes per unit of p                   |
 *   | radius    | float  | 0.3               | 0..0.87  | ball radius, in cube units            |
 *   | blur      | float  | 0.02              | >= 0     | edge softness, in cube units          |
 *   | dotColor  | float3 | (0.8, 0.1, 0.1)   | 0..1     | inside the dots                       |
 *   | baseColor | float3 | (0.9, 0.9, 0.85)  | 0..1     | between the dots                      |
 */

/* Distance from x to the centre of its unit cell, along one axis. */
float cellOffset(float x) { return x - floor(x) - 0.5f; }

float3 polkaDots(float3 p, float scale, float radius, float blur, float3 dotColor,
                 float3 baseColor) {
  float dx = cellOffset(p.x * scale);
  float dy = cellOffset(p.y * scale);
  float dz = cellOffset(p.z * scale);
  float d = sqrt(dx * dx + dy * dy + dz * dz);
  float inside = 1.0f - smoothstep(radius - blur, radius + blur, d);
  return baseColor + (dotColor - baseColor) * inside;
}
