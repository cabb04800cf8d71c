/* blender/voronoi.cl: Blender's Voronoi Texture node (Cycles, Blender 5.0), 1D to 4D, value for
 * value.
 *
 * Worley noise: one feature point per integer cell of Vector * Scale, jittered by the cell's
 * PCG hash times Randomness. F1 is the distance to the closest point, F2 to the second
 * closest, Smooth F1 a smooth minimum over the 5^n neighbourhood, Distance to Edge the distance
 * to the closest cell border, N-Sphere Radius half the distance from the closest point to its
 * closest neighbour. Detail > 0 sums octaves as the Noise node's fBM does (fractional Detail
 * blends the last one in). Color is the hash of the chosen cell; Position its feature point in
 * the units of Vector.
 *
 * One texture function per (dimensions, output); features and metrics are parameters:
 *
 *   float  blVoronoi2DDistance(float3 vector, float scale, float detail, float roughness,
 *                              float lacunarity, float smoothness, float exponent,
 *                              float randomness, int feature, int metric, int normalize)
 *   float3 blVoronoi2DColor   (same parameters)             F1, F2, Smooth F1
 *   float3 blVoronoi2DPosition(same parameters)             F1, F2, Smooth F1 (z = 0)
 *   float  blVoronoi2DRadius  (same parameters)             N-Sphere Radius
 *   blVoronoi3DDistance, blVoronoi3DColor, blVoronoi3DPosition, blVoronoi3DRadius: the same in 3D
 *   blVoronoi4DDistance, blVoronoi4DColor, blVoronoi4DPosition, blVoronoi4DW, blVoronoi4DRadius
 *                              (float3 vector, float w, then as above): 4D, W its fourth
 *                              coordinate and output
 *   float  blVoronoi1DDistance(float w, float scale, float detail, float roughness,
 *                              float lacunarity, float smoothness, float randomness,
 *                              int feature, int normalize)
 *   float3 blVoronoi1DColor, float blVoronoi1DW, float blVoronoi1DRadius (same parameters):
 *                              1D over W (Blender's W output is the feature point); a line has
 *                              one metric, so 1D takes no metric or exponent
 *
 * An output the feature does not produce is 0, as in Blender (Distance of N-Sphere Radius, ...).
 *
 * Parameters (the node's sockets and properties; defaults are Blender's):
 *
 *   | name       | type   | default | meaning                                                 |
 *   |------------|--------|---------|---------------------------------------------------------|
 *   | vector     | float3 | -       | lookup point (2D uses x, y; 1D has none)                |
 *   | w          | float  | 0.0     | fourth coordinate (4D), the lookup point (1D)           |
 *   | scale      | float  | 5.0     | cells per unit of vector                                |
 *   | detail     | float  | 0.0     | octaves beyond the first, clamped to [0, 15]            |
 *   | roughness  | float  | 0.5     | amplitude factor per octave, clamped to [0, 1]          |
 *   | lacunarity | float  | 2.0     | frequency factor per octave                             |
 *   | smoothness | float  | 1.0     | Smooth F1 only, clamped to [0, 1]                       |
 *   | exponent   | float  | 0.5     | Minkowski metric only                                   |
 *   | randomness | float  | 1.0     | jitter of the feature points, clamped to [0, 1]         |
 *   | feature    | int    | 0       | 0 F1, 1 F2, 2 Smooth F1, 3 Distance to Edge, 4 N-Sphere Radius |
 *   | metric     | int    | 0       | 0 Euclidean, 1 Manhattan, 2 Chebychev, 3 Minkowski      |
 *   | normalize  | int    | 0       | 1 divides Distance (and Color) by their largest value   |
 */

#include "hash.h"

float blDot(float4 a, float4 b, int dims) {
  if (dims == 1)
    return a.x * b.x;
  if (dims == 2)
    return a.x * b.x + a.y * b.y;
  if (dims == 3)
    return a.x * b.x + a.y * b.y + a.z * b.z;
  return a.x * b.x + a.y * b.y + a.z * b.z + a.w * b.w;
}

