/* User functions declared every way OpenCL C allows: static, C99 inline, static inline, a
 * prototype before the definition, and one the user keeps out of line with noinline. */
static float half1(float x) { return 0.5f * x; }
inline float twice(float x) { return 2.0f * x; }
static inline float third(float x) { return x / 3.0f; }
float later(float x);
__attribute__((noinline)) float slow(float x) { return x + 1.0f; }
float markerTex(float3 p, float k) { return half1(p.x) + twice(p.y) + third(p.z) + slow(k) + later(k); }
float later(float x) { return x * x; }
