/* blender/hash.h: the hashes of Blender's procedural textures (Cycles' util/hash.h): Bob
 * Jenkins' lookup3 of 2, 3 or 4 32-bit words, and floats hashed by their bit patterns into
 * [0, 1]. Included by the textures of this folder (each gets its own renamed copy). */

uint blRot(uint x, int k) { return (x << k) | (x >> (32 - k)); }

/* lookup3's final mix of (a, b, c); returns c. */
uint blHashFinal(uint a, uint b, uint c) {
  c ^= b;
  c -= blRot(b, 14);
  a ^= c;
  a -= blRot(c, 11);
  b ^= a;
  b -= blRot(a, 25);
  c ^= b;
  c -= blRot(b, 16);
  a ^= c;
  a -= blRot(c, 4);
  b ^= a;
  b -= blRot(a, 14);
  c ^= b;
  c -= blRot(b, 24);
  return c;
}

/* lookup3 of 1..4 32-bit words: the seed is 0xdeadbeef plus the length in bytes plus 13. */
uint blHash1(uint x) {
  uint s = 0xdeadbeefU + 4U + 13U;
  return blHashFinal(s + x, s, s);
}

uint blHash2(uint x, uint y) {
  uint s = 0xdeadbeefU + 8U + 13U;
  return blHashFinal(s + x, s + y, s);
}

uint blHash3(uint x, uint y, uint z) {
  uint s = 0xdeadbeefU + 12U + 13U;
  return blHashFinal(s + x, s + y, s + z);
}

uint blHash4(uint x, uint y, uint z, uint w) {
  uint s = 0xdeadbeefU + 16U + 13U;
  uint a = s + x, b = s + y, c = s + z;
  a -= c; a ^= blRot(c, 4); c += b;
  b -= a; b ^= blRot(a, 6); a += c;
  c -= b; c ^= blRot(b, 8); b += a;
  a -= c; a ^= blRot(c, 16); c += b;
  b -= a; b ^= blRot(a, 19); a += c;
  c -= b; c ^= blRot(b, 4); b += a;
  return blHashFinal(a + w, b, c);
}

/* lookup3 in four lanes at once: blHash2/3/4 of each lane (Perlin hashes four lattice corners
 * per call, as Cycles' SSE code does). Shift counts are unsigned because the host target's
 * vector operators (GLM) take a count of the vector's own element type. */
uint4 blRot4(uint4 x, uint k) { return (x << k) | (x >> (32U - k)); }

uint4 blHashFinal4(uint4 a, uint4 b, uint4 c) {
  c ^= b;
  c -= blRot4(b, 14U);
  a ^= c;
  a -= blRot4(c, 11U);
  b ^= a;
  b -= blRot4(a, 25U);
  c ^= b;
  c -= blRot4(b, 16U);
  a ^= c;
  a -= blRot4(c, 4U);
  b ^= a;
  b -= blRot4(a, 14U);
  c ^= b;
  c -= blRot4(b, 24U);
  return c;
}

uint4 blHash2x4(uint4 x, uint4 y) {
  uint s = 0xdeadbeefU + 8U + 13U;
  return blHashFinal4(x + s, y + s, (uint4)(s));
}

uint4 blHash3x4(uint4 x, uint4 y, uint4 z) {
  uint s = 0xdeadbeefU + 12U + 13U;
  return blHashFinal4(x + s, y + s, z + s);
}

uint4 blHash4x4(uint4 x, uint4 y, uint4 z, uint4 w) {
  uint s = 0xdeadbeefU + 16U + 13U;
  uint4 a = x + s, b = y + s, c = z + s;
  a -= c; a ^= blRot4(c, 4U); c += b;
  b -= a; b ^= blRot4(a, 6U); a += c;
  c -= b; c ^= blRot4(b, 8U); b += a;
  a -= c; a ^= blRot4(c, 16U); c += b;
  b -= a; b ^= blRot4(a, 19U); a += c;
  c -= b; c ^= blRot4(b, 4U); b += a;
  return blHashFinal4(a + w, b, c);
}

/* The bits of an int4 as a uint4 and back. OpenCL reinterprets (as_uint4, as_int4); the host
 * target's prelude has no as_uint4, and its vector conversion between int and uint lanes keeps
 * the bits (two's complement). */
#ifdef __OPENCL_C_VERSION__
#define BL_UINT4_BITS(v) as_uint4(v)
#define BL_INT4_BITS(v) as_int4(v)
#else
#define BL_UINT4_BITS(v) uint4(v)
#define BL_INT4_BITS(v) int4(v)
#endif

/* -v in the lanes of v whose mask lane has its top bit set, v elsewhere (exact: a sign flip).
 * OpenCL flips the sign bits with one xor; the host target, whose prelude has no as_float4,
 * selects -v. Both give the same bits. */
#ifdef __OPENCL_C_VERSION__
#define BL_NEGATE_IF4(v, mask) as_float4(as_uint4(v) ^ ((mask) & 0x80000000U))
#else
#define BL_NEGATE_IF4(v, mask) select((v), -(v), (mask))
#endif

