#include "texrender/SceneData.h"
#include "texrender/Error.h"
#include "texcc/OutOfMemory.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace texrender {

namespace {

cl_float4 f4(float X, float Y, float Z, float W = 0) {
  cl_float4 V;
  V.s[0] = X, V.s[1] = Y, V.s[2] = Z, V.s[3] = W;
  return V;
}
cl_float4 f4(const Vec3 &V, float W = 0) { return f4(V[0], V[1], V[2], W); }

Vec3 transformPoint(const std::array<float, 16> &M, const Vec3 &P) {
  Vec3 R;
  for (int I = 0; I < 3; ++I)
    R[I] = M[4 * I] * P[0] + M[4 * I + 1] * P[1] + M[4 * I + 2] * P[2] + M[4 * I + 3];
  return R;
}

/// Inverse of the upper-left 3x3 and the full affine inverse (rows of a 3x4 matrix).
bool invertAffine(const std::array<float, 16> &M, double Inv[3][4]) {
  double A[3][3];
  for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J)
      A[I][J] = M[4 * I + J];
  double Det = A[0][0] * (A[1][1] * A[2][2] - A[1][2] * A[2][1]) -
               A[0][1] * (A[1][0] * A[2][2] - A[1][2] * A[2][0]) +
               A[0][2] * (A[1][0] * A[2][1] - A[1][1] * A[2][0]);
  if (std::fabs(Det) < 1e-20)
    return false;
  for (int I = 0; I < 3; ++I)
    for (int J = 0; J < 3; ++J) {
      int I1 = (J + 1) % 3, I2 = (J + 2) % 3, J1 = (I + 1) % 3, J2 = (I + 2) % 3;
      Inv[I][J] = (A[I1][J1] * A[I2][J2] - A[I1][J2] * A[I2][J1]) / Det;
    }
  for (int I = 0; I < 3; ++I)
    Inv[I][3] = -(Inv[I][0] * M[3] + Inv[I][1] * M[7] + Inv[I][2] * M[11]);
  return true;
}

Vec3 normalize(Vec3 V) {
  float L = std::sqrt(V[0] * V[0] + V[1] * V[1] + V[2] * V[2]);
  return L > 0 ? Vec3{V[0] / L, V[1] / L, V[2] / L} : V;
}
/// normalize without float underflow or overflow of the squared length ([1e-30, 0, 0] and
/// [3e38, 3e38, 0] are directions too); V is not zero (loadScene checks).
Vec3 normalizeInDouble(const Vec3 &V) {
  double L = std::hypot(double(V[0]), double(V[1]), double(V[2]));
  return {float(V[0] / L), float(V[1] / L), float(V[2] / L)};
}
Vec3 cross(const Vec3 &A, const Vec3 &B) {
  return {A[1] * B[2] - A[2] * B[1], A[2] * B[0] - A[0] * B[2], A[0] * B[1] - A[1] * B[0]};
}
Vec3 sub(const Vec3 &A, const Vec3 &B) { return {A[0] - B[0], A[1] - B[1], A[2] - B[2]}; }
float luminance(const Vec3 &C) { return 0.2126f * C[0] + 0.7152f * C[1] + 0.0722f * C[2]; }

RtBsdfInput makeInput(const LayoutInput *In, const LayoutMaterial &M, float Default) {
  RtBsdfInput R{};
  R.output = -1;
  R.value = f4(Default, Default, Default, Default);
  if (!In)
    return R;
  if (In->IsOutput) {
    R.output = In->Output;
    R.components = In->Output >= 0 && In->Output < int(M.OutputComponents.size())
                       ? M.OutputComponents[In->Output]
                       : 4;
    return R;
  }
  const auto &C = In->Constant;
  if (C.size() == 1)
    R.value = f4(C[0], C[0], C[0], C[0]);
  else
    R.value = f4(C[0], C.size() > 1 ? C[1] : 0, C.size() > 2 ? C[2] : 0, C.size() > 3 ? C[3] : 1);
  return R;
}

