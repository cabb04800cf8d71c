/* blender/image.cl: Blender's Image Texture node (Cycles, Blender 5.0), Flat projection.
 *
 *   float3 blImageColor(sam2D image, float3 vector, int interpolation, int extension,
 *                       int alphaLinked)
 *   float  blImageAlpha(sam2D image, float3 vector, int interpolation, int extension)
 *
 * The lookup is the embedded API's tex2DFiltered (docs/frontend.md), which reads the image as
 * Cycles does: at (vector.x, vector.y), (0, 0) the bottom-left corner of the image (Blender's
 * images start at the bottom row; tex2DFiltered's v = 0 is the top row, hence 1 - y); an sRGB
 * image interpolated in sRGB and decoded after; a colour image's alpha associated while
 * interpolating. Color is then the associated colour, as Cycles gives it when the node's Alpha
 * output is not used, or, with alphaLinked = 1 (Cycles: the Alpha output is linked), divided
 * by the interpolated alpha. Non-Color images are never associated.
 *
 * Parameters (Blender's defaults):
 *
 *   | name          | type   | default | meaning                                          |
 *   |---------------|--------|---------|--------------------------------------------------|
 *   | image         | sam2D  | -       | {"image": name}; its colour space is the binding's (graph.md "Images") |
 *   | vector        | float3 | -       | lookup point; x, y in image widths/heights (Blender: UV; unlinked, Generated) |
 *   | interpolation | int    | 0       | 0 Linear, 1 Closest, 2 Cubic (Cycles' cubic B-spline) |
 *   | extension     | int    | 0       | 0 Repeat, 1 Extend, 2 Clip (transparent black outside), 3 Mirror |
 *   | alphaLinked   | int    | 0       | 1: Color unassociated (divided by Alpha), as when Alpha is used |
 */

float3 blImageColor(sam2D image, float3 vector, int interpolation, int extension,
                    int alphaLinked) {
  float4 c = tex2DFiltered(image, (float2)(vector.x, 1.0f - vector.y), interpolation, extension,
                           alphaLinked);
  return c.xyz;
}

float blImageAlpha(sam2D image, float3 vector, int interpolation, int extension) {
  return tex2DFiltered(image, (float2)(vector.x, 1.0f - vector.y), interpolation, extension, 0).w;
}
