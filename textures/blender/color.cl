/* blender/color.cl: Blender's colour nodes (Cycles, Blender 5.0): Invert Color, Gamma,
 * Brightness/Contrast, Hue/Saturation/Value, RGB to BW, Separate Color and Combine Color.
 *
 *   float3 blInvertColor(float fac, float3 color)
 *   float3 blGamma(float3 color, float gamma)
 *   float3 blBrightContrast(float3 color, float bright, float contrast)
 *   float3 blHueSaturationValue(float hue, float saturation, float value, float fac, float3 color)
 *   float  blRgbToBw(float3 color)                 luminance, Rec.709 / sRGB primaries
 *   float  blSeparateColorR(float3 color, int mode) first output: Red, Hue (HSV, HSL)
 *   float  blSeparateColorG(float3 color, int mode) second: Green, Saturation
 *   float  blSeparateColorB(float3 color, int mode) third: Blue, Value (HSV), Lightness (HSL)
 *   float3 blCombineColor(float r, float g, float b, int mode)
 *
 * Parameters (Blender's defaults):
 *
 *   | name       | type   | default | meaning                                                |
 *   |------------|--------|---------|--------------------------------------------------------|
 *   | fac        | float  | 1.0     | 0 keeps the input colour, 1 applies the node fully     |
 *   | color      | float3 | 0.8 gray | the input colour (linear RGB)                         |
 *   | gamma      | float  | 1.0     | exponent of each positive channel; 0 gives white        |
 *   | bright, contrast | float | 0.0 | Brightness/Contrast; the result is clamped at 0       |
 *   | hue        | float  | 0.5     | 0.5 keeps the hue; the shift wraps                     |
 *   | saturation, value | float | 1.0 | factors                                            |
 *   | mode       | int    | 0       | 0 RGB, 1 HSV, 2 HSL                                    |
 *   | r, g, b    | float  | 0.0     | Combine Color's inputs, in mode's space                |
 */

#include "color.h"

float3 blInvertColor(float fac, float3 color) {
  return fac * ((float3)(1.0f) - color) + (1.0f - fac) * color;
}

float blGammaChannel(float c, float gamma) { return c > 0.0f ? pow(c, gamma) : c; }

float3 blGamma(float3 color, float gamma) {
  if (gamma == 0.0f)
    return (float3)(1.0f);
  return (float3)(blGammaChannel(color.x, gamma), blGammaChannel(color.y, gamma),
                  blGammaChannel(color.z, gamma));
}

float3 blBrightContrast(float3 color, float bright, float contrast) {
  float a = 1.0f + contrast;
  float b = bright - contrast * 0.5f;
  return fmax(a * color + b, (float3)(0.0f));
}

float3 blHueSaturationValue(float hue, float saturation, float value, float fac, float3 color) {
  float3 hsv = blRgbToHsv(color);
  float h = hsv.x + hue + 0.5f;
  hsv.x = h - floor(h);
  hsv.y = clamp(hsv.y * saturation, 0.0f, 1.0f);
  hsv.z *= value;
  float3 rgb = blHsvToRgb(hsv);
  rgb = fac * rgb + (1.0f - fac) * color;
  return fmax(rgb, (float3)(0.0f));
}

float blRgbToBw(float3 color) {
  /* The Y row of linear Rec.709 (sRGB primaries, D65) to XYZ, as Cycles derives it from the
   * default colour management. */
  return 0.2126390059f * color.x + 0.7151686788f * color.y + 0.0721923154f * color.z;
}

float3 blSeparateColor(float3 color, int mode) {
  if (mode == 1)
    return blRgbToHsv(color);
  if (mode == 2)
    return blRgbToHsl(color);
  return color;
}

float blSeparateColorR(float3 color, int mode) { return blSeparateColor(color, mode).x; }

float blSeparateColorG(float3 color, int mode) { return blSeparateColor(color, mode).y; }

float blSeparateColorB(float3 color, int mode) { return blSeparateColor(color, mode).z; }

float3 blCombineColor(float r, float g, float b, int mode) {
  float3 c = (float3)(r, g, b);
  if (mode == 1)
    return blHsvToRgb(c);
  if (mode == 2)
    return blHslToRgb(c);
  return c;
}
