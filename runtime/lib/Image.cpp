#include "texrender/Image.h"
#include "texcc/OutOfMemory.h"
#include "texcc/StaleTemporaries.h"
#include "texcc/Support/AtomicWrite.h"
#include "texcc/Support/File.h"
#include "texrender/Error.h"
#include "texrender/ViewTransform.h"

#include <zlib.h>

#include <cstdlib>

/// stb_image_write's own deflate grows its buffers with an unchecked realloc (an assertion, or
/// a write through the null pointer without one): out of memory while writing a PNG was
/// SIGABRT. zlib's deflate, whose failure is a null result that stbi_write_png_to_mem passes on.
static unsigned char *zlibCompress(unsigned char *Data, int Len, int *OutLen, int Quality) {
  uLongf Size = compressBound(uLong(Len));
  auto *Out = static_cast<unsigned char *>(std::malloc(Size));
  if (!Out)
    return nullptr;
  if (compress2(Out, &Size, Data, uLong(Len), Quality < 0 || Quality > 9 ? Z_DEFAULT_COMPRESSION : Quality) != Z_OK) {
    std::free(Out);
    return nullptr;
  }
  *OutLen = int(Size);
  return Out;
}

#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#define STBIW_ZLIB_COMPRESS zlibCompress
#define STBI_FAILURE_USERMSG
#include <stb_image.h>
#include <stb_image_write.h>
#include <tinyexr.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cerrno>
#include <cfloat>
#include <climits>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include <mutex>
#include <sstream>
#include <unistd.h>