float blEuclid(float4 d, int dims) { return sqrt(blDot(d, d, dims)); }

/* The cell's feature-point offset in [0, 1]^dims and its colour: PCG hashes of the integer cell
 * (Cycles' hash_int2_to_float2 / hash_int3_to_float3, colour hash_int2_to_float3 /
 * hash_int3_to_float3). c holds the cell's integer coordinates as floats. */
float4 blVoronoiCellOffset(float4 c, int dims) {
  if (dims == 1) /* 1D hashes the cell's float, not its integer (hash_float_to_float) */
    return (float4)(blHashFloat1(c.x), 0.0f, 0.0f, 0.0f);
  if (dims == 2)
    return blHashInt2((int)c.x, (int)c.y);
  if (dims == 4)
    return blHashInt4((int)c.x, (int)c.y, (int)c.z, (int)c.w);
  return blHashInt3((int)c.x, (int)c.y, (int)c.z);
}

float3 blVoronoiCellColor(float4 c, int dims) {
  if (dims == 1)
    return (float3)(blHashFloat1(c.x), blHashFloat2(c.x, 1.0f), blHashFloat2(c.x, 2.0f));
  if (dims == 4)
    return blHashInt4((int)c.x, (int)c.y, (int)c.z, (int)c.w).xyz;
  return blHashInt3((int)c.x, (int)c.y, dims == 2 ? 0 : (int)c.z).xyz;
}

/* The metric over the first dims components. */
float blVoronoiMetric(float4 a, float4 b, int dims, int metric, float exponent) {
  float dx = fabs(a.x - b.x), dy = fabs(a.y - b.y), dz = fabs(a.z - b.z), dw = fabs(a.w - b.w);
  if (dims == 1) /* every metric is the absolute difference on a line */
    return dx;
  if (metric == 1)
    return dims == 2 ? dx + dy : (dims == 3 ? dx + dy + dz : dx + dy + dz + dw);
  if (metric == 2)
    return dims == 2 ? fmax(dx, dy)
                     : (dims == 3 ? fmax(fmax(dx, dy), dz) : fmax(fmax(fmax(dx, dy), dz), dw));
  if (metric == 3) {
    float s = pow(dx, exponent) + pow(dy, exponent);
    if (dims >= 3)
      s += pow(dz, exponent);
    if (dims == 4)
      s += pow(dw, exponent);
    return pow(s, 1.0f / exponent);
  }
  return sqrt(blDot(a - b, a - b, dims));
}

float blSmoothstep01(float x) {
  if (x < 0.0f)
    return 0.0f;
  if (x >= 1.0f)
    return 1.0f;
  return (3.0f - 2.0f * x) * (x * x);
}

/* The metric (0 Euclidean, 1 Manhattan, 2 Chebychev) of the differences (x, y, z, w) in four
 * lanes at once, over the first dims (2..4) components: blVoronoiMetric's arithmetic, per lane. */
float4 blVoronoiMetric4(float4 x, float4 y, float4 z, float4 w, int dims, int metric) {
  if (metric == 1) {
    float4 s = fabs(x) + fabs(y);
    if (dims >= 3)
      s += fabs(z);
    return dims == 4 ? s + fabs(w) : s;
  }
  if (metric == 2) {
    float4 s = fmax(fabs(x), fabs(y));
    if (dims >= 3)
      s = fmax(s, fabs(z));
    return dims == 4 ? fmax(s, fabs(w)) : s;
  }
  float4 s = x * x + y * y;
  if (dims >= 3)
    s += z * z;
  return sqrt(dims == 4 ? s + w * w : s);
}

/* The two smallest distances so far (d1 <= d2), their cells' offsets, and whether the scalar
 * loop's p1 and p2 would hold a point yet (it starts them at 0 and copies p1 into p2). */
