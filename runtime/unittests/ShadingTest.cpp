// Analytic checks of the shading kernel (skipped without an OpenCL device): a large floor seen
// from above under a constant sky and/or a sun straight overhead. The floor's radiance is
//   sky L, diffuse rho:            rho * L               (next-event + BSDF sampling, MIS)
//   sun Ls, cone half-angle t:     rho * Ls * sin^2(t)   (the cone's irradiance is pi Ls sin^2 t)
//   mirror c under sky L:          c * L
//   blend(mask m, a, b):           (1 - m) a + m b
//   emission c * strength:         c * strength (seen directly)
// and a glossy surface of colour c (Blender's Glossy BSDF: no Fresnel) under a white sky, seen
// head-on, reflects c E (1 + c (1 - E) / E) = c (E + c (1 - E)), E the single-scattering GGX
// lobe's directional albedo: 0.9939, 0.9153, 0.4199 for roughness 0.2, 0.5, 0.9 (alpha =
// roughness^2, separable Smith G; from a 2M-sample numerical integration of the same model).
// So a white one reflects 1 at every roughness (the multiscatter scale gives back 1 - E).
#include "texrender/Layout.h"
#include "texrender/Renderer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace texrender;

namespace {

LayoutInput constant(std::vector<float> V) {
  LayoutInput I;
  I.Constant = std::move(V);
  return I;
}

LayoutBsdf leaf(const std::string &Type, float Color, float Param = -1) {
  LayoutBsdf B;
  B.Type = Type;
  B.Inputs.push_back({"color", constant({Color, Color, Color})});
  if (Param >= 0)
    B.Inputs.push_back({Type == "emission" ? "strength" : "roughness", constant({Param})});
  return B;
}

Layout layoutWith(const LayoutBsdf &B) {
  Layout L;
  L.Dir = "(test)";
  L.Mode = "interp";
  L.ArgsBin.assign(16, 0);
  LayoutMaterial M;
  M.Name = "m";
  M.Bsdf = B;
  L.Materials.push_back(M);
  return L;
}

/// Renders the floor with material B under Lights; returns the mean radiance (green).
double floorRadiance(const LayoutBsdf &B, const std::vector<Light> &Lights, int Spp = 64) {
  fs::path Dir = fs::temp_directory_path() / ("texrender-shading-" + std::to_string(::getpid()));
  fs::create_directories(Dir);
  std::ofstream(Dir / "floor.obj") << "v -100 0 -100\nv 100 0 -100\nv 100 0 100\nv -100 0 100\n"
                                      "vn 0 1 0\nf 1//1 4//1 3//1 2//1\n";
  Scene S;
  S.Path = (Dir / "scene.json").string();
  S.Cam.Position = {0, 1, 0};
  S.Cam.Target = {0, 0, 0};
  S.Cam.Up = {0, 0, -1};
  S.Cam.FovDegrees = 30;
  S.Render.Width = S.Render.Height = 16;
  S.Render.Spp = Spp;
  S.Render.MaxDepth = 8;
  S.Lights = Lights;
  MeshInstance M;
  M.ObjPath = (Dir / "floor.obj").string();
  M.Material = "m";
  M.Transform = {1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1, 0, 0, 0, 0, 1};
  M.JsonPath = "/meshes/0";
  S.Meshes.push_back(M);
  RendererOptions O;
  O.CacheDir = (fs::temp_directory_path() / "texrender-test-cache").string();
  if (!std::getenv("TEXRENDER_KERNELS"))
    O.KernelDir = TEXRENDER_KERNEL_DIR;
  Renderer R(S, layoutWith(B), O);
  FrameStats Stats;
  std::vector<float> Img = R.render(Stats);
  double Sum = 0;
  for (size_t P = 0; P < Img.size() / 3; ++P)
    Sum += Img[3 * P + 1];
  return Sum / (Img.size() / 3);
}

Light sky(float L) {
  Light S;
  S.Type = "sky";
  S.Radiance = {L, L, L};
  return S;
}

Light sunOverhead(float L, float AngleDeg) {
  Light S;
  S.Type = "sun";
  S.Radiance = {L, L, L};
  S.Direction = {0, 1, 0};
  S.AngularRadiusDegrees = AngleDeg;
  return S;
}

bool haveDevice() { return !listDevices().empty(); }

} // namespace

TEST(Shading, DiffuseUnderSky) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  EXPECT_NEAR(floorRadiance(leaf("diffuse", 0.5f), {sky(1.0f)}), 0.5, 0.01);
}

TEST(Shading, DiffuseUnderSun) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  double S2 = std::pow(std::sin(5.0 * M_PI / 180.0), 2);
  EXPECT_NEAR(floorRadiance(leaf("diffuse", 0.5f), {sunOverhead(100.0f, 5.0f)}), 0.5 * 100 * S2,
              0.01 * 0.5 * 100 * S2);
}

TEST(Shading, SkyAndSunAdd) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  double S2 = std::pow(std::sin(2.0 * M_PI / 180.0), 2);
  double Expected = 0.5 * (0.3 + 500 * S2);
  EXPECT_NEAR(floorRadiance(leaf("diffuse", 0.5f), {sky(0.3f), sunOverhead(500.0f, 2.0f)}, 128),
              Expected, 0.015 * Expected);
}

TEST(Shading, MirrorUnderSky) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  EXPECT_NEAR(floorRadiance(leaf("mirror", 0.8f), {sky(1.0f)}, 4), 0.8, 1e-3);
}

TEST(Shading, BlendByMask) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  LayoutBsdf B;
  B.Type = "blend";
  B.Inputs.push_back({"mask", constant({0.25f})});
  B.Children.push_back({"a", leaf("diffuse", 0.2f)});
  B.Children.push_back({"b", leaf("diffuse", 1.0f)});
  EXPECT_NEAR(floorRadiance(B, {sky(1.0f)}), 0.75 * 0.2 + 0.25 * 1.0, 0.01);
}

TEST(Shading, EmissionSeenDirectly) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  EXPECT_NEAR(floorRadiance(leaf("emission", 2.0f, 1.5f), {}, 1), 3.0, 1e-4);
}

TEST(Shading, GlossyAlbedo) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  // Cycles 5.0's GGX with a constant-colour Fresnel C under a white sky, seen from above:
  // single scattering C E (E the directional albedo at normal incidence) plus the multiple
  // scattering its albedo scaling adds back, C F_ms (1 - E), with F_ms = C Eavg / (1 - C (1 -
  // Eavg)) (Eavg the cosine-weighted average of E; both from rt_ggx_albedo.h's tables).
  const struct { float Roughness; double E, Eavg; } Cases[] = {
      {0.2f, 0.9980, 0.9920}, {0.5f, 0.9153, 0.8814}, {0.9f, 0.4200, 0.5024}};
  for (auto [Roughness, E, Eavg] : Cases)
    for (double C : {1.0, 0.5}) {
      const double Fms = C * Eavg / (1.0 - C * (1.0 - Eavg));
      const double Albedo = C * (E + Fms * (1.0 - E));
      EXPECT_NEAR(floorRadiance(leaf("glossy", float(C), Roughness), {sky(1.0f)}, 128), Albedo,
                  0.02 * Albedo)
          << "roughness " << Roughness << ", colour " << C;
    }
}