int flattenBsdf(const LayoutBsdf &B, const LayoutMaterial &M, std::vector<RtBsdfNode> &Nodes) {
  int Idx = int(Nodes.size());
  Nodes.push_back({});
  RtBsdfNode N{};
  N.a = N.b = -1;
  for (RtBsdfInput &In : N.in)
    In = makeInput(nullptr, M, 0.0f);
  if (B.Type == "diffuse" || B.Type == "glossy" || B.Type == "mirror" || B.Type == "emission") {
    N.type = B.Type == "diffuse"  ? RT_BSDF_DIFFUSE
             : B.Type == "glossy" ? RT_BSDF_GLOSSY
             : B.Type == "mirror" ? RT_BSDF_MIRROR
                                  : RT_BSDF_EMISSION;
    N.in[RT_IN_COLOR] = makeInput(B.input("color"), M, B.Type == "emission" ? 1.0f : 0.8f);
    N.in[RT_IN_ROUGHNESS] = makeInput(B.input(B.Type == "emission" ? "strength" : "roughness"),
                                      M, B.Type == "emission" ? 1.0f : 0.5f);
    N.in[RT_IN_NORMAL] = makeInput(B.input("normal"), M, 0.0f);
  } else if (B.Type == "principled") {
    // Blender's Principled BSDF defaults for the inputs graph.json leaves out.
    N.type = RT_BSDF_PRINCIPLED;
    N.in[RT_IN_COLOR] = makeInput(B.input("baseColor"), M, 0.8f);
    N.in[RT_IN_ROUGHNESS] = makeInput(B.input("roughness"), M, 0.5f);
    N.in[RT_IN_METALLIC] = makeInput(B.input("metallic"), M, 0.0f);
    N.in[RT_IN_SPECULAR] = makeInput(B.input("specular"), M, 0.5f);
    N.in[RT_IN_EMISSION_COLOR] = makeInput(B.input("emissionColor"), M, 1.0f);
    N.in[RT_IN_EMISSION_STRENGTH] = makeInput(B.input("emissionStrength"), M, 0.0f);
    N.in[RT_IN_NORMAL] = makeInput(B.input("normal"), M, 0.0f);
  } else if (B.Type == "blend") {
    N.type = RT_BSDF_BLEND;
    N.in[RT_IN_COLOR] = makeInput(B.input("mask"), M, 0.5f);
    const LayoutBsdf *A = nullptr, *Bb = nullptr;
    for (auto &C : B.Children)
      (C.first == "a" ? A : Bb) = &C.second;
    if (!A || !Bb)
      throw Error("layout.json: material '" + M.Name + "': a blend needs \"a\" and \"b\"");
    N.a = flattenBsdf(*A, M, Nodes);
    N.b = flattenBsdf(*Bb, M, Nodes);
  } else {
    throw Error("layout.json: material '" + M.Name + "': unknown BSDF type '" + B.Type +
                "' (expected diffuse, glossy, mirror, emission, principled or blend)");
  }
  Nodes[Idx] = N;
  return Idx;
}

struct GatheredMesh {
  std::vector<Vec3> P, N;
  std::vector<Vec2> UV;
  std::vector<Vec4> T; // tangents (world space, w the sign), zero for a mesh without them
  std::vector<int> Mesh;
};