typedef struct BlVoronoiBest {
  float d1, d2;
  float4 o1, o2;
  int v1, v2;
} BlVoronoiBest;

/* One candidate of F1 / F2 in the scalar loop's order (d < d1: it becomes the first and the
 * first the second; else d < d2: it becomes the second), as selects on values: with pointers
 * to the running values PoCL's build kept them in memory and branched on every candidate. */
BlVoronoiBest blVoronoiKeep(BlVoronoiBest b, float d, float4 off) {
  int lt1 = d < b.d1, lt2 = d < b.d2;
  BlVoronoiBest r;
  r.d2 = lt1 ? b.d1 : (lt2 ? d : b.d2);
  r.o2 = lt1 ? b.o1 : (lt2 ? off : b.o2);
  r.v2 = lt1 ? b.v1 : (lt2 ? 1 : b.v2);
  r.d1 = lt1 ? d : b.d1;
  r.o1 = lt1 ? off : b.o1;
  r.v1 = lt1 ? 1 : b.v1;
  return r;
}

/* F1 (feature 0) or F2 (1) of one octave in 2D-4D with metric 0-2, as blVoronoiOctave's loop
 * computes it, a row of three cells (i = -1, 0, 1; a fourth lane is computed and unused) at a
 * time: the row's PCG hashes, points and distances on vector types, then the three candidates
 * in the loop's order. The chosen cells' points are computed again after the loop, with the
 * same arithmetic, so every value is the scalar loop's. */
float blVoronoiOctaveRows(float4 cell, float4 rel, int dims, int feature, int metric,
                          float randomness, float3 *color, float4 *pos) {
  int kreach = dims <= 2 ? 0 : 1, ureach = dims == 4 ? 1 : 0;
  float4 lane = (float4)(-1.0f, 0.0f, 1.0f, 2.0f);
  uint4 cx = BL_UINT4_BITS(convert_int4(cell.x + lane));
  BlVoronoiBest b;
  b.d1 = b.d2 = 3.402823466e+38f;
  b.o1 = b.o2 = (float4)(0.0f);
  b.v1 = b.v2 = 0;
  float4 hx, hy, hz = (float4)(0.0f), hw = (float4)(0.0f);
  for (int u = -ureach; u <= ureach; u++)
    for (int k = -kreach; k <= kreach; k++)
      for (int j = -1; j <= 1; j++) {
        float fj = (float)j, fk = (float)k, fu = (float)u;
        blHashIntx4(dims, cx, (uint4)((uint)(int)(cell.y + fj)), (uint4)((uint)(int)(cell.z + fk)),
                    (uint4)((uint)(int)(cell.w + fu)), &hx, &hy, &hz, &hw);
        float4 d = blVoronoiMetric4((lane + hx * randomness) - rel.x,
                                    (fj + hy * randomness) - rel.y,
                                    (fk + hz * randomness) - rel.z,
                                    (fu + hw * randomness) - rel.w, dims, metric);
        b = blVoronoiKeep(b, d.x, (float4)(-1.0f, fj, fk, fu));
        b = blVoronoiKeep(b, d.y, (float4)(0.0f, fj, fk, fu));
        b = blVoronoiKeep(b, d.z, (float4)(1.0f, fj, fk, fu));
      }
  float4 o = feature == 1 ? b.o2 : b.o1;
  int v = feature == 1 ? b.v2 : b.v1;
  float4 p = v ? o + blVoronoiCellOffset(cell + o, dims) * randomness : (float4)(0.0f);
  *color = blVoronoiCellColor(cell + o, dims);
  *pos = p + cell;
  return feature == 1 ? b.d2 : b.d1;
}

/* One octave of F1 (feature 0), F2 (1) or Smooth F1 (2, smoothness already halved and > 0):
 * distance in .w of the result, colour in *color, position (in cells) in *pos. */