/* A hash mapped to [0, 1] as Cycles does (times 1 / 0xFFFFFFFF rounded to float, i.e. 2^-32). */
float blHashToUnit(uint h) { return (float)h * (1.0f / 4294967296.0f); }

float blHashFloat1(float x) { return blHashToUnit(blHash1(as_uint(x))); }

float blHashFloat2(float x, float y) { return blHashToUnit(blHash2(as_uint(x), as_uint(y))); }

float blHashFloat3(float x, float y, float z) {
  return blHashToUnit(blHash3(as_uint(x), as_uint(y), as_uint(z)));
}

float blHashFloat4(float x, float y, float z, float w) {
  return blHashToUnit(blHash4(as_uint(x), as_uint(y), as_uint(z), as_uint(w)));
}

/* PCG 2D and 3D (Jarzynski and Olano, "Hash Functions for GPU Rendering", JCGT 2020) in the
 * signed-integer form Cycles uses for Voronoi cells (so the >> 16 is arithmetic), each
 * component masked to 31 bits and mapped to [0, 1] (times 2^-31). Unsigned arithmetic here:
 * the same bits as Cycles' wrapping signed arithmetic, without signed overflow. */
uint blXorShift16(uint v) { return v ^ (uint)((int)v >> 16); }

float blPcgToUnit(uint v) { return (float)(int)(v & 0x7FFFFFFFU) * (1.0f / 2147483648.0f); }

float4 blHashInt2(int x, int y) {
  uint a = (uint)x * 1664525U + 1013904223U, b = (uint)y * 1664525U + 1013904223U;
  a += b * 1664525U;
  b += a * 1664525U;
  a = blXorShift16(a);
  b = blXorShift16(b);
  a += b * 1664525U;
  b += a * 1664525U;
  return (float4)(blPcgToUnit(a), blPcgToUnit(b), 0.0f, 0.0f);
}

float4 blHashInt3(int x, int y, int z) {
  uint a = (uint)x * 1664525U + 1013904223U, b = (uint)y * 1664525U + 1013904223U;
  uint c = (uint)z * 1664525U + 1013904223U;
  a += b * c;
  b += c * a;
  c += a * b;
  a = blXorShift16(a);
  b = blXorShift16(b);
  c = blXorShift16(c);
  a += b * c;
  b += c * a;
  c += a * b;
  return (float4)(blPcgToUnit(a), blPcgToUnit(b), blPcgToUnit(c), 0.0f);
}

float4 blHashInt4(int x, int y, int z, int w) {
  uint a = (uint)x * 1664525U + 1013904223U, b = (uint)y * 1664525U + 1013904223U;
  uint c = (uint)z * 1664525U + 1013904223U, d = (uint)w * 1664525U + 1013904223U;
  a += b * d;
  b += c * a;
  c += a * b;
  d += b * c;
  a = blXorShift16(a);
  b = blXorShift16(b);
  c = blXorShift16(c);
  d = blXorShift16(d);
  a += b * d;
  b += c * a;
  c += a * b;
  d += b * c;
  return (float4)(blPcgToUnit(a), blPcgToUnit(b), blPcgToUnit(c), blPcgToUnit(d));
}

/* blHashInt2/3/4 in four lanes: lane l of *ha.. is component 0.. of blHashIntN of lane l's
 * cell (Voronoi hashes a row of three cells per call). dims 2 leaves *hc and *hd alone, 3 *hd. */
uint4 blXorShift16x4(uint4 v) { return v ^ BL_UINT4_BITS(BL_INT4_BITS(v) >> 16); }

float4 blPcgToUnit4(uint4 v) {
  return convert_float4(BL_INT4_BITS(v & 0x7FFFFFFFU)) * (1.0f / 2147483648.0f);
}

void blHashIntx4(int dims, uint4 a, uint4 b, uint4 c, uint4 d, float4 *ha, float4 *hb,
                 float4 *hc, float4 *hd) {
  a = a * 1664525U + 1013904223U;
  b = b * 1664525U + 1013904223U;
  if (dims == 2) {
    a += b * 1664525U;
    b += a * 1664525U;
    a = blXorShift16x4(a);
    b = blXorShift16x4(b);
    a += b * 1664525U;
    b += a * 1664525U;
  } else if (dims == 3) {
    c = c * 1664525U + 1013904223U;
    a += b * c;
    b += c * a;
    c += a * b;
    a = blXorShift16x4(a);
    b = blXorShift16x4(b);
    c = blXorShift16x4(c);
    a += b * c;
    b += c * a;
    c += a * b;
    *hc = blPcgToUnit4(c);
  } else {
    c = c * 1664525U + 1013904223U;
    d = d * 1664525U + 1013904223U;
    a += b * d;
    b += c * a;
    c += a * b;
    d += b * c;
    a = blXorShift16x4(a);
    b = blXorShift16x4(b);
    c = blXorShift16x4(c);
    d = blXorShift16x4(d);
    a += b * d;
    b += c * a;
    c += a * b;
    d += b * c;
    *hc = blPcgToUnit4(c);
    *hd = blPcgToUnit4(d);
  }
  *ha = blPcgToUnit4(a);
  *hb = blPcgToUnit4(b);
}

