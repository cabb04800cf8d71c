#ifndef TEXRENDER_ENVIRONMENT_H
#define TEXRENDER_ENVIRONMENT_H

// The world as an equirectangular environment map (scene.json's "environment" light,
// docs/scene.md): its texels as the shade kernel interpolates them and the piecewise-constant
// density over them with which next-event estimation draws directions (kernels/common/rt_env.h
// reads this layout).

#include "texrender/Scene.h"

#include <string>
#include <vector>

namespace texrender {

struct EnvironmentMap {
  int Width = 0, Height = 0;
  int Flags = 0; // RT_ENV_* of rt_env.h
  /// Width*Height RGBA texels (row 0 the image's bottom row, Cycles' v = 0: xyz the value the
  /// kernel interpolates, w the texel's density in (u, v)), then the Height rows' marginal CDF,
  /// then each row's conditional CDF (Width each).
  std::vector<float> Data;
  /// The luminance of the radiance averaged over the sphere of directions, strength included
  /// (the light's share of next-event estimation).
  double MeanLuminance = 0;
};

/// Reads an environment light's image (Image.h's loadTexture: 8/16-bit PNG, JPEG, float EXR,
/// Radiance .hdr) in its colour space as Cycles reads it (an 8- or 16-bit sRGB image is
/// interpolated encoded and decoded after; a colour image's alpha associated) and builds the
/// density: luminance times sin(theta), each texel's weight spread over the neighbours that
/// bilinear interpolation blends it into. Errors name Where ("scene.json: /lights/0").
EnvironmentMap loadEnvironmentMap(const Light &L, const std::string &Where);

} // namespace texrender

#endif