float blVoronoiOctave(float4 coord, int dims, int feature, int metric, float exponent,
                      float randomness, float smoothness, float3 *color, float4 *pos) {
  float4 cell = floor(coord);
  float4 rel = coord - cell;
  if (dims >= 2 && feature != 2 && metric != 3)
    return blVoronoiOctaveRows(cell, rel, dims, feature, metric, randomness, color, pos);
  int reach = feature == 2 ? 2 : 1;
  int jreach = dims == 1 ? 0 : reach, kreach = dims <= 2 ? 0 : reach;
  int ureach = dims == 4 ? reach : 0;
  float d1 = 3.402823466e+38f, d2 = 3.402823466e+38f;
  float4 o1 = (float4)(0.0f), o2 = (float4)(0.0f), p1 = (float4)(0.0f), p2 = (float4)(0.0f);
  float sd = 0.0f, h = -1.0f;
  float3 sc = (float3)(0.0f);
  float4 sp = (float4)(0.0f);
  for (int u = -ureach; u <= ureach; u++)
    for (int k = -kreach; k <= kreach; k++)
      for (int j = -jreach; j <= jreach; j++)
        for (int i = -reach; i <= reach; i++) {
          float4 off = (float4)((float)i, (float)j, (float)k, (float)u);
          float4 point = off + blVoronoiCellOffset(cell + off, dims) * randomness;
          float d = blVoronoiMetric(point, rel, dims, metric, exponent);
          if (feature == 2) {
            h = h == -1.0f ? 1.0f : blSmoothstep01(0.5f + 0.5f * (sd - d) / smoothness);
            float correction = smoothness * h * (1.0f - h);
            sd = sd + h * (d - sd) - correction;
            correction /= 1.0f + 3.0f * smoothness;
            float3 cc = blVoronoiCellColor(cell + off, dims);
            sc = sc + h * (cc - sc) - correction;
            sp = sp + h * (point - sp) - correction;
          } else if (d < d1) {
            d2 = d1;
            o2 = o1;
            p2 = p1;
            d1 = d;
            o1 = off;
            p1 = point;
          } else if (d < d2) {
            d2 = d;
            o2 = off;
            p2 = point;
          }
        }
  if (feature == 2) {
    /* The correction above is subtracted from every component; 2D has no z, 2D and 3D no w. */
    if (dims == 1)
      sp.y = 0.0f;
    if (dims <= 2)
      sp.z = 0.0f;
    if (dims <= 3)
      sp.w = 0.0f;
    *color = sc;
    *pos = cell + sp;
    return sd;
  }
  if (feature == 1) {
    *color = blVoronoiCellColor(cell + o2, dims);
    *pos = p2 + cell;
    return d2;
  }
  *color = blVoronoiCellColor(cell + o1, dims);
  *pos = p1 + cell;
  return d1;
}

/* Distance to Edge of one octave: distance to the closest bisector of the closest point and
 * another point. */
float blVoronoiEdgeOctave(float4 coord, int dims, float randomness) {
  float4 cell = floor(coord);
  float4 rel = coord - cell;
  int kreach = dims == 2 ? 0 : 1, ureach = dims == 4 ? 1 : 0;
  float4 closest = (float4)(0.0f);
  float best = 3.402823466e+38f;
  for (int u = -ureach; u <= ureach; u++)
    for (int k = -kreach; k <= kreach; k++)
      for (int j = -1; j <= 1; j++)
        for (int i = -1; i <= 1; i++) {
          float4 off = (float4)((float)i, (float)j, (float)k, (float)u);
          float4 v = off + blVoronoiCellOffset(cell + off, dims) * randomness - rel;
          float d = blDot(v, v, dims);
          if (d < best) {
            best = d;
            closest = v;
          }
        }
  best = 3.402823466e+38f;
  for (int u = -ureach; u <= ureach; u++)
    for (int k = -kreach; k <= kreach; k++)
      for (int j = -1; j <= 1; j++)
        for (int i = -1; i <= 1; i++) {
          float4 off = (float4)((float)i, (float)j, (float)k, (float)u);
          float4 v = off + blVoronoiCellOffset(cell + off, dims) * randomness - rel;
          float4 perp = v - closest;
          if (blDot(perp, perp, dims) > 0.0001f) {
            float4 n = perp / blEuclid(perp, dims);
            best = fmin(best, blDot((closest + v) / 2.0f, n, dims));
          }
        }
  return best;
}

