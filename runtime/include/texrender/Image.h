#ifndef TEXRENDER_IMAGE_H
#define TEXRENDER_IMAGE_H

// Image files: textures in (8-bit sRGB or HDR to linear RGBA float), renders out (PNG in sRGB
// 8-bit, EXR in linear float), and EXR in (for tests and comparisons).

#include <string>
#include <vector>

namespace texrender {

struct ImageRGBA {
  int Width = 0, Height = 0;
  std::vector<float> Pixels; // RGBA, row-major, row 0 at the top
};

/// Loads a texture: 8-bit images are sRGB-decoded (alpha stays linear); .hdr stays linear.
ImageRGBA loadTexture(const std::string &Path);
/// Loads an EXR (RGBA float).
ImageRGBA loadExr(const std::string &Path);

/// Writes RGB (3 floats per pixel, linear) as .png (sRGB 8-bit) or .exr (float), chosen by
/// the extension; anything else is an error.
void writeImage(const std::string &Path, int Width, int Height, const std::vector<float> &RGB);

float srgbToLinear(float V);
float linearToSrgb(float V);

} // namespace texrender

#endif
