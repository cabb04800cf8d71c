/* blender/color.h: Blender's colour-space conversions (Cycles' util/color.h): RGB to and from
 * HSV and HSL, on unclamped linear RGB. Included by mix.cl and color.cl. */

float3 blRgbToHsv(float3 rgb) {
  float cmax = fmax(rgb.x, fmax(rgb.y, rgb.z));
  float cmin = fmin(rgb.x, fmin(rgb.y, rgb.z));
  float cdelta = cmax - cmin;
  float h = 0.0f, s = cmax != 0.0f ? cdelta / cmax : 0.0f;
  if (s != 0.0f) {
    float3 c = ((float3)(cmax) - rgb) / cdelta;
    if (rgb.x == cmax)
      h = c.z - c.y;
    else if (rgb.y == cmax)
      h = 2.0f + c.x - c.z;
    else
      h = 4.0f + c.y - c.x;
    h /= 6.0f;
    if (h < 0.0f)
      h += 1.0f;
  }
  return (float3)(h, s, cmax);
}

float3 blHsvToRgb(float3 hsv) {
  float h = hsv.x, s = hsv.y, v = hsv.z;
  if (s == 0.0f)
    return (float3)(v);
  if (h == 1.0f)
    h = 0.0f;
  h *= 6.0f;
  float i = floor(h);
  float f = h - i;
  float p = v * (1.0f - s);
  float q = v * (1.0f - s * f);
  float t = v * (1.0f - s * (1.0f - f));
  if (i == 0.0f)
    return (float3)(v, t, p);
  if (i == 1.0f)
    return (float3)(q, v, p);
  if (i == 2.0f)
    return (float3)(p, v, t);
  if (i == 3.0f)
    return (float3)(p, q, v);
  if (i == 4.0f)
    return (float3)(t, p, v);
  return (float3)(v, p, q);
}

float3 blRgbToHsl(float3 rgb) {
  float cmax = fmax(rgb.x, fmax(rgb.y, rgb.z));
  float cmin = fmin(rgb.x, fmin(rgb.y, rgb.z));
  float l = fmin(1.0f, (cmax + cmin) / 2.0f);
  float h = 0.0f, s = 0.0f;
  if (cmax != cmin) {
    float cdelta = cmax - cmin;
    s = l > 0.5f ? cdelta / (2.0f - cmax - cmin) : cdelta / (cmax + cmin);
    if (cmax == rgb.x)
      h = (rgb.y - rgb.z) / cdelta + (rgb.y < rgb.z ? 6.0f : 0.0f);
    else if (cmax == rgb.y)
      h = (rgb.z - rgb.x) / cdelta + 2.0f;
    else
      h = (rgb.x - rgb.y) / cdelta + 4.0f;
  }
  h /= 6.0f;
  return (float3)(h, s, l);
}

float3 blHslToRgb(float3 hsl) {
  float h = hsl.x, s = hsl.y, l = hsl.z;
  float nr = clamp(fabs(h * 6.0f - 3.0f) - 1.0f, 0.0f, 1.0f);
  float ng = clamp(2.0f - fabs(h * 6.0f - 2.0f), 0.0f, 1.0f);
  float nb = clamp(2.0f - fabs(h * 6.0f - 4.0f), 0.0f, 1.0f);
  float chroma = (1.0f - fabs(2.0f * l - 1.0f)) * s;
  return (float3)((nr - 0.5f) * chroma + l, (ng - 0.5f) * chroma + l, (nb - 0.5f) * chroma + l);
}