namespace texrender {

float srgbToLinear(float V) {
  return V <= 0.04045f ? V / 12.92f : std::pow((V + 0.055f) / 1.055f, 2.4f);
}

float linearToSrgb(float V) {
  V = std::clamp(V, 0.0f, 1.0f);
  return V <= 0.0031308f ? 12.92f * V : 1.055f * std::pow(V, 1.0f / 2.4f) - 0.055f;
}

namespace {

/// stb_image and tinyexr fopen() the file: a FIFO would block them, and a folder would be
/// "not of any known type".
void checkImageFile(const std::string &Path, const char *What) {
  std::string Why;
  if (!texcc::checkRegularFile(Path, Why))
    throw Error(Path + ": cannot load " + What + ": " + Why);
}

} // namespace

/// stb_image's reason for a failed allocation ("outofmem", or its user message).
static bool stbiOutOfMemory() {
  const std::string Why = stbi_failure_reason() ? stbi_failure_reason() : "";
  return Why == "outofmem" || Why == "Out of memory";
}

static ImageRGBA readTexture(const std::string &Path, const std::string &ColorSpace);
static ImageRGBA readExr(const std::string &Path);

const std::vector<std::string> &textureColorSpaces() {
  static const std::vector<std::string> Names = {"sRGB", "Linear Rec.709", "Non-Color"};
  return Names;
}

ImageRGBA loadTexture(const std::string &Path, const std::string &ColorSpace) {
  const std::string Step = "reading image '" + Path + "'";
  return texcc::whileAllocating(Step.c_str(), [&] { return readTexture(Path, ColorSpace); });
}

ImageRGBA loadExr(const std::string &Path) {
  const std::string Step = "reading image '" + Path + "'";
  return texcc::whileAllocating(Step.c_str(), [&] { return readExr(Path); });
}

static bool hasExrExtension(const std::string &Path) {
  std::string Ext = std::filesystem::path(Path).extension().string();
  for (char &C : Ext)
    C = char(std::tolower(static_cast<unsigned char>(C)));
  return Ext == ".exr";
}

/// stb_image's RGBA result D (nullptr: its failure) as Img's pixels, each divided by Scale
/// (255 or 65535; 1 for floats); D is freed.
template <class T>
static void takeStbPixels(T *D, const std::string &Path, float Scale, ImageRGBA &Img) {
  if (!D && stbiOutOfMemory())
    throw std::bad_alloc(); // named by loadTexture's step
  if (!D)
    throw Error(Path + ": cannot load image: " + stbi_failure_reason());
  const size_t Count = size_t(Img.Width) * Img.Height * 4;
  Img.Pixels.resize(Count);
  for (size_t I = 0; I < Count; ++I)
    Img.Pixels[I] = float(D[I]) / Scale;
  stbi_image_free(D);
}

/// The file's values as stored (8- and 16-bit normalised to 0..1, float as is), RGBA; Float
/// tells whether the file holds floats (EXR, Radiance HDR): Blender's default colour space of
/// those is linear, of the others sRGB.
static ImageRGBA readTexels(const std::string &Path, bool &Float, bool &Bytes) {
  ImageRGBA Img;
  int N = 0;
  Bytes = false;
  Float = hasExrExtension(Path) || stbi_is_hdr(Path.c_str());
  if (hasExrExtension(Path))
    return readExr(Path);
  if (Float) {
    takeStbPixels(stbi_loadf(Path.c_str(), &Img.Width, &Img.Height, &N, 4), Path, 1.0f, Img);
  } else if (stbi_is_16_bit(Path.c_str())) {
    takeStbPixels(stbi_load_16(Path.c_str(), &Img.Width, &Img.Height, &N, 4), Path, 65535.0f,
                  Img);
  } else {
    Bytes = true;
    takeStbPixels(stbi_load(Path.c_str(), &Img.Width, &Img.Height, &N, 4), Path, 255.0f, Img);
  }
  return Img;
}

static ImageRGBA readTexture(const std::string &Path, const std::string &ColorSpace) {
  checkImageFile(Path, "image");
  const auto &Known = textureColorSpaces();
  if (!ColorSpace.empty() && std::find(Known.begin(), Known.end(), ColorSpace) == Known.end())
    throw Error(Path + ": unknown colour space '" + ColorSpace +
                "' (expected 'sRGB', 'Linear Rec.709' or 'Non-Color')");
  bool Float = false, Bytes = false;
  ImageRGBA Img = readTexels(Path, Float, Bytes);
  Img.Bits = Float ? 32 : Bytes ? 8 : 16;
  Img.ColorSpace = !ColorSpace.empty() ? ColorSpace : Float ? "Linear Rec.709" : "sRGB";
  if (Img.ColorSpace != "sRGB")
    return Img;
  // sRGB-encoded colour (alpha stays linear) to linear, as Blender decodes it: negative values
  // are 0. 8-bit files through a table: 256 pow() calls instead of one per texel.
  float Lut[256];
  for (int I = 0; I < 256; ++I)
    Lut[I] = srgbToLinear(I / 255.0f);
  size_t Count = size_t(Img.Width) * Img.Height;
  for (size_t I = 0; I < Count; ++I)
    for (int C = 0; C < 3; ++C) {
      float &V = Img.Pixels[4 * I + C];
      V = Bytes ? Lut[std::lround(V * 255.0f)] : V <= 0.0f ? 0.0f : srgbToLinear(V);
    }
  return Img;
}

static ImageRGBA readExr(const std::string &Path) {
  checkImageFile(Path, "EXR");
  ImageRGBA Img;
  float *D = nullptr;
  const char *Err = nullptr;
  if (LoadEXR(&D, &Img.Width, &Img.Height, Path.c_str(), &Err) != TINYEXR_SUCCESS) {
    std::string Why = Err ? Err : "unknown error";
    if (Err)
      FreeEXRErrorMessage(Err);
    throw Error(Path + ": cannot load EXR: " + Why);
  }
  Img.Pixels.assign(D, D + size_t(Img.Width) * Img.Height * 4);
  std::free(D);
  return Img;
}

void writeAtomically(const std::string &Path,
                     const std::function<void(const std::string &)> &Write) {
  std::filesystem::path Target(Path);
  std::string Why;
  if (!texcc::checkReplaceable(Path, Why)) // before anything is written next to it (/dev/full)
    throw Error(Path + ": cannot write: " + Why);
  texcc::removeStaleTemporaries(Target.parent_path().string(), {Target.filename().string()});
  if (!texcc::writeAtomicallyWith(
          Path, [&](const std::string &Temp, std::string &) { Write(Temp); return true; }, Why))
    throw Error(Path + ": cannot write: " + Why);
}

std::string readWholeFile(const std::string &Path, const std::string &What) {
  std::string Text, Why;
  if (!texcc::readRegularFile(Path, Text, Why))
    throw Error(Path + ": cannot open" + What + ": " + Why);
  return Text;
}

std::string readGraphFile(const std::string &Path) {
  std::string Text, Why;
  if (!texcc::readRegularFile(Path, Text, Why, texcc::MaxGraphBytes))
    throw Error(Path + ": cannot open graph: " + Why);
  return Text;
}

void writeTextFile(const std::string &Path, const std::string &Text) {
  writeAtomically(Path, [&](const std::string &Temp) {
    std::string Why;
    if (!texcc::writeWholeFile(Temp, Text.data(), Text.size(), Why))
      throw Error(Path + ": cannot write: " + Why);
  });
}

/// The EXR file's bytes, as tinyexr's SaveEXR makes them (3 float channels stored B, G, R; ZIP
/// compression, none below 16x16), in memory: SaveEXR's own file writing ignored fclose()'s
/// result, so on a full disk the last buffered block was lost and the file torn with success.
using MallocBytes = std::unique_ptr<unsigned char, void (*)(void *)>;

static MallocBytes encodeExr(const std::string &Path, int Width, int Height,
                             const std::vector<float> &RGB, size_t &Size) {
  const size_t Pixels = size_t(Width) * size_t(Height);
  std::vector<float> Planes[3];
  for (int C = 0; C < 3; ++C) {
    Planes[C].resize(Pixels);
    for (size_t I = 0; I < Pixels; ++I)
      Planes[C][I] = RGB[3 * I + size_t(C)];
  }
  EXRHeader Header;
  InitEXRHeader(&Header);
  Header.compression_type =
      Width < 16 && Height < 16 ? TINYEXR_COMPRESSIONTYPE_NONE : TINYEXR_COMPRESSIONTYPE_ZIP;
  EXRChannelInfo Channels[3] = {};
  int PixelTypes[3], Requested[3];
  const char *Names[3] = {"B", "G", "R"};
  float *ImagePtr[3] = {Planes[2].data(), Planes[1].data(), Planes[0].data()};
  for (int C = 0; C < 3; ++C) {
    std::strncpy(Channels[C].name, Names[C], sizeof Channels[C].name - 1);
    PixelTypes[C] = Requested[C] = TINYEXR_PIXELTYPE_FLOAT;
  }
  Header.num_channels = 3;
  Header.channels = Channels;
  Header.pixel_types = PixelTypes;
  Header.requested_pixel_types = Requested;
  EXRImage Image;
  InitEXRImage(&Image);
  Image.num_channels = 3;
  Image.images = reinterpret_cast<unsigned char **>(ImagePtr);
  Image.width = Width;
  Image.height = Height;
  unsigned char *Mem = nullptr;
  const char *Err = nullptr;
  Size = SaveEXRImageToMemory(&Image, &Header, &Mem, &Err);
  if (Size == 0 || !Mem) {
    std::string Why = Err ? Err : "unknown error";
    if (Err)
      FreeEXRErrorMessage(Err);
    std::free(Mem);
    throw Error(Path + ": cannot write EXR: " + Why);
  }
  return MallocBytes(Mem, std::free);
}

/// Bytes to Temp (writeWholeFile: every write and the close checked); a failure names Path.
static void writeBytes(const std::string &Path, const std::string &Temp, const void *Data,
                       size_t Size) {
  std::string Why;
  if (!texcc::writeWholeFile(Temp, Data, Size, Why))
    throw Error(Path + ": cannot write: " + Why);
}

static void writeExr(const std::string &Path, const std::string &Temp, int Width, int Height,
                     const std::vector<float> &RGB) {
  // tinyexr copies the pixels into float planes (here: encodeExr's three), compresses them into
  // blocks and then mallocs the whole file without checking the result (a write through the
  // null pointer, SIGSEGV, when it fails). So first reserve the worst case, as
  // ClContext::allocate does for PoCL's buffers (reserved and released at once, nothing
  // touched): the planes (16 bytes a pixel), the blocks and the file (each at most the 12 bytes
  // a pixel of the data, and zlib's bound on top).
  const size_t Pixels = size_t(Width) * size_t(Height);
  const size_t Data = 12 * Pixels,
               Worst = 16 * Pixels + 2 * (compressBound(uLong(Data)) + (1u << 20));
  void *Probe = std::malloc(Worst);
  if (!Probe)
    throw std::bad_alloc(); // named by writeImage's step
  std::free(Probe);
  size_t Size = 0;
  const MallocBytes File = encodeExr(Path, Width, Height, RGB, Size);
  writeBytes(Path, Temp, File.get(), Size);
}

static void writePng(const std::string &Path, const std::string &Temp, int Width, int Height,
                     const std::vector<float> &RGB, const ViewTransform *View) {
  // stb_image_write counts the filtered rows in an int.
  if ((size_t(Width) * 3 + 1) * size_t(Height) > size_t(INT_MAX))
    throw Error(Path + ": cannot write PNG: " + std::to_string(Width) + "x" + std::to_string(Height) +
                " is more than the PNG encoder holds (2 GiB of rows; write an .exr)");
  std::vector<unsigned char> Bytes(RGB.size());
  if (View) {
    std::vector<float> Display(RGB);
    View->apply(Display);
    for (size_t I = 0; I < RGB.size(); ++I)
      Bytes[I] = ViewTransform::toByte(Display[I]);
  } else {
    for (size_t I = 0; I < RGB.size(); ++I)
      Bytes[I] = static_cast<unsigned char>(std::lround(linearToSrgb(RGB[I]) * 255.0f));
  }
  // In memory first: stbi_write_png returns 0 both when an allocation fails and when the file
  // cannot be opened, and does not check its fwrite or fclose.
  int Len = 0;
  MallocBytes Png(
      stbi_write_png_to_mem(Bytes.data(), Width * 3, Width, Height, 3, &Len), std::free);
  if (!Png)
    throw std::bad_alloc(); // its only failure: an allocation (named by writeImage's step)
  Bytes = {};
  writeBytes(Path, Temp, Png.get(), size_t(Len));
}

/// The last guard of "no Inf or NaN in an image": NaN becomes 0 and +-Inf +-FLT_MAX (the
/// renderer's sums never hold either; see accumulate.cl).
static std::vector<float> finiteValues(const std::vector<float> &RGB) {
  std::vector<float> Out(RGB);
  for (float &V : Out)
    if (std::isnan(V))
      V = 0.0f;
    else if (std::isinf(V))
      V = V > 0 ? FLT_MAX : -FLT_MAX;
  return Out;
}

/// stb_image_write's PNG settings are globals: a write sets them under this lock.
static std::mutex PngSettingsLock;

static void writeImageWith(const std::string &Path, int Width, int Height,
                           const std::vector<float> &RGB, bool FastPng,
                           OutputGroup *Group = nullptr, const ViewTransform *View = nullptr) {
  std::string Ext = std::filesystem::path(Path).extension().string();
  std::transform(Ext.begin(), Ext.end(), Ext.begin(), ::tolower);
  if (Ext != ".exr" && Ext != ".png")
    throw Error(Path + ": unknown image format '" + Ext + "' (expected .png or .exr)");
  const std::string Step = "writing the image '" + Path + "'";
  texcc::whileAllocating(Step.c_str(), [&] {
    std::vector<float> Finite = finiteValues(RGB);
    auto Write = [&](const std::string &Temp) {
      if (Ext == ".exr")
        return writeExr(Path, Temp, Width, Height, Finite);
      // stb's defaults (each row's best of five filters, deflate level 8), or for a preview
      // no filter and level 1: a 256x256 render of the atrium encodes in 26 M instructions
      // instead of 62 M (callgrind), 19 ms instead of 52 ms, and its file was 23% smaller.
      std::lock_guard<std::mutex> Lock(PngSettingsLock);
      stbi_write_force_png_filter = FastPng ? 0 : -1;
      stbi_write_png_compression_level = FastPng ? 1 : 8;
      writePng(Path, Temp, Width, Height, Finite, View);
    };
    if (Group)
      Group->add(Path, Write);
    else
      writeAtomically(Path, Write);
  });
}

OutputGroup::~OutputGroup() {
  std::error_code Ignored;
  for (const auto &[Path, Temp] : Pending)
    std::filesystem::remove(Temp, Ignored);
}

void OutputGroup::add(const std::string &Path,
                      const std::function<void(const std::string &)> &Write) {
  std::string Why;
  if (!texcc::checkReplaceable(Path, Why))
    throw Error(Path + ": cannot write: " + Why);
  const std::filesystem::path Target(Path);
  texcc::removeStaleTemporaries(Target.parent_path().string(), {Target.filename().string()});
  const std::string Temp = texcc::temporaryPathFor(Path);
  Pending.push_back({Path, Temp}); // removed by the destructor if Write throws
  Write(Temp);
}

void OutputGroup::addImage(const std::string &Path, int Width, int Height,
                           const std::vector<float> &RGB, const ViewTransform *View) {
  writeImageWith(Path, Width, Height, RGB, false, this, View);
}

void OutputGroup::addText(const std::string &Path, const std::string &Text) {
  add(Path, [&](const std::string &Temp) {
    std::string Why;
    if (!texcc::writeWholeFile(Temp, Text.data(), Text.size(), Why))
      throw Error(Path + ": cannot write: " + Why);
  });
}

void OutputGroup::commit() {
  std::error_code EC;
  for (size_t I = 0; I < Pending.size(); ++I) {
    std::filesystem::rename(Pending[I].second, Pending[I].first, EC);
    if (EC) {
      const std::string Path = Pending[I].first;
      Pending.erase(Pending.begin(), Pending.begin() + long(I)); // those in place stay
      throw Error(Path + ": cannot write: " + EC.message());
    }
  }
  Pending.clear();
}

void writeImage(const std::string &Path, int Width, int Height, const std::vector<float> &RGB,
                const ViewTransform *View) {
  writeImageWith(Path, Width, Height, RGB, false, nullptr, View);
}

/// The view of writePreviewImage's .png (setPreviewViewTransform); null: plain sRGB.
static std::mutex PreviewViewLock;
static std::shared_ptr<const ViewTransform> PreviewView;

void setPreviewViewTransform(std::shared_ptr<const ViewTransform> View) {
  std::lock_guard<std::mutex> Lock(PreviewViewLock);
  PreviewView = std::move(View);
}

void writePreviewImage(const std::string &Path, int Width, int Height, const std::vector<float> &RGB) {
  std::shared_ptr<const ViewTransform> View;
  {
    std::lock_guard<std::mutex> Lock(PreviewViewLock);
    View = PreviewView;
  }
  writeImageWith(Path, Width, Height, RGB, true, nullptr, View.get());
}

} // namespace texrender
