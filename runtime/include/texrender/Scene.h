#ifndef TEXRENDER_SCENE_H
#define TEXRENDER_SCENE_H

// scene.json (docs/scene.md) and its OBJ meshes, loaded into plain host data. Errors name the
// file, the JSON path and the reason.

#include "texrender/ViewTransform.h"
#include <array>
#include <string>
#include <vector>

namespace texrender {

using Vec3 = std::array<float, 3>;
using Vec2 = std::array<float, 2>;
using Vec4 = std::array<float, 4>;

/// A triangle mesh as loaded from OBJ: three corners per triangle.
struct TriangleMesh {
  std::vector<Vec3> Positions; // 3 per triangle
  std::vector<Vec3> Normals;   // 3 per triangle, empty when the file had none
  std::vector<Vec2> UVs;       // 3 per triangle, zeros when the file had none
  // 3 per triangle when the file gives tangents (vtan, docs/scene.md "Tangents"): xyz the
  // UV tangent, w the bitangent sign (1 or -1); w = 0 for a triangle without them. Empty when
  // the file gives none.
  std::vector<Vec4> Tangents;
  size_t triangleCount() const { return Positions.size() / 3; }
};

/// Loads an OBJ (or gzip-compressed .obj.gz): triangulated; normals are kept when every
/// face has them and otherwise generated (area-weighted, per vertex position).
TriangleMesh loadObj(const std::string &Path);

/// One corner of an OBJ face: zero-based position, texture coordinate and normal indices as the
/// file gives them (-1: none; not yet checked against the arrays).
struct ObjCorner {
  int V = -1, T = -1, N = -1;
};

/// An OBJ file's text as read (for loadObj and the tests): the v, vn and vt arrays (3, 3 and 2
/// floats each) and the faces as triangles, three corners each, in file order (quads split along
/// the shorter diagonal, larger polygons fanned from their first corner, faces of fewer than
/// three corners skipped). Throws Error naming Path and the line for a number that is not a
/// finite float or a face corner that is not one.
struct ObjText {
  std::vector<float> Positions, Normals, TexCoords;
  std::vector<float> Tangents; // vtan: 4 floats each, one per vn (checked by parseObj)
  std::vector<ObjCorner> Corners;
};
ObjText parseObj(const std::string &Path, const std::string &Text);

struct Camera {
  Vec3 Position{0, 0, 1};
  Vec3 Target{0, 0, 0};
  Vec3 Up{0, 1, 0};
  float FovDegrees = 40.0f;
  std::string FovAxis = "smaller"; // x | y | smaller
};

struct Light {
  std::string Type; // sky | sun | point | spot | area | environment
  Vec3 Radiance{0, 0, 0};  // sky, sun
  Vec3 Direction{0, 1, 0}; // sun: towards it; spot: the way it shines; area: the side it lights
  float AngularRadiusDegrees = 0.27f;
  // Lamps (point, spot, area), in Cycles' units (docs/scene.md).
  Vec3 Position{0, 0, 0};
  Vec3 Power{0, 0, 0}; // watts: Blender's Color x Power
  float Radius = 0;    // point, spot
  float SpotSizeDegrees = 45, SpotBlend = 0.15f;
  std::string Shape = "rectangle"; // area: rectangle | ellipse
  float Width = 1, Height = 1;     // area
  Vec3 AxisU{1, 0, 0};             // area: the direction of its width
  bool CastShadow = true;
  bool SoftFalloff = true;       // point, spot: false makes a radius > 0 a sphere
  bool VisibleToCamera = false; // Blender 5.0's default for a light object
  // Environment (an equirectangular map; docs/scene.md).
  std::string Image;                // resolved path
  std::string ColorSpace;           // "": the file's default (sRGB, or linear for float files)
  std::string Interpolation = "linear"; // linear | closest
  float Strength = 1;
  /// World directions to the map's (row-major, orthonormal: scene.json's rows, normalized).
  std::array<float, 9> Matrix{1, 0, 0, 0, 1, 0, 0, 0, 1};
};

struct MeshInstance {
  std::string ObjPath;  // resolved
  std::string Material;
  Vec3 Emission{0, 0, 0};
  bool Emissive = false;
  std::array<float, 16> Transform; // row-major object-to-world
  std::string JsonPath;            // "/meshes/2" (for messages)
};

struct RenderSettings {
  int Width = 256, Height = 256;
  int Spp = 16;
  int MaxDepth = 8;
  int AoSamples = 8;
  float AoDistance = 0.5f;
  unsigned Seed = 1;
  /// texrender --region: the part of the film to render (RegionWidth 0: the whole film). Its
  /// pixels keep their full-film coordinates and random streams (kernels/raygen.cl).
  int RegionX = 0, RegionY = 0, RegionWidth = 0, RegionHeight = 0;
  /// A lane of a frame (Lanes.h): the region's RegionHeight rows are film rows RegionY,
  /// RegionY + RegionRowStep, ... (1: consecutive rows, as --region gives).
  int RegionRowStep = 1;
  /// film.view: a .png's Color Management (Config empty: texrender's --ocio-config or $OCIO).
  ViewSettings View;
  int Frame = 0;  // readSetting("Frame") (texrender --frame)
  float Time = 0; // readSetting("Time"), seconds (texrender: Frame / --fps)
};

struct Scene {
  std::string Path;         // scene.json
  std::string TexturesDir;  // resolved texcc output folder ("" when none given)
  Camera Cam;
  RenderSettings Render;
  std::vector<Light> Lights;
  std::vector<MeshInstance> Meshes;
};

/// Why a Width x Height film cannot be rendered ("" when it can): the kernels number pixels and
/// paths with 32-bit ints, so at most 2^31 - 1 pixels (a 2147483647x2147483647 film asked for
/// 18446743730112168016 bytes of paths: the count had wrapped).
std::string tooManyPixels(long long Width, long long Height);

/// The largest coordinate a vertex may have in world space (after its mesh's transform):
/// rendering multiplies two coordinates (edges' cross products, the scene radius squared), which
/// must stay finite floats. A mesh scaled by 1e38 used to vanish silently.
constexpr double MaxWorldCoordinate = 1e18;

/// Parses scene.json; paths in it become relative to its folder. Does not load the OBJs.
Scene loadScene(const std::string &Path);

} // namespace texrender

#endif
