#include "texrender/Scene.h"
#include "texrender/Error.h"
#include "texrender/Image.h"
#include "texcc/OutOfMemory.h"
#include "texcc/Support/Numbers.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>
#include <sstream>

namespace fs = std::filesystem;
using nlohmann::json;

namespace texrender {

namespace {

/// Reads typed values out of scene.json, reporting "file: /json/path: reason".
class Reader {
public:
  explicit Reader(std::string File) : File(std::move(File)) {}

  [[noreturn]] void fail(const std::string &Path, const std::string &Why) const {
    throw Error(File + ": " + (Path.empty() ? "/" : Path) + ": " + Why);
  }

  void checkKeys(const json &J, const std::string &Path, std::set<std::string> Allowed) const {
    if (!J.is_object())
      fail(Path, "expected an object");
    for (auto &[K, V] : J.items()) {
      (void)V;
      if (!Allowed.count(K)) {
        std::string List;
        for (auto &A : Allowed)
          List += (List.empty() ? "" : ", ") + A;
        fail(Path + "/" + K, "unknown key '" + K + "' (expected one of: " + List + ")");
      }
    }
  }

  float number(const json &J, const std::string &Path) const {
    if (!J.is_number())
      fail(Path, "expected a number, got " + std::string(J.type_name()));
    // A number that would round to a float infinity is refused (FLT_MAX as printed is not).
    double D = J.get<double>();
    if (!texcc::fitsInFloat(D))
      fail(Path, "number " + J.dump() + " is out of range for a float");
    return static_cast<float>(D);
  }

  int integer(const json &J, const std::string &Path) const {
    if (!J.is_number_integer())
      fail(Path, "expected an integer, got " + J.dump());
    // get<int>() would wrap a larger one silently (4294967297 spp would be 1).
    if (J.is_number_unsigned() ? J.get<uint64_t>() > uint64_t(std::numeric_limits<int>::max())
                               : J.get<int64_t>() < std::numeric_limits<int>::min() ||
                                     J.get<int64_t>() > std::numeric_limits<int>::max())
      fail(Path, "integer " + J.dump() + " is out of range");
    return J.get<int>();
  }

  Vec3 vec3(const json &J, const std::string &Path) const {
    if (!J.is_array() || J.size() != 3)
      fail(Path, "expected an array of 3 numbers, got " + J.dump());
    return {number(J[0], Path + "/0"), number(J[1], Path + "/1"), number(J[2], Path + "/2")};
  }

  /// A radiance (sky, sun, mesh emission): no component is negative (light is never taken
  /// away; a negative emission used to be accepted and rendered as a light sink).
  Vec3 radiance(const json &J, const std::string &Path) const {
    Vec3 V = vec3(J, Path);
    for (int I = 0; I < 3; ++I)
      if (V[I] < 0)
        fail(Path + "/" + std::to_string(I),
             "expected a non-negative radiance, got " + J[I].dump());
    return V;
  }

  /// A lamp's power (watts per channel): no component is negative.
  Vec3 power(const json &J, const std::string &Path) const {
    Vec3 V = vec3(J, Path);
    for (int I = 0; I < 3; ++I)
      if (V[I] < 0)
        fail(Path + "/" + std::to_string(I), "expected a non-negative power, got " + J[I].dump());
    return V;
  }

  bool boolean(const json &J, const std::string &Path) const {
    if (!J.is_boolean())
      fail(Path, "expected true or false, got " + J.dump());
    return J.get<bool>();
  }

  std::string string(const json &J, const std::string &Path) const {
    if (!J.is_string())
      fail(Path, "expected a string, got " + std::string(J.type_name()));
    return J.get<std::string>();
  }

