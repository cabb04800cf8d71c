/* scratches.cl: fine scratches on a polished surface (the scratches example's own nodes; the
 * Voronoi pattern and the noise come from the texture library, ../../textures/).
 *
 * A Voronoi pattern whose cells are stretched very long in one direction has edges that run
 * almost parallel to that direction: thin straight lines. scratchSpace turns and stretches the
 * lookup point so that voronoiEdge draws such lines; scratchMask turns the edge distance into
 * a thin line and lets a noise break the lines into scratches of random length.
 *
 * Texture functions (graph "fn" names):
 *
 *   float3 scratchSpace(float3 p, float angle, float stretch)
 *       p turned by `angle` radians about the y axis, then scaled by 1/stretch along the
 *       turned x axis (cells become `stretch` times longer along the scratches).
 *   float scratchMask(float edge, float noise, float width, float density)
 *       1 - smoothstep(0, width, edge) (a line of half width `width` on the Voronoi edges),
 *       kept where noise (in [-1, 1]) exceeds 1 - 2 * density: 0 clean, 1 scratch.
 *
 * Parameters:
 *
 *   | name    | type   | default | range | meaning                                          |
 *   |---------|--------|---------|-------|--------------------------------------------------|
 *   | p       | float3 | -       | any   | {"attr": "ObjectPos"}                            |
 *   | angle   | float  | 0.5     | any   | scratch direction, radians about y               |
 *   | stretch | float  | 12      | >= 1  | cell elongation: longer, straighter scratches    |
 *   | edge    | float  | -       | >= 0  | voronoiEdge of scratchSpace                      |
 *   | noise   | float  | -       | -1..1 | perlin3: where the scratches are                 |
 *   | width   | float  | 0.02    | > 0   | line half width, in scaled Voronoi units         |
 *   | density | float  | 0.5     | 0..1  | share of the lines kept (0 none, 1 all)          |
 */

float3 scratchSpace(float3 p, float angle, float stretch) {
  float c = cos(angle), s = sin(angle);
  float u = c * p.x + s * p.z;
  float w = -s * p.x + c * p.z;
  return (float3)(u / fmax(stretch, 1.0f), p.y, w);
}

float scratchMask(float edge, float noise, float width, float density) {
  float line = 1.0f - smoothstep(0.0f, fmax(width, 1e-5f), edge);
  float keep = smoothstep(0.95f - 2.0f * density, 1.05f - 2.0f * density, noise);
  return line * keep;
}