void gatherMeshes(const Scene &S, const Layout &L, SceneData &D, GatheredMesh &G) {
  for (size_t MI = 0; MI < S.Meshes.size(); ++MI) {
    const MeshInstance &Mi = S.Meshes[MI];
    int Mat = L.findMaterial(Mi.Material);
    if (Mat < 0)
      throw Error(S.Path + ": " + Mi.JsonPath + "/material: unknown material '" + Mi.Material +
                  "' (known materials in " + L.Dir + "/layout.json: " + L.materialNames() + ")");
    if (!std::filesystem::exists(Mi.ObjPath))
      throw Error(S.Path + ": " + Mi.JsonPath + "/obj: OBJ file not found: " + Mi.ObjPath);
    TriangleMesh TM = loadObj(Mi.ObjPath);
    double Inv[3][4];
    if (!invertAffine(Mi.Transform, Inv))
      throw Error(S.Path + ": " + Mi.JsonPath + "/transform: the matrix is singular");
    RtMesh M{};
    for (int R = 0; R < 3; ++R)
      M.worldToObject[R] = f4(float(Inv[R][0]), float(Inv[R][1]), float(Inv[R][2]), float(Inv[R][3]));
    M.emission = f4(Mi.Emission);
    M.material = Mat;
    D.Meshes.push_back(M);
    // Room for this mesh: its exact size for the first, doubling after (as push_back would).
    auto Grow = [](auto &V, size_t Add) {
      if (V.capacity() < V.size() + Add)
        V.reserve(std::max(V.size() + Add, 2 * V.capacity()));
    };
    Grow(G.P, TM.Positions.size()), Grow(G.N, TM.Positions.size());
    Grow(G.UV, TM.Positions.size()), Grow(G.Mesh, TM.triangleCount());
    Grow(G.T, TM.Positions.size());
    const bool HasTransform = Mi.Transform != std::array<float, 16>{1, 0, 0, 0, 0, 1, 0, 0,
                                                                     0, 0, 1, 0, 0, 0, 0, 1};
    for (size_t K = 0; K < TM.Positions.size(); ++K) {
      G.P.push_back(transformPoint(Mi.Transform, TM.Positions[K]));
      const Vec3 &W = G.P.back();
      if (!(std::fabs(W[0]) <= MaxWorldCoordinate && std::fabs(W[1]) <= MaxWorldCoordinate &&
            std::fabs(W[2]) <= MaxWorldCoordinate)) {
        // In double, so that the message shows the value an overflow made Inf.
        double D[3];
        for (int I = 0; I < 3; ++I)
          D[I] = double(Mi.Transform[4 * I]) * TM.Positions[K][0] +
                 double(Mi.Transform[4 * I + 1]) * TM.Positions[K][1] +
                 double(Mi.Transform[4 * I + 2]) * TM.Positions[K][2] + Mi.Transform[4 * I + 3];
        char Where[160];
        std::snprintf(Where, sizeof Where, "(%g, %g, %g)", D[0], D[1], D[2]);
        throw Error(S.Path + ": " + Mi.JsonPath + (HasTransform ? "/transform" : "/obj") +
                    ": a vertex of '" + Mi.ObjPath + "' is at " +
                    Where + " in world space, past +-1e18, the largest coordinate texrender "
                    "renders (products of two coordinates must be finite floats)");
      }
      // Normals transform with the inverse transpose.
      const Vec3 &N = TM.Normals[K];
      G.N.push_back(normalize({float(Inv[0][0] * N[0] + Inv[1][0] * N[1] + Inv[2][0] * N[2]),
                               float(Inv[0][1] * N[0] + Inv[1][1] * N[1] + Inv[2][1] * N[2]),
                               float(Inv[0][2] * N[0] + Inv[1][2] * N[1] + Inv[2][2] * N[2])}));
      G.UV.push_back(TM.UVs[K]);
      // A tangent lies in the surface: it turns as the positions' differences do, and keeps
      // its length, as the normals keep theirs (Cycles combines them in object space).
      Vec4 T = TM.Tangents.empty() ? Vec4{0, 0, 0, 0} : TM.Tangents[K];
      const std::array<float, 16> &X = Mi.Transform;
      Vec3 TW = {X[0] * T[0] + X[1] * T[1] + X[2] * T[2], X[4] * T[0] + X[5] * T[1] + X[6] * T[2],
                X[8] * T[0] + X[9] * T[1] + X[10] * T[2]};
      const float From = std::sqrt(T[0] * T[0] + T[1] * T[1] + T[2] * T[2]),
                  To = std::sqrt(TW[0] * TW[0] + TW[1] * TW[1] + TW[2] * TW[2]);
      const float Keep = To > 0 ? From / To : 0.0f;
      G.T.push_back({TW[0] * Keep, TW[1] * Keep, TW[2] * Keep, T[3]});
    }
    for (size_t T = 0; T < TM.triangleCount(); ++T)
      G.Mesh.push_back(int(MI));
  }
}

