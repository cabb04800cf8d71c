/* texture300.cl: a realistic 300-line texture file for the front end's speed benchmark
 * (bench/frontend-speed.md). Value and gradient noise, fBm, turbulence, Voronoi (F1/F2),
 * domain warping, and five textures built from them:
 *   marble(float3 p, float scale, int octaves, __global const float4 *ramp, int rampCount) float3
 *   wood(float3 p, float rings, float grain) float3
 *   rust(float3 p, float amount, float threshold) float
 *   cells(float3 p, float scale, float jitter) float2
 *   layered(sam2D image, float3 p, float blend) float4
 */

#define NOISE_OCTAVES_MAX 12
#define LACUNARITY 2.0f
#define GAIN 0.5f
#define TWO_PI 6.28318530718f
#define SMOOTH(t) ((t) * (t) * (3.0f - 2.0f * (t)))
#define QUINTIC(t) ((t) * (t) * (t) * ((t) * ((t) * 6.0f - 15.0f) + 10.0f))

__constant float kGradients[12][3] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1},
    {1, 0, -1}, {-1, 0, -1}, {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}};

/* Integer hashing (PCG-like): deterministic on every device. */
uint hashUint(uint x) {
  x ^= x >> 16;
  x *= 0x7feb352dU;
  x ^= x >> 15;
  x *= 0x846ca68bU;
  x ^= x >> 16;
  return x;
}

uint hash3i(int3 c) {
  uint h = hashUint((uint)c.x);
  h = hashUint(h ^ (uint)c.y);
  h = hashUint(h ^ (uint)c.z);
  return h;
}

float hashToUnit(uint h) { return (float)(h & 0x00ffffffU) / 16777216.0f; }

float3 hashToUnit3(uint h) {
  return (float3)(hashToUnit(h), hashToUnit(hashUint(h + 1U)), hashToUnit(hashUint(h + 2U)));
}

/* Value noise in [0,1]. */
float valueNoise(float3 p) {
  float3 i = floor(p);
  float3 f = p - i;
  int3 c = convert_int3(i);
  float3 u = (float3)(SMOOTH(f.x), SMOOTH(f.y), SMOOTH(f.z));
  float n000 = hashToUnit(hash3i(c));
  float n100 = hashToUnit(hash3i(c + (int3)(1, 0, 0)));
  float n010 = hashToUnit(hash3i(c + (int3)(0, 1, 0)));
  float n110 = hashToUnit(hash3i(c + (int3)(1, 1, 0)));
  float n001 = hashToUnit(hash3i(c + (int3)(0, 0, 1)));
  float n101 = hashToUnit(hash3i(c + (int3)(1, 0, 1)));
  float n011 = hashToUnit(hash3i(c + (int3)(0, 1, 1)));
  float n111 = hashToUnit(hash3i(c + (int3)(1, 1, 1)));
  float x00 = mix(n000, n100, u.x);
  float x10 = mix(n010, n110, u.x);
  float x01 = mix(n001, n101, u.x);
  float x11 = mix(n011, n111, u.x);
  return mix(mix(x00, x10, u.y), mix(x01, x11, u.y), u.z);
}

float gradientDot(int3 c, float3 d) {
  uint g = hash3i(c) % 12U;
  return kGradients[g][0] * d.x + kGradients[g][1] * d.y + kGradients[g][2] * d.z;
}

/* Gradient (Perlin) noise in about [-1,1]. */
float gradientNoise(float3 p) {
  float3 i = floor(p);
  float3 f = p - i;
  int3 c = convert_int3(i);
  float3 u = (float3)(QUINTIC(f.x), QUINTIC(f.y), QUINTIC(f.z));
  float g000 = gradientDot(c, f);
  float g100 = gradientDot(c + (int3)(1, 0, 0), f - (float3)(1, 0, 0));
  float g010 = gradientDot(c + (int3)(0, 1, 0), f - (float3)(0, 1, 0));
  float g110 = gradientDot(c + (int3)(1, 1, 0), f - (float3)(1, 1, 0));
  float g001 = gradientDot(c + (int3)(0, 0, 1), f - (float3)(0, 0, 1));
  float g101 = gradientDot(c + (int3)(1, 0, 1), f - (float3)(1, 0, 1));
  float g011 = gradientDot(c + (int3)(0, 1, 1), f - (float3)(0, 1, 1));
  float g111 = gradientDot(c + (int3)(1, 1, 1), f - (float3)(1, 1, 1));
  float x00 = mix(g000, g100, u.x);
  float x10 = mix(g010, g110, u.x);
  float x01 = mix(g001, g101, u.x);
  float x11 = mix(g011, g111, u.x);
  return mix(mix(x00, x10, u.y), mix(x01, x11, u.y), u.z);
}

