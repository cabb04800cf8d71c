/* image.cl: image lookup through tex2D.
 *
 * tex2D is the embedded API's bilinear, wrapping fetch (returns linear RGBA; an unbound image
 * reads magenta). These nodes add tiling and an offset in uv, so an image repeats `tiling`
 * times over the unit square; the result is periodic in uv with period 1 / tiling.
 *
 * Texture functions (graph "fn" names):
 *
 *   float4 imageTexture(sam2D image, float2 uv, float2 tiling, float2 offset)
 *       tex2D(image, uv * tiling + offset)
 *   float4 imageTextureUV(sam2D image, float2 tiling)
 *       the same at the hit's own texture coordinates, readAttr("TexCoord0"), offset 0
 *   float  imageLuminance(sam2D image, float2 uv, float2 tiling, float2 offset)
 *       Rec. 709 luminance of imageTexture (a mask from an image)
 *
 * Parameters:
 *
 *   | name   | type   | default    | range | meaning                                        |
 *   |--------|--------|------------|-------|------------------------------------------------|
 *   | image  | sam2D  | -          | -     | {"image": name}, the name bound in the graph's "images" |
 *   | uv     | float2 | -          | any   | usually {"attr": "TexCoord0"}                  |
 *   | tiling | float2 | (1, 1)     | != 0  | repetitions per unit of uv                     |
 *   | offset | float2 | (0, 0)     | any   | shift, in image widths/heights                 |
 */

float4 imageTexture(sam2D image, float2 uv, float2 tiling, float2 offset) {
  float2 st = (float2)(uv.x * tiling.x + offset.x, uv.y * tiling.y + offset.y);
  return tex2D(image, st);
}

float4 imageTextureUV(sam2D image, float2 tiling) {
  float2 uv = readAttr("TexCoord0");
  return tex2D(image, (float2)(uv.x * tiling.x, uv.y * tiling.y));
}

float imageLuminance(sam2D image, float2 uv, float2 tiling, float2 offset) {
  float4 c = imageTexture(image, uv, tiling, offset);
  return 0.2126f * c.x + 0.7152f * c.y + 0.0722f * c.z;
}