/// A point, spot or area lamp with Cycles' conversion of watts to radiance (scene/light.cpp
/// of Cycles 5.0: eval_fac = 1 / (pi * area), area = 4 pi r^2 for a point or spot, 4 for one of
/// radius 0; an area lamp's own area): a point or spot of radius r > 0 is a disk facing the lit
/// point of radiance P / (4 pi^2 r^2), one of radius 0 a point of intensity P / (4 pi) W/sr; an
/// area lamp has the radiance P / (pi A) on the side it lights.
RtLight makeLamp(const Light &Li, const std::string &Where) {
  RtLight L{};
  L.tri = (Li.CastShadow ? 0 : RT_LAMP_NO_SHADOW) | (Li.VisibleToCamera ? RT_LAMP_CAMERA : 0);
  L.pos = f4(Li.Position, Li.Type == "area" ? 0.0f : Li.Radius);
  const float Pi = float(M_PI);
  Vec3 P = Li.Power;
  float Scale;
  if (Li.Type == "area") {
    L.type = RT_LIGHT_AREA;
    Vec3 N = normalizeInDouble(Li.Direction);
    Vec3 U = Li.AxisU;
    float Along = U[0] * N[0] + U[1] * N[1] + U[2] * N[2];
    U = {U[0] - Along * N[0], U[1] - Along * N[1], U[2] - Along * N[2]};
    if (!(U[0] != 0 || U[1] != 0 || U[2] != 0)) // no axisU: any axis of the plane
      U = std::fabs(N[0]) < 0.9f ? cross(N, {1, 0, 0}) : cross(N, {0, 1, 0});
    U = normalizeInDouble(U);
    Vec3 V = normalize(cross(N, U));
    float HU = 0.5f * Li.Width, HV = 0.5f * Li.Height;
    L.dir = f4(N);
    L.u = f4(U[0] * HU, U[1] * HU, U[2] * HU);
    L.v = f4(V[0] * HV, V[1] * HV, V[2] * HV);
    bool Ellipse = Li.Shape == "ellipse";
    if (Ellipse)
      L.tri |= RT_LAMP_ELLIPSE;
    L.area = Li.Width * Li.Height * (Ellipse ? Pi / 4.0f : 1.0f);
    Scale = 1.0f / (Pi * L.area);
  } else {
    L.type = Li.Type == "spot" ? RT_LIGHT_SPOT : RT_LIGHT_POINT;
    float R = Li.Radius;
    if (!Li.SoftFalloff && R > 0) // Cycles' is_sphere: the same radiance on a sphere
      L.tri |= RT_LAMP_SPHERE;
    L.area = Pi * R * R;
    Scale = R > 0 ? 1.0f / (4.0f * Pi * Pi * R * R) : 1.0f / (4.0f * Pi);
    if (Li.Type == "spot") {
      float CosHalf = std::cos(0.5f * Li.SpotSizeDegrees * Pi / 180.0f);
      L.dir = f4(normalizeInDouble(Li.Direction), CosHalf);
      // Cycles: smoothstep((cos - cosHalf) / ((1 - cosHalf) * blend)); blend 0: a hard edge.
      float Den = (1.0f - CosHalf) * Li.SpotBlend;
      L.u = f4(0, 0, 0, Den > 0 ? 1.0f / Den : 1e30f);
    }
  }
  L.radiance = f4(P[0] * Scale, P[1] * Scale, P[2] * Scale);
  for (int I = 0; I < 3; ++I)
    if (!std::isfinite(L.radiance.s[I]) || !std::isfinite(Scale))
      throw Error(Where + ": its radiance (power / " +
                  (Li.Type == "area" ? std::string("(pi x area)") : std::string("(4 pi^2 r^2)")) +
                  ") overflows a float: a smaller power or a larger " +
                  (Li.Type == "area" ? "size" : "radius"));
  return L;
}