/* Fractal Brownian motion over gradient noise, normalised to about [-1,1]. */
float fbm(float3 p, int octaves) {
  float sum = 0.0f;
  float amplitude = 1.0f;
  float norm = 0.0f;
  int n = clamp(octaves, 1, NOISE_OCTAVES_MAX);
  for (int o = 0; o < n; ++o) {
    sum += amplitude * gradientNoise(p);
    norm += amplitude;
    amplitude *= GAIN;
    p *= LACUNARITY;
  }
  return sum / norm;
}

/* Turbulence: fBm of |noise|, in [0,1]. */
float turbulence(float3 p, int octaves) {
  float sum = 0.0f;
  float amplitude = 1.0f;
  float norm = 0.0f;
  int n = clamp(octaves, 1, NOISE_OCTAVES_MAX);
  for (int o = 0; o < n; ++o) {
    sum += amplitude * fabs(gradientNoise(p));
    norm += amplitude;
    amplitude *= GAIN;
    p *= LACUNARITY;
  }
  return sum / norm;
}

/* Ridged multifractal, in [0,1]. */
float ridged(float3 p, int octaves, float offset) {
  float sum = 0.0f;
  float amplitude = 0.5f;
  float previous = 1.0f;
  int n = clamp(octaves, 1, NOISE_OCTAVES_MAX);
  for (int o = 0; o < n; ++o) {
    float r = offset - fabs(gradientNoise(p));
    r *= r;
    sum += r * amplitude * previous;
    previous = r;
    amplitude *= GAIN;
    p *= LACUNARITY;
  }
  return clamp(sum, 0.0f, 1.0f);
}

/* Voronoi: distances to the nearest and second-nearest feature points (F1, F2). */
float2 voronoi(float3 p, float jitter) {
  float3 i = floor(p);
  float3 f = p - i;
  int3 c = convert_int3(i);
  float f1 = 8.0f, f2 = 8.0f;
  for (int z = -1; z <= 1; ++z) {
    for (int y = -1; y <= 1; ++y) {
      for (int x = -1; x <= 1; ++x) {
        int3 cell = c + (int3)(x, y, z);
        float3 feature = (float3)(x, y, z) + jitter * hashToUnit3(hash3i(cell));
        float d = length(feature - f);
        if (d < f1) {
          f2 = f1;
          f1 = d;
        } else if (d < f2) {
          f2 = d;
        }
      }
    }
  }
  return (float2)(f1, f2);
}

/* Domain warping: displaces p by a vector fBm field. */
float3 warp(float3 p, float strength, int octaves) {
  float3 q = (float3)(fbm(p, octaves), fbm(p + (float3)(5.2f, 1.3f, 2.8f), octaves),
                      fbm(p + (float3)(1.7f, 9.2f, 4.1f), octaves));
  return p + strength * q;
}

/* Evaluates a piecewise-linear colour ramp; stops are (position, r, g, b), sorted. */
float3 evalRamp(__global const float4 *stops, int count, float t) {
  if (count <= 0)
    return (float3)(t);
  if (t <= stops[0].x)
    return stops[0].yzw;
  for (int k = 1; k < count; ++k) {
    if (t <= stops[k].x) {
      float span = max(stops[k].x - stops[k - 1].x, 1e-6f);
      float w = (t - stops[k - 1].x) / span;
      return mix(stops[k - 1].yzw, stops[k].yzw, w);
    }
  }
  return stops[count - 1].yzw;
}

float luminance(float3 c) { return dot(c, (float3)(0.2126f, 0.7152f, 0.0722f)); }

float3 saturate3(float3 c) { return clamp(c, 0.0f, 1.0f); }

/* Marble: veins along x, perturbed by turbulence, coloured by a ramp. */
float3 marble(float3 p, float scale, int octaves, __global const float4 *ramp, int rampCount) {
  float3 q = p * scale;
  float t = 0.5f + 0.5f * sin(q.x * 4.0f + 6.0f * turbulence(q, octaves));
  float3 base = evalRamp(ramp, rampCount, t);
  float ao = readAttr("AO");
  return saturate3(base * (0.6f + 0.4f * ao));
}

/* Wood: concentric rings around the object's y axis, with fine grain and a warm tint. */
float3 wood(float3 p, float rings, float grain) {
  float3 q = warp(p, 0.15f, 3);
  float r = length(q.xz) * rings;
  float ring = r - floor(r);
  ring = SMOOTH(ring);
  float fine = valueNoise(q * (float3)(grain, grain * 0.05f, grain));
  float3 light = (float3)(0.72f, 0.52f, 0.32f);
  float3 dark = (float3)(0.38f, 0.22f, 0.10f);
  float3 color = mix(dark, light, 0.7f * ring + 0.3f * fine);
  float3 n = readAttr("Normal");
  float3 v = readAttr("ViewDir");
  float facing = clamp(dot(n, v), 0.0f, 1.0f);
  return color * (0.8f + 0.2f * facing);
}

