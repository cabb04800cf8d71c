/* brick.cl: running-bond brickwork in the (u, v) plane.
 *
 * Rows of bricks of size brickSize (in units of uv) are separated by mortar joints of width
 * mortar; every odd row is shifted by offset * brickSize.x. Row r covers
 * v in [r * h, (r + 1) * h) with h = brickSize.y. The pattern is periodic with period
 * (brickSize.x, 2 * brickSize.y) when offset is 0.5 (with period (brickSize.x, brickSize.y)
 * when offset is 0), and in general with period brickSize.x along u.
 *
 * Texture functions (graph "fn" names):
 *
 *   float  brickMask(float2 uv, float2 brickSize, float mortar, float offset)
 *       1 on a brick, 0 in the mortar (a joint of width `mortar` centred on every border).
 *   float  brickId(float2 uv, float2 brickSize, float offset)
 *       a random value in [0, 1) per brick, constant over the brick.
 *   float3 brickColor(float2 uv, float2 brickSize, float mortar, float offset,
 *                     float3 colorA, float3 colorB, float3 mortarColor)
 *       each brick a colour between colorA and colorB (by brickId), mortarColor in the joints.
 *
 * Parameters:
 *
 *   | name        | type   | default        | range            | meaning                       |
 *   |-------------|--------|----------------|------------------|-------------------------------|
 *   | uv          | float2 | -              | any              | usually {"attr": "TexCoord0"} |
 *   | brickSize   | float2 | (0.25, 0.0833) | > 0              | brick plus one joint, in uv   |
 *   | mortar      | float  | 0.01           | 0..min(brickSize) | joint width, in uv           |
 *   | offset      | float  | 0.5            | 0..1             | odd-row shift, fraction of a brick |
 *   | colorA, colorB | float3 | (0.55, 0.2, 0.12), (0.7, 0.33, 0.2) | 0..1 | brick colour range |
 *   | mortarColor | float3 | (0.75, 0.73, 0.68) | 0..1         | joint colour                  |
 */

uint hashU32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

/* Row index in .y, column (after the row's shift) in .x, both integral; the position inside
 * the brick in units of the brick size in .z, .w (each in [0, 1)). */
float4 brickCell(float2 uv, float2 brickSize, float offset) {
  float v = uv.y / brickSize.y;
  float row = floor(v);
  float rowParity = row - 2.0f * floor(row * 0.5f);
  float u = uv.x / brickSize.x - rowParity * offset;
  float col = floor(u);
  return (float4)(col, row, u - col, v - row);
}

float brickMask(float2 uv, float2 brickSize, float mortar, float offset) {
  float4 c = brickCell(uv, brickSize, offset);
  float hu = 0.5f * mortar / brickSize.x, hv = 0.5f * mortar / brickSize.y;
  int inMortar = c.z < hu || c.z >= 1.0f - hu || c.w < hv || c.w >= 1.0f - hv;
  return inMortar ? 0.0f : 1.0f;
}

float brickId(float2 uv, float2 brickSize, float offset) {
  float4 c = brickCell(uv, brickSize, offset);
  uint h = hashU32((uint)(int)c.x + hashU32((uint)(int)c.y));
  return (float)(h >> 8) * (1.0f / 16777216.0f);
}

float3 brickColor(float2 uv, float2 brickSize, float mortar, float offset, float3 colorA,
                  float3 colorB, float3 mortarColor) {
  if (brickMask(uv, brickSize, mortar, offset) < 0.5f)
    return mortarColor;
  float w = brickId(uv, brickSize, offset);
  return (float3)(colorA.x + (colorB.x - colorA.x) * w, colorA.y + (colorB.y - colorA.y) * w,
                  colorA.z + (colorB.z - colorA.z) * w);
}
