#ifndef TEXRENDER_SCENEDATA_H
#define TEXRENDER_SCENEDATA_H

// The scene in the device's format: triangles in BVH order with their shading data, meshes,
// the flattened BSDF trees of the layout's materials, the light table and its CDF, the camera.
// Built on the host from scene.json, the OBJs and layout.json.

#include "texrender/Bvh.h"
#include "texrender/Environment.h"
#include "texrender/Layout.h"
#include "texrender/Scene.h"

#include <vector>

extern "C" {
#include "rt_types.h"
}

namespace texrender {

struct SceneData {
  Bvh Tree;
  std::vector<RtTri> Tris;
  std::vector<RtTriAttr> TriAttrs;
  std::vector<Vec3> Positions; // world space, BVH order, 3 per triangle (host traversal)
  std::vector<RtMesh> Meshes;
  std::vector<RtMaterial> Materials;
  std::vector<RtBsdfNode> BsdfNodes;
  std::vector<RtLight> Lights;
  std::vector<float> LightCdf;
  int SkyLight = -1, SunLight = -1;
  int LampFirst = 0, NumLamps = 0; // point, spot and area lamps: Lights[LampFirst, +NumLamps)
  int EnvLight = -1;  // the environment map's index in Lights, or -1
  EnvironmentMap Env; // its texels and density (the shade kernel's envMap buffer)
  float SceneRadius = 1.0f;
};

/// Loads every OBJ, applies the transforms, resolves materials by name (an unknown one is an
/// error naming it and listing the known ones), builds the BVH and the light table.
SceneData buildSceneData(const Scene &S, const Layout &L);

/// The flattened BSDF trees of the layout's materials (also rebuilt after a live edit).
void buildMaterials(const Layout &L, std::vector<RtMaterial> &Materials,
                    std::vector<RtBsdfNode> &Nodes);

/// The pinhole camera for a Width x Height film (fov on the axis scene.json names).
RtCamera makeCamera(const Camera &C, int Width, int Height);

} // namespace texrender

#endif