/* Distance to Edge of one octave in 1D: Cycles measures from the midpoints between this cell's
 * point and its two neighbours' (not from the closest point's bisectors, as in 2D-4D). */
float blVoronoiEdgeOctave1D(float coord, float randomness) {
  float cell = floor(coord);
  float rel = coord - cell;
  float mid = blHashFloat1(cell) * randomness;
  float left = -1.0f + blHashFloat1(cell - 1.0f) * randomness;
  float right = 1.0f + blHashFloat1(cell + 1.0f) * randomness;
  return fmin(fabs((mid + left) / 2.0f - rel), fabs((mid + right) / 2.0f - rel));
}

/* N-Sphere Radius: half the distance from the closest point to the point closest to it. */
float blVoronoiRadius(float4 coord, int dims, float randomness) {
  float4 cell = floor(coord);
  float4 rel = coord - cell;
  int jreach = dims == 1 ? 0 : 1, kreach = dims <= 2 ? 0 : 1, ureach = dims == 4 ? 1 : 0;
  float4 closest = (float4)(0.0f), closestOff = (float4)(0.0f);
  float best = 3.402823466e+38f;
  for (int u = -ureach; u <= ureach; u++)
    for (int k = -kreach; k <= kreach; k++)
      for (int j = -jreach; j <= jreach; j++)
        for (int i = -1; i <= 1; i++) {
          float4 off = (float4)((float)i, (float)j, (float)k, (float)u);
          float4 point = off + blVoronoiCellOffset(cell + off, dims) * randomness;
          float d = blEuclid(point - rel, dims);
          if (d < best) {
            best = d;
            closest = point;
            closestOff = off;
          }
        }
  best = 3.402823466e+38f;
  float4 neighbour = (float4)(0.0f);
  for (int u = -ureach; u <= ureach; u++)
    for (int k = -kreach; k <= kreach; k++)
      for (int j = -jreach; j <= jreach; j++)
        for (int i = -1; i <= 1; i++) {
          if (i == 0 && j == 0 && k == 0 && u == 0)
            continue;
          float4 off = (float4)((float)i, (float)j, (float)k, (float)u) + closestOff;
          float4 point = off + blVoronoiCellOffset(cell + off, dims) * randomness;
          float d = blEuclid(closest - point, dims);
          if (d < best) {
            best = d;
            neighbour = point;
          }
        }
  return blEuclid(neighbour - closest, dims) / 2.0f;
}

/* The node: output 0 Distance, 1 Color, 2 Position (w: the W output), 3 Radius, as a float4
 * (scalar in .x). w is the W input (4D only). */
