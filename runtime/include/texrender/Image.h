#ifndef TEXRENDER_IMAGE_H
#define TEXRENDER_IMAGE_H

// Image files: textures in (8-bit sRGB or HDR to linear RGBA float), renders out (PNG in sRGB
// 8-bit, EXR in linear float), and EXR in (for tests and comparisons).

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace texrender {

class ViewTransform;

struct ImageRGBA {
  int Width = 0, Height = 0;
  std::vector<float> Pixels; // RGBA, row-major, row 0 at the top
  std::string ColorSpace;    // loadTexture: the colour space the file was read in
  int Bits = 0;              // loadTexture: 8 or 16 (integer files), 32 (float files)
};

/// The colour spaces of a texture, as Blender names them: "sRGB" (colour decoded to linear,
/// alpha as is), "Linear Rec.709" (values as stored) and "Non-Color" (values as stored: data,
/// never premultiplied by alpha).
const std::vector<std::string> &textureColorSpaces();
/// Loads a texture (8- or 16-bit PNG, JPEG, BMP, TGA, Radiance .hdr, float .exr) to linear
/// RGBA floats: 8-bit values / 255, 16-bit / 65535, floats as stored, then decoded from sRGB
/// where ColorSpace is "sRGB". An empty ColorSpace is Blender's default for the file: sRGB for
/// 8- and 16-bit files, "Linear Rec.709" for .exr and .hdr. Another name is an Error.
ImageRGBA loadTexture(const std::string &Path, const std::string &ColorSpace = "");
/// Loads an EXR (RGBA float).
ImageRGBA loadExr(const std::string &Path);

/// Writes RGB (3 floats per pixel, linear) as .png (sRGB 8-bit) or .exr (float), chosen by
/// the extension; anything else is an error. Atomic, like every texrender output. A .png goes
/// through View where one is given (Blender's view transform, look, exposure and gamma:
/// ViewTransform.h), else it is the plain sRGB encoding; an .exr stays linear.
void writeImage(const std::string &Path, int Width, int Height, const std::vector<float> &RGB,
                const ViewTransform *View = nullptr);
/// writeImage for a preview rewritten several times a second (texrender --watch): a .png is
/// encoded for speed (no per-row filter search, the fastest deflate level: a larger file); an
/// .exr as writeImage. Batch outputs use writeImage.
void writePreviewImage(const std::string &Path, int Width, int Height, const std::vector<float> &RGB);
/// The view writePreviewImage's .png goes through (texrender --watch sets the one it starts
/// with); null (the default): plain sRGB.
void setPreviewViewTransform(std::shared_ptr<const ViewTransform> View);

/// Runs Write on a temporary name next to Path (a hidden file in the same folder) and renames
/// it to Path only when Write has succeeded, so that a crash, a kill or an error never leaves a
/// half-written Path: the reader sees the old file or the complete new one. On an error the
/// temporary is removed and the error is rethrown.
void writeAtomically(const std::string &Path, const std::function<void(const std::string &)> &Write);
/// writeAtomically for a text file (stats.json).
void writeTextFile(const std::string &Path, const std::string &Text);
/// Outputs that appear together (texrender's image, --variance and --stats): each add writes
/// its file to a temporary beside it at once (an error there removes every temporary of the
/// group and no output changes: a failing --stats no longer leaves a new image beside the
/// error), and commit() renames them all into place. A group destroyed without commit()
/// removes its temporaries.
class OutputGroup {
public:
  OutputGroup() = default;
  OutputGroup(const OutputGroup &) = delete;
  OutputGroup &operator=(const OutputGroup &) = delete;
  ~OutputGroup();
  void addImage(const std::string &Path, int Width, int Height, const std::vector<float> &RGB,
                const ViewTransform *View = nullptr);
  void addText(const std::string &Path, const std::string &Text);
  /// Write(Temp) makes the file (throwing on an error).
  void add(const std::string &Path, const std::function<void(const std::string &)> &Write);
  void commit();

private:
  std::vector<std::pair<std::string, std::string>> Pending; // output, its temporary
};

/// The whole of a file, byte for byte. Throws Error "PATH: cannot open" + What (e.g.
/// " kernel source") + ": " + the reason; a FIFO, a device or a folder is refused, never read
/// (texcc/Support/File.h).
std::string readWholeFile(const std::string &Path, const std::string &What = "");
/// graph.json, whole: readWholeFile, refusing a graph larger than texcc reads
/// (texcc::MaxGraphBytes) before reading it.
std::string readGraphFile(const std::string &Path);

float srgbToLinear(float V);
float linearToSrgb(float V);

} // namespace texrender

#endif