void buildLights(const Scene &S, SceneData &D) {
  std::vector<float> Weights;
  for (size_t T = 0; T < D.TriAttrs.size(); ++T) {
    const RtMesh &M = D.Meshes[D.TriAttrs[T].mesh];
    Vec3 E{M.emission.s[0], M.emission.s[1], M.emission.s[2]};
    if (!(E[0] > 0 || E[1] > 0 || E[2] > 0))
      continue;
    Vec3 C = cross(sub(D.Positions[3 * T + 1], D.Positions[3 * T]),
                   sub(D.Positions[3 * T + 2], D.Positions[3 * T]));
    float Area = 0.5f * std::sqrt(C[0] * C[0] + C[1] * C[1] + C[2] * C[2]);
    if (Area <= 0)
      continue;
    RtLight L{};
    L.type = RT_LIGHT_TRIANGLE;
    L.tri = int(T);
    L.area = Area;
    L.radiance = M.emission;
    D.TriAttrs[T].light = int(D.Lights.size());
    D.Lights.push_back(L);
    Weights.push_back(Area * std::max(luminance(E), 1e-6f) * float(M_PI));
  }
  float Cross = float(M_PI) * D.SceneRadius * D.SceneRadius;
  // The sky and the sun first (next to each other: shade.cl splits their joint share), then the
  // environment map, then the lamps (shade.cl intersects every path segment with them).
  for (const Light &Li : S.Lights) {
    if (Li.Type != "sky" && Li.Type != "sun")
      continue;
    RtLight L{};
    L.tri = -1;
    L.radiance = f4(Li.Radiance);
    float Lum = std::max(luminance(Li.Radiance), 1e-6f);
    if (Li.Type == "sky") {
      L.type = RT_LIGHT_SKY;
      D.SkyLight = int(D.Lights.size());
      Weights.push_back(Lum * float(M_PI) * Cross);
    } else {
      L.type = RT_LIGHT_SUN;
      float CosMax = std::cos(Li.AngularRadiusDegrees * float(M_PI) / 180.0f);
      L.dir = f4(normalizeInDouble(Li.Direction), CosMax);
      D.SunLight = int(D.Lights.size());
      Weights.push_back(Lum * 2.0f * float(M_PI) * (1.0f - CosMax) * Cross);
    }
    D.Lights.push_back(L);
  }
  for (size_t I = 0; I < S.Lights.size(); ++I)
    if (S.Lights[I].Type == "environment") {
      const Light &Li = S.Lights[I];
      D.Env = loadEnvironmentMap(Li, S.Path + ": /lights/" + std::to_string(I));
      RtLight L{};
      L.type = RT_LIGHT_ENV;
      L.tri = -1;
      L.radiance = f4(Li.Strength, Li.Strength, Li.Strength);
      const std::array<float, 9> &M = Li.Matrix; // rows: world direction -> the map's
      L.dir = f4(M[0], M[1], M[2]), L.pos = f4(M[3], M[4], M[5]), L.u = f4(M[6], M[7], M[8]);
      D.EnvLight = int(D.Lights.size());
      D.Lights.push_back(L);
      Weights.push_back(std::max(float(D.Env.MeanLuminance), 1e-6f) * float(M_PI) * Cross);
    }
  D.LampFirst = int(D.Lights.size());
  for (size_t I = 0; I < S.Lights.size(); ++I) {
    const Light &Li = S.Lights[I];
    if (Li.Type == "sky" || Li.Type == "sun" || Li.Type == "environment")
      continue;
    D.Lights.push_back(makeLamp(Li, S.Path + ": /lights/" + std::to_string(I)));
    // Its power (a spot's: the part inside its cone) chooses it.
    float Share = Li.Type == "spot" ? 0.5f * (1.0f - D.Lights.back().dir.s[3]) : 1.0f;
    Weights.push_back(std::max(luminance(Li.Power) * std::max(Share, 1e-3f), 1e-6f));
  }
  D.NumLamps = int(D.Lights.size()) - D.LampFirst;
  double Total = 0;
  for (float W : Weights)
    Total += W;
  double Acc = 0;
  for (size_t I = 0; I < D.Lights.size(); ++I) {
    D.Lights[I].select = float(Weights[I] / Total);
    Acc += Weights[I];
    D.LightCdf.push_back(I + 1 == D.Lights.size() ? 1.0f : float(Acc / Total));
  }
}

} // namespace

