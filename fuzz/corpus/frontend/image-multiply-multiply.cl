/* multiply.cl: the paper's sample texture: two images multiplied.
 *
 * Both images are looked up with tex2D at the hit's texture coordinates (each with its own
 * tiling) and multiplied channel by channel: the colour image shows through where the mask
 * image is white and is darkened where it is dark. The images are bound in graph.json
 * ("images") and reach the function as sam2D handles.
 *
 * Texture function (graph "fn" name):
 *
 *   float3 multiplyImages(sam2D colorImage, sam2D maskImage, float2 colorTiling, float2 maskTiling)
 *
 * Parameters:
 *
 *   | name        | type   | default | range | meaning                                      |
 *   |-------------|--------|---------|-------|----------------------------------------------|
 *   | colorImage  | sam2D  | -       | -     | {"image": "tiles"}                           |
 *   | maskImage   | sam2D  | -       | -     | {"image": "dots"}                            |
 *   | colorTiling | float2 | (1, 1)  | != 0  | repetitions of colorImage over uv [0, 1]^2   |
 *   | maskTiling  | float2 | (2, 2)  | != 0  | repetitions of maskImage                     |
 */

float3 multiplyImages(sam2D colorImage, sam2D maskImage, float2 colorTiling, float2 maskTiling) {
  float2 uv = readAttr("TexCoord0");
  float4 c = tex2D(colorImage, (float2)(uv.x * colorTiling.x, uv.y * colorTiling.y));
  float4 m = tex2D(maskImage, (float2)(uv.x * maskTiling.x, uv.y * maskTiling.y));
  return (float3)(c.x * m.x, c.y * m.y, c.z * m.z);
}
