/* checker.cl: checkerboards in 2D and 3D.
 *
 * The cells are the unit cells of p * scale; a cell's parity is that of
 * floor(x) + floor(y) (+ floor(z)). The pattern is periodic with period 2 / scale along each
 * axis and flips between neighbouring cells. Points exactly on a border belong to the cell
 * above it (floor).
 *
 * Texture functions (graph "fn" names):
 *
 *   float  checkerMask2(float2 uv, float scale)      1 in even cells, 0 in odd cells
 *   float  checkerMask3(float3 p, float scale)       the same in 3D (a solid checkerboard)
 *   float3 checker3(float3 p, float scale, float3 colorA, float3 colorB)
 *                                                    colorA in even cells, colorB in odd cells
 *
 * Parameters:
 *
 *   | name   | type   | default | range | meaning                                      |
 *   |--------|--------|---------|-------|----------------------------------------------|
 *   | uv, p  | float2 / float3 | - | any | lookup point ({"attr": "TexCoord0"} / {"attr": "ObjectPos"}) |
 *   | scale  | float  | 4.0     | > 0   | cells per unit                               |
 *   | colorA | float3 | (0.8, 0.8, 0.8) | 0..1 | even cells                           |
 *   | colorB | float3 | (0.2, 0.2, 0.2) | 0..1 | odd cells                            |
 */

float parityMask(float s) {
  float h = s * 0.5f;
  /* s is an integer sum; its parity is whether s/2 has a fractional part. */
  return (h - floor(h)) < 0.25f ? 1.0f : 0.0f;
}

float checkerMask2(float2 uv, float scale) {
  return parityMask(floor(uv.x * scale) + floor(uv.y * scale));
}

float checkerMask3(float3 p, float scale) {
  return parityMask(floor(p.x * scale) + floor(p.y * scale) + floor(p.z * scale));
}

float3 checker3(float3 p, float scale, float3 colorA, float3 colorB) {
  return checkerMask3(p, scale) > 0.5f ? colorA : colorB;
}
