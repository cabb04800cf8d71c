#ifndef TEXRENDER_VIEWTRANSFORM_H
#define TEXRENDER_VIEWTRANSFORM_H

// The picture Blender shows: linear scene colour through Blender's Color Management (view
// transform, look, exposure, gamma; display sRGB) to the display values an 8-bit PNG stores
// (docs/cli.md, "texrender view transforms"). Standard is computed here; AgX and Filmic run
// through OpenColorIO with the LUT files of the user's Blender, read when the transform is made.

#include <memory>
#include <string>
#include <vector>

namespace texrender {

/// Blender's Color Management settings (Render Properties > Color Management), by Blender's
/// names: Transform "Standard", "AgX" or "Filmic"; Look "None" or one of the view's looks
/// ("AgX - Punchy", "Medium High Contrast", ...); Exposure in stops; Gamma > 0. Config: the
/// path of Blender's config.ocio (datafiles/colormanagement/config.ocio of Blender 5.0), whose
/// folder holds the LUT files AgX and Filmic read; Standard needs none.
struct ViewSettings {
  std::string Transform = "Standard";
  std::string Look = "None";
  float Exposure = 0.0f, Gamma = 1.0f;
  std::string Config;

  bool isPlainSrgb() const {
    return Transform == "Standard" && Look == "None" && Exposure == 0.0f && Gamma == 1.0f;
  }
};

/// The view transforms texrender reproduces, and the looks of each (besides "None").
const std::vector<std::string> &viewTransformNames();
std::vector<std::string> lookNames(const std::string &Transform);

class ViewTransform {
public:
  /// Checks the settings and, for AgX and Filmic, reads the config's LUT files; throws Error
  /// naming the setting, or the config or LUT file that is missing or unreadable.
  explicit ViewTransform(const ViewSettings &Settings);
  ~ViewTransform();

  const ViewSettings &settings() const { return Settings; }
  /// RGB (3 floats a pixel, linear Rec.709 scene values) to display values (0..1 after
  /// clamping), in place.
  void apply(std::vector<float> &RGB) const;
  /// A display value to its 8-bit code as Blender rounds it (0 at or below 0, 255 from
  /// 1 - 0.5/255 up, else 255 v + 0.5 truncated).
  static unsigned char toByte(float V);

private:
  struct Processor;
  ViewSettings Settings;
  std::unique_ptr<Processor> Ocio; // AgX, Filmic
};

} // namespace texrender

#endif
