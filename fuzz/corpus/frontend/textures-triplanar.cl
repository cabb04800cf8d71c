/* triplanar.cl: triplanar projection of an image (no texture coordinates needed).
 *
 * The image is projected along the three axes: onto the yz plane (seen from x), the zx plane
 * (from y) and the xy plane (from z), each lookup at p * scale; the three are blended with
 * weights |n_i|^sharpness, normalised to sum 1. Where n is axis-aligned the result is exactly
 * that axis' projection. Continuous in p and n.
 *
 * Texture functions (graph "fn" names):
 *
 *   float4 triplanar(sam2D image, float3 p, float3 n, float scale, float sharpness)
 *   float3 triplanarWeights(float3 n, float sharpness)   the blend weights (x, y, z), sum 1
 *
 * Parameters:
 *
 *   | name      | type   | default | range  | meaning                                       |
 *   |-----------|--------|---------|--------|-----------------------------------------------|
 *   | image     | sam2D  | -       | -      | {"image": name}                               |
 *   | p         | float3 | -       | any    | usually {"attr": "ObjectPos"}                 |
 *   | n         | float3 | -       | != 0   | usually {"attr": "Normal"}; need not be unit  |
 *   | scale     | float  | 1.0     | != 0   | image repetitions per unit of p               |
 *   | sharpness | float  | 4.0     | >= 1   | blend exponent: 1 soft, large values hard seams |
 */

float3 triplanarWeights(float3 n, float sharpness) {
  float wx = pow(fabs(n.x), sharpness);
  float wy = pow(fabs(n.y), sharpness);
  float wz = pow(fabs(n.z), sharpness);
  float sum = wx + wy + wz;
  if (!(sum > 0.0f))
    return (float3)(1.0f / 3.0f, 1.0f / 3.0f, 1.0f / 3.0f);
  return (float3)(wx / sum, wy / sum, wz / sum);
}

float4 triplanar(sam2D image, float3 p, float3 n, float scale, float sharpness) {
  float3 w = triplanarWeights(n, sharpness);
  float4 cx = tex2D(image, (float2)(p.y * scale, p.z * scale));
  float4 cy = tex2D(image, (float2)(p.z * scale, p.x * scale));
  float4 cz = tex2D(image, (float2)(p.x * scale, p.y * scale));
  return cx * w.x + cy * w.y + cz * w.z;
}
