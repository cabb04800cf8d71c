/* voronoi.cl: Worley (cellular) noise in 3D.
 *
 * Space (p * scale) is cut into unit cells; cell c holds one feature point at
 * c + 0.5 + jitter * (h(c) - 0.5), where h(c) is a hashed point of [0, 1)^3. The functions
 * below report, for the lookup point, the distances to the nearest (F1) and second-nearest
 * (F2) feature points, measured in scaled units (multiply by 1/scale for units of p), over the
 * 3x3x3 neighbourhood of p's cell (exact for F1; for F2 exact up to jitter 1 in all but rare
 * configurations, as in Blender and Worley's original).
 * Bounds: the own cell's feature point is at most sqrt(3) away, and a face neighbour's at most
 * sqrt(6), so F1 <= sqrt(3) and F2 <= sqrt(6); typical values are below 1.
 *
 * Texture functions (graph "fn" names):
 *
 *   float voronoiF1(float3 p, float scale, float jitter)       F1, range [0, sqrt(3)]
 *   float voronoiF2(float3 p, float scale, float jitter)       F2 >= F1, range [0, sqrt(6)]
 *   float voronoiEdge(float3 p, float scale, float jitter)     F2 - F1: 0 on the cell borders
 *                                                              (the Voronoi edges), range [0, sqrt(6)]
 *   float voronoiCellId(float3 p, float scale, float jitter)   a random value in [0, 1) per
 *                                                              cell of the nearest feature point,
 *                                                              constant over that Voronoi cell
 *   float3 voronoiCellColor(float3 p, float scale, float jitter)  a random colour in [0, 1)^3
 *                                                              per Voronoi cell
 *
 * Parameters:
 *
 *   | name   | type   | default | range | meaning                                           |
 *   |--------|--------|---------|-------|---------------------------------------------------|
 *   | p      | float3 | -       | any   | lookup point, usually {"attr": "ObjectPos"}       |
 *   | scale  | float  | 4.0     | > 0   | cells per unit of p                               |
 *   | jitter | float  | 1.0     | 0..1  | feature point randomness: 0 puts every feature point at its cell centre (a cubic grid), 1 anywhere in the cell; clamped to [0, 1] |
 */

uint hashU32(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

uint hashCell(int x, int y, int z) {
  return hashU32((uint)x + hashU32((uint)y + hashU32((uint)z)));
}

/* A value in [0, 1) from the top 24 bits of h. */
float unitFloat(uint h) { return (float)(h >> 8) * (1.0f / 16777216.0f); }

/* The result of one search: F1, F2 and the hash of the nearest feature point's cell. */
typedef struct VoronoiResult {
  float f1;
  float f2;
  uint cell;
} VoronoiResult;

VoronoiResult voronoiSearch(float3 p, float scale, float jitter) {
  float j = jitter < 0.0f ? 0.0f : (jitter > 1.0f ? 1.0f : jitter);
  float x = p.x * scale, y = p.y * scale, z = p.z * scale;
  float fx = floor(x), fy = floor(y), fz = floor(z);
  int ix = (int)fx, iy = (int)fy, iz = (int)fz;
  VoronoiResult r;
  r.f1 = 1e30f;
  r.f2 = 1e30f;
  r.cell = 0U;
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 1; ++dx) {
        uint h = hashCell(ix + dx, iy + dy, iz + dz);
        float px = fx + (float)dx + 0.5f + j * (unitFloat(h) - 0.5f);
        float py = fy + (float)dy + 0.5f + j * (unitFloat(hashU32(h ^ 0x68e31da4U)) - 0.5f);
        float pz = fz + (float)dz + 0.5f + j * (unitFloat(hashU32(h ^ 0xb5297a4dU)) - 0.5f);
        float ex = px - x, ey = py - y, ez = pz - z;
        float d = sqrt(ex * ex + ey * ey + ez * ez);
        if (d < r.f1) {
          r.f2 = r.f1;
          r.f1 = d;
          r.cell = h;
        } else if (d < r.f2) {
          r.f2 = d;
        }
      }
  return r;
}

float voronoiF1(float3 p, float scale, float jitter) {
  return voronoiSearch(p, scale, jitter).f1;
}

float voronoiF2(float3 p, float scale, float jitter) {
  return voronoiSearch(p, scale, jitter).f2;
}

float voronoiEdge(float3 p, float scale, float jitter) {
  VoronoiResult r = voronoiSearch(p, scale, jitter);
  return r.f2 - r.f1;
}

float voronoiCellId(float3 p, float scale, float jitter) {
  return unitFloat(hashU32(voronoiSearch(p, scale, jitter).cell ^ 0x1b873593U));
}

float3 voronoiCellColor(float3 p, float scale, float jitter) {
  uint h = voronoiSearch(p, scale, jitter).cell;
  return (float3)(unitFloat(hashU32(h ^ 0x1b873593U)), unitFloat(hashU32(h ^ 0xcc9e2d51U)),
                  unitFloat(hashU32(h ^ 0x85ebca6bU)));
}