void buildMaterials(const Layout &L, std::vector<RtMaterial> &Materials,
                    std::vector<RtBsdfNode> &Nodes) {
  Materials.assign(L.Materials.size(), RtMaterial{});
  Nodes.clear();
  for (const LayoutMaterial &M : L.Materials) {
    if (M.Index < 0 || M.Index >= int(Materials.size()))
      throw Error(L.Dir + "/layout.json: material '" + M.Name + "' has an out-of-range index");
    RtMaterial &R = Materials[M.Index];
    R.root = flattenBsdf(M.Bsdf, M, Nodes);
    R.numOutputs = int(M.OutputComponents.size());
    R.readsAo = M.ReadsAo && R.numOutputs > 0;
  }
}

static SceneData gatherSceneData(const Scene &S, const Layout &L);

SceneData buildSceneData(const Scene &S, const Layout &L) {
  // Loading an OBJ and building the BVH name their own steps inside this one.
  return texcc::whileAllocating("gathering the scene's triangles",
                                [&] { return gatherSceneData(S, L); });
}

static SceneData gatherSceneData(const Scene &S, const Layout &L) {
  SceneData D;
  GatheredMesh G;
  gatherMeshes(S, L, D, G);
  Vec3 Lo{INFINITY, INFINITY, INFINITY}, Hi{-INFINITY, -INFINITY, -INFINITY};
  for (auto &P : G.P)
    for (int A = 0; A < 3; ++A)
      Lo[A] = std::min(Lo[A], P[A]), Hi[A] = std::max(Hi[A], P[A]);
  Vec3 Ext = sub(Hi, Lo);
  D.SceneRadius = std::max(1e-3f, 0.5f * std::sqrt(Ext[0] * Ext[0] + Ext[1] * Ext[1] + Ext[2] * Ext[2]));
  D.Tree = buildBvh(G.P);
  size_t NT = D.Tree.Order.size();
  D.Tris.resize(NT);
  D.TriAttrs.resize(NT);
  D.Positions.resize(3 * NT);
  for (size_t K = 0; K < NT; ++K) {
    size_t T = D.Tree.Order[K];
    const Vec3 &A = G.P[3 * T], &B = G.P[3 * T + 1], &C = G.P[3 * T + 2];
    D.Positions[3 * K] = A, D.Positions[3 * K + 1] = B, D.Positions[3 * K + 2] = C;
    D.Tris[K] = {f4(A), f4(sub(B, A)), f4(sub(C, A))};
    RtTriAttr &At = D.TriAttrs[K];
    At = RtTriAttr{};
    At.n0 = f4(G.N[3 * T], 1.0f);
    At.n1 = f4(G.N[3 * T + 1]);
    At.n2 = f4(G.N[3 * T + 2]);
    At.uv01 = f4(G.UV[3 * T][0], G.UV[3 * T][1], G.UV[3 * T + 1][0], G.UV[3 * T + 1][1]);
    At.uv2 = f4(G.UV[3 * T + 2][0], G.UV[3 * T + 2][1], 0);
    At.mesh = G.Mesh[T];
    At.light = -1;
    for (int C = 0; C < 3; ++C) {
      const Vec4 &Tc = G.T[3 * T + size_t(C)];
      (C == 0 ? At.t0 : C == 1 ? At.t1 : At.t2) = f4(Tc[0], Tc[1], Tc[2], Tc[3]);
    }
  }
  buildMaterials(L, D.Materials, D.BsdfNodes);
  buildLights(S, D);
  return D;
}

RtCamera makeCamera(const Camera &C, int Width, int Height) {
  Vec3 F = normalize(sub(C.Target, C.Position));
  Vec3 R = normalize(cross(F, C.Up));
  Vec3 U = cross(R, F);
  float T = std::tan(C.FovDegrees * float(M_PI) / 360.0f);
  float Aspect = float(Width) / float(Height);
  bool OnX = C.FovAxis == "x" || (C.FovAxis == "smaller" && Width <= Height);
  float TX = OnX ? T : T * Aspect, TY = OnX ? T / Aspect : T;
  RtCamera Cam;
  Cam.position = f4(C.Position);
  Cam.forward = f4(F);
  Cam.right = f4(R[0] * TX, R[1] * TX, R[2] * TX);
  Cam.up = f4(U[0] * TY, U[1] * TY, U[2] * TY);
  return Cam;
}

} // namespace texrender