float4 blVoronoiTexture(float3 vector, float w, int dims, float scale, float detail,
                        float roughness, float lacunarity, float smoothness, float exponent,
                        float randomness, int feature, int metric, int normalize, int output) {
  detail = clamp(detail, 0.0f, 15.0f);
  roughness = clamp(roughness, 0.0f, 1.0f);
  randomness = clamp(randomness, 0.0f, 1.0f);
  smoothness = clamp(smoothness / 2.0f, 0.0f, 0.5f);
  float4 coord = (float4)(vector * scale, dims == 4 ? w * scale : 0.0f);
  if (dims == 1)
    coord = (float4)(w * scale, 0.0f, 0.0f, 0.0f);
  if (dims == 2)
    coord.z = 0.0f;
  if (feature == 4)
    return output == 3 ? (float4)(blVoronoiRadius(coord, dims, randomness), 0.0f, 0.0f, 0.0f)
                       : (float4)(0.0f);
  int zeroInput = detail == 0.0f || roughness == 0.0f;
  float amplitude = 1.0f, octaveScale = 1.0f;
  if (feature == 3) {
    if (output != 0)
      return (float4)(0.0f);
    float maxDistance = 0.5f + 0.5f * randomness;
    float maxAmplitude = maxDistance, distance = 8.0f;
    for (int i = 0; i <= ceil(detail); ++i) {
      float d = dims == 1 ? blVoronoiEdgeOctave1D(coord.x * octaveScale, randomness)
                          : blVoronoiEdgeOctave(coord * octaveScale, dims, randomness);
      if (zeroInput) {
        distance = d;
        break;
      }
      if (i <= detail) {
        maxAmplitude = maxAmplitude + amplitude * (maxDistance / octaveScale - maxAmplitude);
        distance = distance + amplitude * (fmin(distance, d / octaveScale) - distance);
        octaveScale *= lacunarity;
        amplitude *= roughness;
      } else {
        float rmd = detail - floor(detail);
        if (rmd != 0.0f) {
          float lerpAmplitude =
              maxAmplitude + amplitude * (maxDistance / octaveScale - maxAmplitude);
          maxAmplitude = maxAmplitude + rmd * (lerpAmplitude - maxAmplitude);
          float lerpDistance = distance + amplitude * (fmin(distance, d / octaveScale) - distance);
          distance = distance + rmd * (fmin(distance, lerpDistance) - distance);
        }
      }
    }
    if (normalize)
      distance /= maxAmplitude;
    return (float4)(distance, 0.0f, 0.0f, 0.0f);
  }
  if (feature == 2 && smoothness == 0.0f)
    feature = 0;
  float m = 0.5f + 0.5f * randomness;
  float maxDistance = blVoronoiMetric((float4)(0.0f), (float4)(m), dims, metric,
                                      exponent) * (feature == 1 ? 2.0f : 1.0f);
  float maxAmplitude = 0.0f, distance = 0.0f;
  float3 color = (float3)(0.0f);
  float4 position = (float4)(0.0f);
  for (int i = 0; i <= ceil(detail); ++i) {
    float3 c;
    float4 p;
    float d = blVoronoiOctave(coord * octaveScale, dims, feature, metric, exponent, randomness,
                              smoothness, &c, &p);
    if (zeroInput) {
      maxAmplitude = 1.0f;
      distance = d;
      color = c;
      position = p;
      break;
    }
    if (i <= detail) {
      maxAmplitude += amplitude;
      distance += d * amplitude;
      color += c * amplitude;
      position = position + amplitude * (p / octaveScale - position);
      octaveScale *= lacunarity;
      amplitude *= roughness;
    } else {
      float rmd = detail - floor(detail);
      if (rmd != 0.0f) {
        maxAmplitude = maxAmplitude + rmd * (maxAmplitude + amplitude - maxAmplitude);
        distance = distance + rmd * (distance + d * amplitude - distance);
        color = color + rmd * (color + c * amplitude - color);
        float4 lerpPosition = position + amplitude * (p / octaveScale - position);
        position = position + rmd * (lerpPosition - position);
      }
    }
  }
  if (normalize) {
    distance /= maxAmplitude * maxDistance;
    color /= maxAmplitude;
  }
  position = scale != 0.0f ? position / scale : (float4)(0.0f);
  if (output == 0)
    return (float4)(distance, 0.0f, 0.0f, 0.0f);
  if (output == 1)
    return (float4)(color, 0.0f);
  if (output == 2)
    return position;
  return (float4)(0.0f);
}

float blVoronoi2DDistance(float3 vector, float scale, float detail, float roughness,
                          float lacunarity, float smoothness, float exponent, float randomness,
                          int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, 0.0f, 2, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 0).x;
}

float3 blVoronoi2DColor(float3 vector, float scale, float detail, float roughness,
                        float lacunarity, float smoothness, float exponent, float randomness,
                        int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, 0.0f, 2, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 1).xyz;
}