/* Rust: a mask in [0,1] that grows in occluded creases and follows ridged noise. */
float rust(float3 p, float amount, float threshold) {
  float3 wp = readAttr("WorldPos");
  float ao = readAttr("AO");
  float crease = 1.0f - ao;
  float pattern = ridged(p * 3.0f + wp * 0.1f, 5, 1.0f);
  float streaks = turbulence((float3)(p.x * 8.0f, p.y * 0.5f, p.z * 8.0f), 4);
  float m = amount * (0.55f * pattern + 0.25f * streaks + 0.6f * crease);
  return smoothstep(threshold - 0.05f, threshold + 0.05f, m);
}

/* Cells: (F1, F2 - F1) of Voronoi, animated slowly with the scene time. */
float2 cells(float3 p, float scale, float jitter) {
  float time = readSetting("Time");
  float3 q = p * scale + (float3)(0.0f, 0.1f * time, 0.0f);
  float2 d = voronoi(q, clamp(jitter, 0.0f, 1.0f));
  return (float2)(d.x, d.y - d.x);
}

/* Layered: an image over a procedural base, blended by fBm and the surface's grazing angle. */
float4 layered(sam2D image, float3 p, float blend) {
  float2 uv = readAttr("TexCoord0");
  float4 texel = tex2D(image, uv);
  float3 base = wood(p, 6.0f, 40.0f);
  float n = 0.5f + 0.5f * fbm(p * 2.0f, 5);
  float3 g = readAttr("GeomNormal");
  float3 v = readAttr("ViewDir");
  float grazing = 1.0f - fabs(dot(g, v));
  float w = clamp(blend * n + 0.25f * grazing, 0.0f, 1.0f);
  float3 color = mix(base, texel.xyz, w * texel.w);
  return (float4)(color, 1.0f);
}

/* Helpers kept for other graphs. */
float checker3(float3 p, float size) {
  int3 c = convert_int3(floor(p / size));
  return (float)((c.x + c.y + c.z) & 1);
}

float stripes(float x, float width, float softness) {
  float s = 0.5f + 0.5f * sin(TWO_PI * x / width);
  return smoothstep(0.5f - softness, 0.5f + softness, s);
}

float3 hueShift(float3 color, float shift) {
  const float3 k = (float3)(0.57735f);
  float c = cos(shift * TWO_PI);
  return color * c + cross(k, color) * sin(shift * TWO_PI) + k * dot(k, color) * (1.0f - c);
}

float3 contrast(float3 color, float amount) {
  float l = luminance(color);
  return saturate3((color - l) * amount + l);
}

float bias(float t, float b) { return pow(t, log(b) / log(0.5f)); }

float gainCurve(float t, float g) {
  return t < 0.5f ? bias(2.0f * t, 1.0f - g) * 0.5f : 1.0f - bias(2.0f - 2.0f * t, 1.0f - g) * 0.5f;
}

float3 triplanarWeights(float3 n, float sharpness) {
  float3 w = pow(fabs(n), (float3)(sharpness));
  return w / (w.x + w.y + w.z);
}

float triplanarNoise(float3 p, float scale) {
  float3 n = readAttr("Normal");
  float3 w = triplanarWeights(n, 4.0f);
  float a = valueNoise((float3)(p.y, p.z, 0.0f) * scale);
  float b = valueNoise((float3)(p.x, p.z, 0.0f) * scale);
  float c = valueNoise((float3)(p.x, p.y, 0.0f) * scale);
  return a * w.x + b * w.y + c * w.z;
}

float flicker(float speed) {
  int frame = readSetting("Frame");
  float t = readSetting("Time");
  return 0.5f + 0.5f * sin(speed * t + 0.01f * (float)frame);
}

float distanceFade(float nearDist, float farDist) {
  float3 cam = readSetting("CameraPos");
  float3 wp = readAttr("WorldPos");
  return 1.0f - smoothstep(nearDist, farDist, distance(cam, wp));
}

float3 tangentStreaks(float3 p, float density) {
  float3 t = readAttr("Tangent");
  float s = stripes(dot(p, t) * density, 1.0f, 0.2f);
  return (float3)(s, s * 0.9f, s * 0.8f);
}

float objectMask(float height) {
  float3 op = readAttr("ObjectPos");
  return step(height, op.y);
}