  std::string File;
};

using Mat4 = std::array<float, 16>;

Mat4 identity() { return {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1}; }

Mat4 multiply(const Mat4 &A, const Mat4 &B) {
  Mat4 C{};
  for (int R = 0; R < 4; ++R)
    for (int K = 0; K < 4; ++K)
      for (int Col = 0; Col < 4; ++Col)
        C[R * 4 + Col] += A[R * 4 + K] * B[K * 4 + Col];
  return C;
}

Mat4 parseTransform(const Reader &R, const json &J, const std::string &Path) {
  R.checkKeys(J, Path, {"matrix", "scale", "rotateY", "translate"});
  if (J.contains("matrix")) {
    if (J.size() != 1)
      R.fail(Path, "'matrix' cannot be combined with scale/rotateY/translate");
    const json &M = J["matrix"];
    if (!M.is_array() || M.size() != 4)
      R.fail(Path + "/matrix", "expected 4 rows of 4 numbers");
    Mat4 Out{};
    for (int Row = 0; Row < 4; ++Row) {
      if (!M[Row].is_array() || M[Row].size() != 4)
        R.fail(Path + "/matrix/" + std::to_string(Row), "expected 4 numbers");
      for (int C = 0; C < 4; ++C)
        Out[Row * 4 + C] = R.number(M[Row][C], Path + "/matrix/" + std::to_string(Row));
    }
    return Out;
  }
  Mat4 T = identity();
  if (J.contains("scale")) {
    Vec3 S = R.vec3(J["scale"], Path + "/scale");
    Mat4 M = identity();
    M[0] = S[0], M[5] = S[1], M[10] = S[2];
    T = multiply(M, T);
  }
  if (J.contains("rotateY")) {
    float A = R.number(J["rotateY"], Path + "/rotateY") * float(M_PI) / 180.0f;
    Mat4 M = identity();
    M[0] = std::cos(A), M[2] = std::sin(A), M[8] = -std::sin(A), M[10] = std::cos(A);
    T = multiply(M, T);
  }
  if (J.contains("translate")) {
    Vec3 V = R.vec3(J["translate"], Path + "/translate");
    Mat4 M = identity();
    M[3] = V[0], M[7] = V[1], M[11] = V[2];
    T = multiply(M, T);
  }
  return T;
}

std::string resolve(const fs::path &Dir, const std::string &P) {
  fs::path Q(P);
  return (Q.is_absolute() ? Q : Dir / Q).lexically_normal().string();
}

void parseCamera(const Reader &R, const json &J, Camera &C) {
  R.checkKeys(J, "/camera", {"position", "target", "up", "fov", "fovAxis"});
  if (J.contains("position")) C.Position = R.vec3(J["position"], "/camera/position");
  if (J.contains("target")) C.Target = R.vec3(J["target"], "/camera/target");
  if (J.contains("up")) C.Up = R.vec3(J["up"], "/camera/up");
  if (J.contains("fov")) {
    C.FovDegrees = R.number(J["fov"], "/camera/fov");
    if (C.FovDegrees <= 0 || C.FovDegrees >= 180)
      R.fail("/camera/fov", "expected degrees in (0, 180)");
  }
  if (J.contains("fovAxis")) {
    C.FovAxis = R.string(J["fovAxis"], "/camera/fovAxis");
    if (C.FovAxis != "x" && C.FovAxis != "y" && C.FovAxis != "smaller")
      R.fail("/camera/fovAxis", "unknown axis '" + C.FovAxis + "' (expected x, y or smaller)");
  }
  // Without a view direction, or with up along it, the camera basis is NaN: every pixel
  // would be a non-finite sample.
  Vec3 D{C.Target[0] - C.Position[0], C.Target[1] - C.Position[1], C.Target[2] - C.Position[2]};
  if (D[0] == 0 && D[1] == 0 && D[2] == 0)
    R.fail("/camera/target", "the target is the camera position: no view direction");
  Vec3 X{D[1] * C.Up[2] - D[2] * C.Up[1], D[2] * C.Up[0] - D[0] * C.Up[2],
         D[0] * C.Up[1] - D[1] * C.Up[0]};
  if (X[0] == 0 && X[1] == 0 && X[2] == 0)
    R.fail("/camera/up", "'up' is parallel to the view direction (or zero)");
}

/// film.view: Blender's Color Management of a .png (ViewTransform.h); names as Blender's.
void parseView(const Reader &R, const json &J, ViewSettings &V) {
  R.checkKeys(J, "/film/view", {"transform", "look", "exposure", "gamma"});
  auto Quoted = [](const std::vector<std::string> &Names) {
    std::string S;
    for (const std::string &N : Names)
      S += (S.empty() ? "'" : ", '") + N + "'";
    return S;
  };
  if (J.contains("transform")) V.Transform = R.string(J["transform"], "/film/view/transform");
  const auto &Views = viewTransformNames();
  if (std::find(Views.begin(), Views.end(), V.Transform) == Views.end())
    R.fail("/film/view/transform", "view transform '" + V.Transform + "' is not supported; "
           "supported: " + Quoted(Views));
  if (J.contains("look")) V.Look = R.string(J["look"], "/film/view/look");
  const std::vector<std::string> Looks = lookNames(V.Transform);
  if (std::find(Looks.begin(), Looks.end(), V.Look) == Looks.end())
    R.fail("/film/view/look", "look '" + V.Look + "' is not a look of view transform '" +
           V.Transform + "'; its looks: " + Quoted(Looks));
  if (J.contains("exposure")) V.Exposure = R.number(J["exposure"], "/film/view/exposure");
  if (J.contains("gamma")) V.Gamma = R.number(J["gamma"], "/film/view/gamma");
  if (std::fabs(V.Exposure) > 32.0f)
    R.fail("/film/view/exposure", "expected -32 to 32 stops");
  if (!(V.Gamma > 0.0f))
    R.fail("/film/view/gamma", "expected a number above 0");
}

void parseRender(const Reader &R, const json &J, RenderSettings &S) {
  R.checkKeys(J, "/render", {"spp", "maxDepth", "aoSamples", "aoDistance", "seed"});
  if (J.contains("spp")) S.Spp = R.integer(J["spp"], "/render/spp");
  if (J.contains("maxDepth")) S.MaxDepth = R.integer(J["maxDepth"], "/render/maxDepth");
  if (J.contains("aoSamples")) S.AoSamples = R.integer(J["aoSamples"], "/render/aoSamples");
  if (J.contains("aoDistance")) S.AoDistance = R.number(J["aoDistance"], "/render/aoDistance");
  if (J.contains("seed")) S.Seed = static_cast<unsigned>(R.integer(J["seed"], "/render/seed"));
  if (S.Spp < 1) R.fail("/render/spp", "expected at least 1");
  if (S.MaxDepth < -1) R.fail("/render/maxDepth", "expected -1 (unlimited) or >= 0");
  if (S.AoSamples < 1) R.fail("/render/aoSamples", "expected at least 1");
}

/// A direction that has a normal form (in double, so that no finite non-zero vector underflows
/// to zero): a zero one would make the light's frame NaN.
Vec3 direction(const Reader &R, const json &J, const std::string &Path, const std::string &What) {
  Vec3 D = R.vec3(J, Path);
  if (std::hypot(double(D[0]), double(D[1]), double(D[2])) == 0)
    R.fail(Path, "the " + What + " is zero");
  return D;
}

/// Point, spot and area lamps (Blender's, in Cycles' units; docs/scene.md).
void parseLamp(const Reader &R, const json &J, const std::string &Path, Light &L) {
  std::set<std::string> Keys{"type", "position", "power", "castShadow", "visibleToCamera"};
  if (L.Type == "point" || L.Type == "spot")
    Keys.insert({"radius", "softFalloff"});
  if (L.Type == "spot")
    Keys.insert({"direction", "spotSize", "spotBlend"});
  if (L.Type == "area")
    Keys.insert({"direction", "shape", "size", "axisU"});
  R.checkKeys(J, Path, Keys);
  for (const char *Need : {"position", "power"})
    if (!J.contains(Need))
      R.fail(Path, "a " + L.Type + " lamp needs a \"" + Need + "\"");
  L.Position = R.vec3(J["position"], Path + "/position");
  L.Power = R.power(J["power"], Path + "/power");
  if (J.contains("castShadow"))
    L.CastShadow = R.boolean(J["castShadow"], Path + "/castShadow");
  if (J.contains("softFalloff"))
    L.SoftFalloff = R.boolean(J["softFalloff"], Path + "/softFalloff");
  if (J.contains("visibleToCamera"))
    L.VisibleToCamera = R.boolean(J["visibleToCamera"], Path + "/visibleToCamera");
  if (J.contains("radius")) {
    L.Radius = R.number(J["radius"], Path + "/radius");
    if (!(L.Radius >= 0))
      R.fail(Path + "/radius", "expected a radius >= 0 (0: a point)");
  }
  if (L.Type == "spot" || L.Type == "area") {
    if (!J.contains("direction"))
      R.fail(Path, "a " + L.Type + " lamp needs a \"direction\" (the way it shines)");
    L.Direction = direction(R, J["direction"], Path + "/direction", "direction");
  }
  if (L.Type == "spot") {
    if (J.contains("spotSize"))
      L.SpotSizeDegrees = R.number(J["spotSize"], Path + "/spotSize");
    if (!(L.SpotSizeDegrees > 0 && L.SpotSizeDegrees <= 180))
      R.fail(Path + "/spotSize", "expected the cone's full angle in degrees, in (0, 180]");
    if (J.contains("spotBlend"))
      L.SpotBlend = R.number(J["spotBlend"], Path + "/spotBlend");
    if (!(L.SpotBlend >= 0 && L.SpotBlend <= 1))
      R.fail(Path + "/spotBlend", "expected a blend in [0, 1]");
  }
  if (L.Type == "area") {
    if (J.contains("shape")) {
      L.Shape = R.string(J["shape"], Path + "/shape");
      if (L.Shape != "rectangle" && L.Shape != "ellipse")
        R.fail(Path + "/shape",
               "unknown shape '" + L.Shape + "' (expected rectangle or ellipse)");
    }
    if (J.contains("size")) {
      const json &Z = J["size"];
      if (Z.is_number()) {
        L.Width = L.Height = R.number(Z, Path + "/size");
      } else {
        if (!Z.is_array() || Z.size() != 2)
          R.fail(Path + "/size", "expected a number or [width, height], got " + Z.dump());
        L.Width = R.number(Z[0], Path + "/size/0");
        L.Height = R.number(Z[1], Path + "/size/1");
      }
      if (!(L.Width > 0 && L.Height > 0))
        R.fail(Path + "/size", "expected sizes > 0, got " + Z.dump());
    }
    if (J.contains("axisU")) {
      L.AxisU = direction(R, J["axisU"], Path + "/axisU", "axisU");
      const Vec3 &D = L.Direction, &U = L.AxisU;
      double C[3] = {double(D[1]) * U[2] - double(D[2]) * U[1],
                     double(D[2]) * U[0] - double(D[0]) * U[2],
                     double(D[0]) * U[1] - double(D[1]) * U[0]};
      double Sin = std::hypot(C[0], C[1], C[2]) /
                   (std::hypot(double(D[0]), double(D[1]), double(D[2])) *
                    std::hypot(double(U[0]), double(U[1]), double(U[2])));
      if (!(Sin > 1e-3))
        R.fail(Path + "/axisU", "axisU is parallel to the direction: it must lie in the lamp's "
                                "plane");
    } else {
      L.AxisU = {0, 0, 0}; // any axis of the plane (SceneData picks one)
    }
  }
}

/// The environment map (the world as an equirectangular image; docs/scene.md).
void parseEnvironment(const Reader &R, const json &J, const std::string &Path,
                      const fs::path &Dir, Light &L) {
  R.checkKeys(J, Path, {"type", "image", "strength", "colorSpace", "interpolation", "matrix"});
  if (!J.contains("image"))
    R.fail(Path, "an environment needs an \"image\" (an equirectangular image file)");
  std::string Image = R.string(J["image"], Path + "/image");
  if (Image.empty())
    R.fail(Path + "/image", "expected an image file name, got \"\"");
  L.Image = resolve(Dir, Image);
  if (J.contains("strength")) {
    L.Strength = R.number(J["strength"], Path + "/strength");
    if (!(L.Strength >= 0))
      R.fail(Path + "/strength", "expected a strength >= 0");
  }
  if (J.contains("colorSpace")) {
    L.ColorSpace = R.string(J["colorSpace"], Path + "/colorSpace");
    const auto &Known = textureColorSpaces();
    if (std::find(Known.begin(), Known.end(), L.ColorSpace) == Known.end())
      R.fail(Path + "/colorSpace", "unknown colour space '" + L.ColorSpace +
                                       "' (expected sRGB, Linear Rec.709 or Non-Color)");
  }
  if (J.contains("interpolation")) {
    L.Interpolation = R.string(J["interpolation"], Path + "/interpolation");
    if (L.Interpolation != "linear" && L.Interpolation != "closest")
      R.fail(Path + "/interpolation", "unknown interpolation '" + L.Interpolation +
                                          "' (expected linear or closest)");
  }
  if (J.contains("matrix")) {
    const std::string P = Path + "/matrix";
    const json &M = J["matrix"];
    if (!M.is_array() || M.size() != 3)
      R.fail(P, "expected 3 rows of 3 numbers");
    double A[9];
    for (int Row = 0; Row < 3; ++Row) {
      if (!M[Row].is_array() || M[Row].size() != 3)
        R.fail(P + "/" + std::to_string(Row), "expected 3 numbers");
      for (int C = 0; C < 3; ++C)
        A[Row * 3 + C] = R.number(M[Row][C], P + "/" + std::to_string(Row) + "/" + std::to_string(C));
    }
    // A rotation (or a mirror) times a positive scale: M M^T = s^2 I.
    double S2 = (A[0] * A[0] + A[1] * A[1] + A[2] * A[2] + A[3] * A[3] + A[4] * A[4] +
                 A[5] * A[5] + A[6] * A[6] + A[7] * A[7] + A[8] * A[8]) / 3;
    bool Orthogonal = S2 > 0 && std::isfinite(S2);
    for (int I = 0; I < 3 && Orthogonal; ++I)
      for (int K = 0; K < 3; ++K) {
        double D = A[I * 3] * A[K * 3] + A[I * 3 + 1] * A[K * 3 + 1] + A[I * 3 + 2] * A[K * 3 + 2];
        Orthogonal &= std::fabs(D / S2 - (I == K ? 1.0 : 0.0)) <= 1e-3;
      }
    if (!Orthogonal)
      R.fail(P, "expected a rotation (rows orthogonal and of one length), got " + M.dump());
    for (int I = 0; I < 9; ++I)
      L.Matrix[I] = float(A[I] / std::sqrt(S2));
  }
}

Light parseLight(const Reader &R, const json &J, const std::string &Path, const fs::path &Dir) {
  if (!J.is_object() || !J.contains("type"))
    R.fail(Path, "a light needs a \"type\" (sky, sun, point, spot, area or environment)");
  Light L;
  L.Type = R.string(J["type"], Path + "/type");
  if (L.Type == "point" || L.Type == "spot" || L.Type == "area") {
    parseLamp(R, J, Path, L);
    return L;
  }
  if (L.Type == "environment") {
    parseEnvironment(R, J, Path, Dir, L);
    return L;
  }
  if (L.Type == "sky") {
    R.checkKeys(J, Path, {"type", "radiance"});
  } else if (L.Type == "sun") {
    R.checkKeys(J, Path, {"type", "radiance", "direction", "angularRadius"});
    if (!J.contains("direction"))
      R.fail(Path, "a sun needs a \"direction\"");
    L.Direction = direction(R, J["direction"], Path + "/direction", "sun direction");
    if (J.contains("angularRadius"))
      L.AngularRadiusDegrees = R.number(J["angularRadius"], Path + "/angularRadius");
    if (L.AngularRadiusDegrees <= 0 || L.AngularRadiusDegrees >= 90)
      R.fail(Path + "/angularRadius", "expected degrees in (0, 90)");
  } else {
    R.fail(Path + "/type", "unknown light type '" + L.Type +
                               "' (expected sky, sun, point, spot, area or environment; "
                               "emissive meshes are meshes with \"emission\")");
  }
  if (!J.contains("radiance"))
    R.fail(Path, "a " + L.Type + " needs a \"radiance\"");
  L.Radiance = R.radiance(J["radiance"], Path + "/radiance");
  return L;
}

/// nlohmann's message without its "[json.exception.parse_error.101] " tag.
std::string jsonReason(const json::exception &E) {
  std::string What = E.what();
  size_t Tag = What.find("] ");
  return Tag == std::string::npos ? What : What.substr(Tag + 2);
}

} // namespace

std::string tooManyPixels(long long Width, long long Height) {
  const long long Pixels = Width * Height; // both at most 2^31 - 1: no overflow
  if (Pixels <= std::numeric_limits<int>::max())
    return "";
  return std::to_string(Width) + "x" + std::to_string(Height) + " is " + std::to_string(Pixels) +
         " pixels; texrender renders at most 2147483647 (2^31 - 1: the kernels count pixels in "
         "32-bit integers)";
}

static Scene readScene(const std::string &Path);

Scene loadScene(const std::string &Path) {
  const std::string Step = "reading '" + Path + "'";
  // Unwinding out of a half-parsed scene would allocate (texcc/OutOfMemory.h): out of memory
  // exits here, with the step's line.
  texcc::ExitOnOutOfMemory ExitHere("texrender");
  return texcc::whileAllocating(Step.c_str(), [&] { return readScene(Path); });
}

static Scene readScene(const std::string &Path) {
  std::string Text = readWholeFile(Path, " scene file");
  json J;
  try {
    J = json::parse(Text);
  } catch (const json::parse_error &E) {
    size_t Line = 1, Col = 1;
    for (size_t I = 0; I + 1 < E.byte && I < Text.size(); ++I, ++Col)
      if (Text[I] == '\n')
        ++Line, Col = 0;
    throw Error(Path + ":" + std::to_string(Line) + ":" + std::to_string(Col) +
                ": invalid JSON: " + jsonReason(E));
  } catch (const json::exception &E) {
    // A number too large for a double ("1e400") is out_of_range, not a parse_error.
    throw Error(Path + ": invalid JSON: " + jsonReason(E));
  }
  Reader R(Path);
  R.checkKeys(J, "", {"texrender", "textures", "camera", "film", "render", "lights", "meshes"});
  if (!J.contains("texrender") || !J["texrender"].is_number_integer() || J["texrender"] != 1)
    R.fail("/texrender", "expected \"texrender\": 1 (the scene format version)");
  fs::path Dir = fs::path(Path).parent_path();
  Scene S;
  S.Path = Path;
  if (J.contains("textures"))
    S.TexturesDir = resolve(Dir, R.string(J["textures"], "/textures"));
  if (J.contains("camera"))
    parseCamera(R, J["camera"], S.Cam);
  if (J.contains("film")) {
    R.checkKeys(J["film"], "/film", {"width", "height", "view"});
    if (J["film"].contains("width")) S.Render.Width = R.integer(J["film"]["width"], "/film/width");
    if (J["film"].contains("height")) S.Render.Height = R.integer(J["film"]["height"], "/film/height");
    if (S.Render.Width < 1 || S.Render.Height < 1)
      R.fail("/film", "width and height must be at least 1");
    if (std::string Why = tooManyPixels(S.Render.Width, S.Render.Height); !Why.empty())
      R.fail("/film", Why);
    if (J["film"].contains("view"))
      parseView(R, J["film"]["view"], S.Render.View);
  }
  if (J.contains("render"))
    parseRender(R, J["render"], S.Render);
  if (J.contains("lights")) {
    if (!J["lights"].is_array())
      R.fail("/lights", "expected an array");
    int World = -1; // the sky or environment met first
    for (size_t I = 0; I < J["lights"].size(); ++I) {
      std::string P = "/lights/" + std::to_string(I);
      S.Lights.push_back(parseLight(R, J["lights"][I], P, Dir));
      const std::string &T = S.Lights.back().Type;
      if (T != "sky" && T != "environment")
        continue;
      if (World >= 0 && (T == "environment" || S.Lights[World].Type == "environment"))
        R.fail(P, "a second world light: /lights/" + std::to_string(World) + " is a " +
                      S.Lights[World].Type + " (a scene has one sky or one environment)");
      if (World < 0)
        World = int(I);
    }
  }
  if (!J.contains("meshes") || !J["meshes"].is_array() || J["meshes"].empty())
    R.fail("/meshes", "expected a non-empty array of meshes");
  for (size_t I = 0; I < J["meshes"].size(); ++I) {
    std::string P = "/meshes/" + std::to_string(I);
    const json &M = J["meshes"][I];
    R.checkKeys(M, P, {"obj", "material", "emission", "transform"});
    MeshInstance Mi;
    Mi.JsonPath = P;
    if (!M.contains("obj"))
      R.fail(P, "a mesh needs \"obj\" (an OBJ file)");
    if (!M.contains("material"))
      R.fail(P, "a mesh needs \"material\" (a material name of the texcc output)");
    Mi.ObjPath = resolve(Dir, R.string(M["obj"], P + "/obj"));
    Mi.Material = R.string(M["material"], P + "/material");
    if (M.contains("emission")) {
      Mi.Emission = R.radiance(M["emission"], P + "/emission");
      Mi.Emissive = Mi.Emission[0] > 0 || Mi.Emission[1] > 0 || Mi.Emission[2] > 0;
    }
    Mi.Transform = M.contains("transform") ? parseTransform(R, M["transform"], P + "/transform")
                                           : identity();
    S.Meshes.push_back(Mi);
  }
  return S;
}

} // namespace texrender