float3 blVoronoi2DPosition(float3 vector, float scale, float detail, float roughness,
                           float lacunarity, float smoothness, float exponent, float randomness,
                           int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, 0.0f, 2, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 2).xyz;
}

float blVoronoi2DRadius(float3 vector, float scale, float detail, float roughness,
                        float lacunarity, float smoothness, float exponent, float randomness,
                        int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, 0.0f, 2, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 3).x;
}

float blVoronoi3DDistance(float3 vector, float scale, float detail, float roughness,
                          float lacunarity, float smoothness, float exponent, float randomness,
                          int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, 0.0f, 3, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 0).x;
}

float3 blVoronoi3DColor(float3 vector, float scale, float detail, float roughness,
                        float lacunarity, float smoothness, float exponent, float randomness,
                        int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, 0.0f, 3, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 1).xyz;
}

float3 blVoronoi3DPosition(float3 vector, float scale, float detail, float roughness,
                           float lacunarity, float smoothness, float exponent, float randomness,
                           int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, 0.0f, 3, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 2).xyz;
}

float blVoronoi3DRadius(float3 vector, float scale, float detail, float roughness,
                        float lacunarity, float smoothness, float exponent, float randomness,
                        int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, 0.0f, 3, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 3).x;
}

float blVoronoi4DDistance(float3 vector, float w, float scale, float detail, float roughness,
                          float lacunarity, float smoothness, float exponent, float randomness,
                          int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, w, 4, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 0).x;
}

float3 blVoronoi4DColor(float3 vector, float w, float scale, float detail, float roughness,
                        float lacunarity, float smoothness, float exponent, float randomness,
                        int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, w, 4, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 1).xyz;
}

float3 blVoronoi4DPosition(float3 vector, float w, float scale, float detail, float roughness,
                           float lacunarity, float smoothness, float exponent, float randomness,
                           int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, w, 4, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 2).xyz;
}

float blVoronoi4DW(float3 vector, float w, float scale, float detail, float roughness,
                   float lacunarity, float smoothness, float exponent, float randomness,
                   int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, w, 4, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 2).w;
}

float blVoronoi4DRadius(float3 vector, float w, float scale, float detail, float roughness,
                        float lacunarity, float smoothness, float exponent, float randomness,
                        int feature, int metric, int normalize) {
  return blVoronoiTexture(vector, w, 4, scale, detail, roughness, lacunarity, smoothness,
                          exponent, randomness, feature, metric, normalize, 3).x;
}

/* 1D: the W input only; every metric is |a - b| on a line, so there is no metric or exponent.
 * Position is the W output. */
float blVoronoi1DDistance(float w, float scale, float detail, float roughness, float lacunarity,
                          float smoothness, float randomness, int feature, int normalize) {
  return blVoronoiTexture((float3)(0.0f), w, 1, scale, detail, roughness, lacunarity, smoothness,
                          1.0f, randomness, feature, 0, normalize, 0).x;
}

float3 blVoronoi1DColor(float w, float scale, float detail, float roughness, float lacunarity,
                        float smoothness, float randomness, int feature, int normalize) {
  return blVoronoiTexture((float3)(0.0f), w, 1, scale, detail, roughness, lacunarity, smoothness,
                          1.0f, randomness, feature, 0, normalize, 1).xyz;
}

float blVoronoi1DW(float w, float scale, float detail, float roughness, float lacunarity,
                   float smoothness, float randomness, int feature, int normalize) {
  return blVoronoiTexture((float3)(0.0f), w, 1, scale, detail, roughness, lacunarity, smoothness,
                          1.0f, randomness, feature, 0, normalize, 2).x;
}

float blVoronoi1DRadius(float w, float scale, float detail, float roughness, float lacunarity,
                        float smoothness, float randomness, int feature, int normalize) {
  return blVoronoiTexture((float3)(0.0f), w, 1, scale, detail, roughness, lacunarity, smoothness,
                          1.0f, randomness, feature, 0, normalize, 3).x;
}
