/* tex.cl: small textures for the reliability corpus (testsuite/reliability).
 *   add(a: float, b: float) -> float: a + b.
 *   tint(color: float3, gain: float) -> float3: color * gain.
 *   octave(p: float3, octaves: int) -> float: p.x scaled by the octave count.
 *   rootOf(x: float) -> float: sqrt(x), NaN for a negative x (the NaN tests).
 *   sample(image: sam2D, uv: float2) -> float4: the image at uv.
 */
float add(float a, float b) { return a + b; }

float3 tint(float3 color, float gain) { return color * gain; }

float octave(float3 p, int octaves) { return p.x * (float)octaves; }

float rootOf(float x) { return sqrt(x); }

float4 sample(sam2D image, float2 uv) { return tex2D(image, uv); }
