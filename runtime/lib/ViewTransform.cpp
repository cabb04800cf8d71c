// Blender's view transforms for 8-bit output (ViewTransform.h).
//
// Blender 5.0 turns a render into display values with OpenColorIO: a scale by 2^Exposure in
// scene linear, the look (in the look's process space), the display/view transform, then an
// exponent 1/Gamma (Blender's create_ocio_display_processor). Its config.ocio is OCIO profile
// 2.4, which Debian 12's OpenColorIO 2.1 refuses to load. So the chains of the views and looks
// texrender reproduces are built here with OCIO 2.1's own transforms, step for step as that
// config defines them (its matrices and allocation ranges below, the colour spaces' names in
// the comments), and the LUT files (.cube, .spi1d, .spimtx) are the user's own, read from the
// config's folder when the transform is made. Standard is sRGB's encoding after exposure and
// gamma and needs neither OCIO nor the config.

#include "texrender/ViewTransform.h"

#include "texrender/Error.h"
#include "texrender/Image.h"

#include <OpenColorIO/OpenColorIO.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <sstream>

namespace OCIO = OCIO_NAMESPACE;

namespace texrender {

namespace {

using Transform = OCIO::TransformRcPtr;

/// A 3x3 matrix (rows) as OCIO's 4x4 MatrixTransform.
Transform matrix(const double (&M)[9], bool Inverse = false) {
  const double M4[16] = {M[0], M[1], M[2], 0, M[3], M[4], M[5], 0, M[6], M[7], M[8], 0, 0, 0, 0, 1};
  auto T = OCIO::MatrixTransform::Create();
  T->setMatrix(M4);
  if (Inverse)
    T->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  return T;
}

Transform file(const char *Name, OCIO::Interpolation Interp, bool Inverse = false) {
  auto T = OCIO::FileTransform::Create();
  T->setSrc(Name);
  T->setInterpolation(Interp);
  if (Inverse)
    T->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  return T;
}

Transform lg2(float Min, float Max, bool Inverse = false) {
  auto T = OCIO::AllocationTransform::Create();
  T->setAllocation(OCIO::ALLOCATION_LG2);
  const float Vars[2] = {Min, Max};
  T->setVars(2, Vars);
  if (Inverse)
    T->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  return T;
}

Transform group(std::initializer_list<Transform> Children, bool Inverse = false) {
  auto G = OCIO::GroupTransform::Create();
  for (const Transform &C : Children)
    G->appendTransform(C);
  if (Inverse)
    G->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  return G;
}

Transform exponent(double V, bool Inverse = false) {
  auto T = OCIO::ExponentTransform::Create();
  const double Value[4] = {V, V, V, 1.0};
  T->setValue(Value);
  if (Inverse)
    T->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  return T;
}

// The config's matrices (rows): CIE XYZ D65 to each linear space ("Linear Rec.709",
// "Linear Rec.2020", "Linear FilmLight E-Gamut"), AgX Log's inset and rotation of the
// primaries, and the luminance weights of its Greyscale look.
constexpr double XyzToRec709[9] = {3.2409699,  -1.5373832, -0.4986108, -0.9692436, 1.8759675,
                                   0.0415551,  0.0556301,  -0.2039770, 1.0569715};
constexpr double XyzToRec2020[9] = {1.7166512,  -0.3556708, -0.2533663, -0.6666844, 1.6164812,
                                    0.0157685,  0.0176399,  -0.0427706, 0.9421031};
constexpr double XyzToEGamut[9] = {1.5250528,  -0.3159135, -0.1226583, -0.5091526, 1.3333274,
                                   0.1382844,  0.0957153,  0.0508974,  0.7879558};
constexpr double AgxInset[9] = {0.856627153315983, 0.0951212405381588, 0.0482516061458583,
                                0.137318972929847, 0.761241990602591,  0.101439036467562,
                                0.11189821299995,  0.0767994186031903, 0.811302368396859};
constexpr double AgxGreyscale[9] = {
    0.2589235355689848, 0.6104985346066525, 0.13057792982436284,
    0.2589235355689848, 0.6104985346066525, 0.13057792982436284,
    0.2589235355689848, 0.6104985346066525, 0.13057792982436284};
// AgX's log2 range (stops below and above 0.18-ish mid grey) and Filmic's.
constexpr float AgxMin = -12.47393f, AgxMax = 12.5260688117f;
constexpr float FilmicMin = -12.473931188f, FilmicMax = 12.526068812f, FilmicLogMax = 4.026068812f;

// The scene reference is CIE XYZ with illuminant E; the config reaches XYZ D65 (its display
// reference) through xyz_E_to_D65.spimtx.
Transform xyzEToD65() { return file("xyz_E_to_D65.spimtx", OCIO::INTERP_LINEAR); }
Transform xyzEToLinear(const double (&M)[9], bool Inverse = false) {
  return group({xyzEToD65(), matrix(M)}, Inverse);
}
/// Display "sRGB" from the display reference (XYZ D65): linear Rec.709, sRGB's piecewise code.
Transform srgbDisplayFromXyzD65(bool Inverse = false) {
  auto Encode = OCIO::ExponentWithLinearTransform::Create();
  const double Gamma[4] = {2.4, 2.4, 2.4, 1.0}, Offset[4] = {0.055, 0.055, 0.055, 0.0};
  Encode->setGamma(Gamma);
  Encode->setOffset(Offset);
  Encode->setDirection(OCIO::TRANSFORM_DIR_INVERSE);
  return group({matrix(XyzToRec709), Encode}, Inverse);
}

/// "AgX Log" from the scene reference ("Luminance Compensation Rec.2020", the inset, log2),
/// and back (its to_scene_reference, which does not undo the compensation).
Transform agxLogFromXyzE() {
  Transform Compensation = group({xyzEToLinear(XyzToEGamut), lg2(AgxMin, AgxMax),
                                  file("luminance_compensation_bt2020.cube", OCIO::INTERP_TETRAHEDRAL),
                                  lg2(AgxMin, AgxMax, true), xyzEToLinear(XyzToEGamut, true),
                                  xyzEToLinear(XyzToRec2020)});
  return group({Compensation, matrix(AgxInset), lg2(AgxMin, AgxMax)});
}
Transform xyzEFromAgxLog() {
  return group({lg2(AgxMin, AgxMax, true), matrix(AgxInset, true), xyzEToLinear(XyzToRec2020, true)});
}
/// "Filmic Log" from the scene reference, and back.
Transform filmicLogFromXyzE() {
  auto Uniform = OCIO::AllocationTransform::Create();
  Uniform->setAllocation(OCIO::ALLOCATION_UNIFORM);
  const float Vars[2] = {0.0f, 0.66f};
  Uniform->setVars(2, Vars);
  return group({xyzEToLinear(XyzToRec709), lg2(FilmicMin, FilmicMax),
                file("filmic_desat_33.cube", OCIO::INTERP_TETRAHEDRAL), Uniform});
}
Transform xyzEFromFilmicLog() {
  return group({lg2(FilmicMin, FilmicLogMax, true), xyzEToLinear(XyzToRec709, true)});
}

/// The views: scene reference (XYZ E) to display sRGB.
Transform agxView() {
  // "AgX Base Rec.1886": E-Gamut, log2, the formation LUT (Rec.1886 code values), then the
  // Rec.1886 display space back to XYZ D65 (exponent 2.4) and on to display sRGB.
  Transform Rec1886ToXyzD65 = group({matrix(XyzToRec709), exponent(2.4, true)}, true);
  return group({xyzEToLinear(XyzToEGamut), lg2(AgxMin, AgxMax),
                file("AgX_Base_sRGB.cube", OCIO::INTERP_TETRAHEDRAL), Rec1886ToXyzD65,
                srgbDisplayFromXyzD65()});
}
Transform filmicView() {
  // "Filmic sRGB": Filmic Log, the base contrast curve (display sRGB code values), and to
  // XYZ D65 from display sRGB and back.
  return group({filmicLogFromXyzE(), file("filmic_to_0-70_1-03.spi1d", OCIO::INTERP_LINEAR),
                srgbDisplayFromXyzD65(true), srgbDisplayFromXyzD65()});
}

Transform gradingPrimary(double Contrast, double Saturation) {
  OCIO::GradingPrimary V(OCIO::GRADING_LOG);
  V.m_contrast = OCIO::GradingRGBM(Contrast, Contrast, Contrast, 1.0);
  V.m_saturation = Saturation;
  V.m_pivot = -0.2;
  auto T = OCIO::GradingPrimaryTransform::Create(OCIO::GRADING_LOG);
  T->setValue(V);
  return T;
}

Transform agxPunchy() {
  auto Tone = OCIO::GradingToneTransform::Create(OCIO::GRADING_LOG);
  OCIO::GradingTone V = Tone->getValue();
  V.m_shadows = OCIO::GradingRGBMSW(0.2, 0.2, 0.2, 0.35, 0.4, 0.1); // start 0.4, pivot 0.1
  Tone->setValue(V);
  auto Power = OCIO::CDLTransform::Create();
  const double P[3] = {1.0912, 1.0912, 1.0912};
  Power->setPower(P);
  return group({Tone, Power});
}

Transform filmicContrast(const char *Curve) {
  return group({file(Curve, OCIO::INTERP_LINEAR),
                file("filmic_to_0-70_1-03.spi1d", OCIO::INTERP_LINEAR, true)});
}

struct LookDef {
  const char *View, *Name;
  Transform (*Make)();
};

// Each look runs in its process space (AgX Log or Filmic Log), between the scene reference
// and the view, as OCIO's LookTransform does.
const LookDef Looks[] = {
    {"AgX", "AgX - Punchy", agxPunchy},
    {"AgX", "AgX - Greyscale",
     [] { return group({lg2(AgxMin, AgxMax, true), matrix(AgxGreyscale), lg2(AgxMin, AgxMax)}); }},
    {"AgX", "AgX - Very High Contrast", [] { return gradingPrimary(1.57, 0.9); }},
    {"AgX", "AgX - High Contrast", [] { return gradingPrimary(1.4, 0.95); }},
    {"AgX", "AgX - Medium High Contrast", [] { return gradingPrimary(1.2, 1.0); }},
    {"AgX", "AgX - Base Contrast", [] { return gradingPrimary(1.0, 1.0); }},
    {"AgX", "AgX - Medium Low Contrast", [] { return gradingPrimary(0.9, 1.05); }},
    {"AgX", "AgX - Low Contrast", [] { return gradingPrimary(0.8, 1.1); }},
    {"AgX", "AgX - Very Low Contrast", [] { return gradingPrimary(0.7, 1.15); }},
    {"Filmic", "Very High Contrast", [] { return filmicContrast("filmic_to_1.20_1-00.spi1d"); }},
    {"Filmic", "High Contrast", [] { return filmicContrast("filmic_to_0.99_1-0075.spi1d"); }},
    {"Filmic", "Medium High Contrast", [] { return filmicContrast("filmic_to_0-85_1-011.spi1d"); }},
    {"Filmic", "Medium Contrast", [] { return group({}); }},
    {"Filmic", "Medium Low Contrast", [] { return filmicContrast("filmic_to_0-60_1-04.spi1d"); }},
    {"Filmic", "Low Contrast", [] { return filmicContrast("filmic_to_0-48_1-09.spi1d"); }},
    {"Filmic", "Very Low Contrast", [] { return filmicContrast("filmic_to_0-35_1-30.spi1d"); }},
};

const LookDef *findLook(const std::string &View, const std::string &Name) {
  for (const LookDef &L : Looks)
    if (View == L.View && Name == L.Name)
      return &L;
  return nullptr;
}

std::string number(float V) {
  std::ostringstream S;
  S << V;
  return S.str();
}

std::string joinQuoted(const std::vector<std::string> &Names) {
  std::string S;
  for (const std::string &N : Names)
    S += (S.empty() ? "'" : ", '") + N + "'";
  return S;
}

} // namespace

const std::vector<std::string> &viewTransformNames() {
  static const std::vector<std::string> Names = {"Standard", "AgX", "Filmic"};
  return Names;
}

std::vector<std::string> lookNames(const std::string &Transform) {
  std::vector<std::string> Names = {"None"};
  for (const LookDef &L : Looks)
    if (Transform == L.View)
      Names.push_back(L.Name);
  return Names;
}

struct ViewTransform::Processor {
  OCIO::ConstCPUProcessorRcPtr Cpu;
};

/// The whole chain as Blender builds it: scene linear (Rec.709) scaled by 2^Exposure, to the
/// scene reference, the look (into its process space and back), the view, then 1/Gamma.
static Transform blenderChain(const ViewSettings &S, const LookDef *Look) {
  auto G = OCIO::GroupTransform::Create();
  if (S.Exposure != 0.0f) {
    const double K = std::exp2(double(S.Exposure));
    const double Scale[9] = {K, 0, 0, 0, K, 0, 0, 0, K};
    G->appendTransform(matrix(Scale));
  }
  G->appendTransform(xyzEToLinear(XyzToRec709, true));
  if (Look) {
    const bool Agx = std::string(Look->View) == "AgX";
    G->appendTransform(Agx ? agxLogFromXyzE() : filmicLogFromXyzE());
    G->appendTransform(Look->Make());
    G->appendTransform(Agx ? xyzEFromAgxLog() : xyzEFromFilmicLog());
  }
  G->appendTransform(S.Transform == "AgX" ? agxView() : filmicView());
  if (S.Gamma != 1.0f)
    G->appendTransform(exponent(1.0 / double(S.Gamma)));
  return G;
}

ViewTransform::ViewTransform(const ViewSettings &S) : Settings(S) {
  const auto &Views = viewTransformNames();
  if (std::find(Views.begin(), Views.end(), S.Transform) == Views.end())
    throw Error("view transform '" + S.Transform + "' is not supported; supported: " +
                joinQuoted(Views));
  const std::vector<std::string> ViewLooks = lookNames(S.Transform);
  if (std::find(ViewLooks.begin(), ViewLooks.end(), S.Look) == ViewLooks.end())
    throw Error("look '" + S.Look + "' is not a look of view transform '" + S.Transform +
                "'; its looks: " + joinQuoted(ViewLooks));
  if (!std::isfinite(S.Exposure) || std::fabs(S.Exposure) > 32.0f)
    throw Error("exposure " + number(S.Exposure) + " is out of range (-32 to 32 stops)");
  if (!std::isfinite(S.Gamma) || S.Gamma <= 0.0f)
    throw Error("gamma " + number(S.Gamma) + " is not above 0 (Blender's range: 0.001 to 5)");
  if (S.Transform == "Standard")
    return;
  const std::string Why = "view transform '" + S.Transform + "' reads Blender's LUT files";
  if (S.Config.empty())
    throw Error(Why + ": name Blender's config.ocio with --ocio-config or $OCIO "
                      "(Blender 5.0: 5.0/datafiles/colormanagement/config.ocio)");
  std::error_code EC;
  if (!std::filesystem::is_regular_file(S.Config, EC))
    throw Error(S.Config + ": cannot open OCIO config: " +
                (EC ? EC.message() : std::string("not a regular file")));
  try {
    auto Config = OCIO::Config::CreateRaw()->createEditableCopy();
    Config->setWorkingDir(std::filesystem::path(S.Config).parent_path().string().c_str());
    Config->setSearchPath("luts:filmic"); // Blender's config's search_path
    OCIO::ConstProcessorRcPtr P = Config->getProcessor(blenderChain(S, findLook(S.Transform, S.Look)));
    Ocio = std::make_unique<Processor>();
    Ocio->Cpu = P->getDefaultCPUProcessor();
  } catch (const OCIO::Exception &E) {
    throw Error(S.Config + ": " + Why + ": " + E.what());
  }
}

ViewTransform::~ViewTransform() = default;

void ViewTransform::apply(std::vector<float> &RGB) const {
  if (Ocio) {
    const long Pixels = long(RGB.size() / 3);
    OCIO::PackedImageDesc Desc(RGB.data(), Pixels, 1, 3);
    Ocio->Cpu->apply(Desc);
    return;
  }
  const float Scale = std::exp2(Settings.Exposure), Exponent = 1.0f / Settings.Gamma;
  for (float &V : RGB) {
    V = linearToSrgb(V * Scale);
    if (Exponent != 1.0f)
      V = std::pow(V, Exponent);
  }
}

unsigned char ViewTransform::toByte(float V) {
  if (!(V > 0.0f))
    return 0;
  if (V > 1.0f - 0.5f / 255.0f)
    return 255;
  return static_cast<unsigned char>(255.0f * V + 0.5f);
}

} // namespace texrender
