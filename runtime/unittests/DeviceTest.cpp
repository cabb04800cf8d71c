// Device tests (skipped without an OpenCL device): the OpenCL BVH traversal against host brute
// force, and the AO kernels (one launch of hits x N work-items) against a brute-force host AO.
#include "texrender/Bvh.h"
#include "texrender/Error.h"
#include "texrender/Layout.h"
#include "texrender/Renderer.h"
#include "TestScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <random>
#include <unistd.h>

namespace fs = std::filesystem;
using namespace texrender;
using namespace texrender::test;

namespace {

Vec3 v3(const cl_float4 &V) { return {V.s[0], V.s[1], V.s[2]}; }

} // namespace

TEST(Device, ClosestHitMatchesBruteForce) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  std::mt19937 Rng(7);
  std::uniform_real_distribution<float> U(-1.0f, 1.0f), S(0.02f, 0.3f);
  std::string Obj;
  for (int T = 0; T < 400; ++T) {
    float Cx = U(Rng), Cy = U(Rng) * 0.5f + 0.5f, Cz = U(Rng);
    for (int K = 0; K < 3; ++K)
      Obj += "v " + std::to_string(Cx + U(Rng) * S(Rng)) + " " + std::to_string(Cy + U(Rng) * S(Rng)) +
             " " + std::to_string(Cz + U(Rng) * S(Rng)) + "\n";
    Obj += "f " + std::to_string(3 * T + 1) + " " + std::to_string(3 * T + 2) + " " +
           std::to_string(3 * T + 3) + "\n";
  }
  TestScene T = makeScene(tempDir("bvh"), {Obj}, 48);
  Renderer R(T.S, T.L, testOptions());
  FrameStats Stats;
  uint32_t Mask = (1u << TEXCC_ATTR_WORLDPOS) | (1u << TEXCC_ATTR_VIEWDIR);
  auto Attrs = R.primaryHitAttributes(Mask, Stats);
  const auto &P = R.sceneData().Positions;
  int Hits = 0, Mismatch = 0;
  for (auto &A : Attrs) {
    Vec3 D = v3(A.viewDir);
    D = {-D[0], -D[1], -D[2]};
    HostHit Ref = traceBruteForce(P, T.S.Cam.Position, D, 0.0f, 1e30f);
    bool DevHit = A.worldPos.s[3] == 1.0f;
    if (DevHit != (Ref.Tri >= 0)) {
      ++Mismatch;
      continue;
    }
    if (!DevHit)
      continue;
    ++Hits;
    for (int C = 0; C < 3; ++C)
      EXPECT_NEAR(A.worldPos.s[C], T.S.Cam.Position[C] + Ref.T * D[C], 1e-3);
  }
  // Rays grazing a shared edge may legitimately differ; nothing else may.
  EXPECT_LE(Mismatch, 2);
  EXPECT_GT(Hits, 200);
}

TEST(Device, AmbientOcclusionOneLaunchMatchesBruteForce) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  const int Size = 24, N = 64;
  const float Dist = 0.5f;
  TestScene T = makeScene(tempDir("ao"), {FloorAndCube}, Size);
  T.S.Render.AoSamples = N;
  T.S.Render.AoDistance = Dist;
  Renderer R(T.S, T.L, testOptions());
  FrameStats Stats;
  uint32_t Mask = (1u << TEXCC_ATTR_WORLDPOS) | (1u << TEXCC_ATTR_NORMAL) |
                  (1u << TEXCC_ATTR_GEOMNORMAL) | (1u << TEXCC_ATTR_AO);
  auto Attrs = R.primaryHitAttributes(Mask, Stats);
  // One AO launch of (hits incl. misses) x N work-items, then one reduction.
  ASSERT_EQ(Stats.Kernels.count("ao_trace"), 1u);
  EXPECT_EQ(Stats.Kernels.at("ao_trace").Launches, 1u);
  EXPECT_EQ(Stats.Kernels.at("ao_trace").WorkItems, uint64_t(Size) * Size * N);
  EXPECT_EQ(Stats.Kernels.at("ao_reduce").Launches, 1u);

  const auto &P = R.sceneData().Positions;
  std::mt19937 Rng(11);
  std::uniform_real_distribution<float> U(0.0f, 1.0f);
  int Hits = 0, Outliers = 0;
  double SumDev = 0, SumHost = 0;
  for (auto &A : Attrs) {
    if (A.worldPos.s[3] != 1.0f)
      continue;
    ++Hits;
    Vec3 Pos = v3(A.worldPos), Nrm = v3(A.normal), Ng = v3(A.geomNormal);
    // Brute force: 1024 cosine-weighted rays against every triangle.
    Vec3 Tn = std::fabs(Nrm[0]) > 0.5f ? Vec3{0, 1, 0} : Vec3{1, 0, 0};
    Vec3 Bt = {Nrm[1] * Tn[2] - Nrm[2] * Tn[1], Nrm[2] * Tn[0] - Nrm[0] * Tn[2], Nrm[0] * Tn[1] - Nrm[1] * Tn[0]};
    float L = std::sqrt(Bt[0] * Bt[0] + Bt[1] * Bt[1] + Bt[2] * Bt[2]);
    for (auto &C : Bt) C /= L;
    Tn = {Bt[1] * Nrm[2] - Bt[2] * Nrm[1], Bt[2] * Nrm[0] - Bt[0] * Nrm[2], Bt[0] * Nrm[1] - Bt[1] * Nrm[0]};
    float Eps = 1e-4f * (1.0f + std::max({std::fabs(Pos[0]), std::fabs(Pos[1]), std::fabs(Pos[2])}));
    Vec3 O = {Pos[0] + Eps * Ng[0], Pos[1] + Eps * Ng[1], Pos[2] + Eps * Ng[2]};
    const int M = 1024;
    int Occ = 0;
    for (int K = 0; K < M; ++K) {
      float R1 = U(Rng), Phi = 2 * float(M_PI) * U(Rng), Rr = std::sqrt(R1), Z = std::sqrt(1 - R1);
      float X = Rr * std::cos(Phi), Y = Rr * std::sin(Phi);
      Vec3 D = {X * Tn[0] + Y * Bt[0] + Z * Nrm[0], X * Tn[1] + Y * Bt[1] + Z * Nrm[1],
                X * Tn[2] + Y * Bt[2] + Z * Nrm[2]};
      Occ += traceBruteForce(P, O, D, 0.0f, Dist).Tri >= 0;
    }
    double Host = 1.0 - double(Occ) / M, Dev = A.uvAO.s[2];
    double Sigma = std::sqrt(std::max(Host * (1 - Host), 1.0 / M) / N + Host * (1 - Host) / M);
    if (std::fabs(Dev - Host) > 4.5 * Sigma + 1e-3)
      ++Outliers;
    SumDev += Dev, SumHost += Host;
  }
  ASSERT_GT(Hits, 100);
  EXPECT_LE(Outliers, 2) << "of " << Hits << " hits";
  EXPECT_NEAR(SumDev / Hits, SumHost / Hits, 0.01);
  EXPECT_LT(SumHost / Hits, 0.97) << "the scene should have visible occlusion";
  EXPECT_EQ(Stats.AoRays, uint64_t(Hits) * N);
}

// A layout adopted after a live edit may number the materials differently: every mesh follows
// its material by name, and a name the new layout lacks is an error naming it.
TEST(Device, NewLayoutMapsMeshMaterialsByName) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  fs::path Dir = tempDir("remap");
  TestScene T = makeScene(Dir, {FloorAndCube}, 4);
  Renderer R(T.S, T.L, testOptions());
  ASSERT_EQ(R.sceneData().Meshes[0].material, T.L.findMaterial("white"));
  Layout Reversed = T.L;
  std::reverse(Reversed.Materials.begin(), Reversed.Materials.end());
  for (size_t I = 0; I < Reversed.Materials.size(); ++I)
    Reversed.Materials[I].Index = int(I);
  ASSERT_NE(Reversed.findMaterial("white"), T.L.findMaterial("white"));
  R.setLayout(Reversed);
  EXPECT_EQ(R.sceneData().Meshes[0].material, Reversed.findMaterial("white"));
  Layout Renamed = T.L;
  Renamed.Materials[size_t(T.L.findMaterial("white"))].Name = "chalk";
  try {
    R.setLayout(Renamed);
    ADD_FAILURE() << "a layout without the mesh's material was adopted";
  } catch (const Error &E) {
    EXPECT_NE(std::string(E.what()).find("has no material 'white'"), std::string::npos) << E.what();
  }
  fs::remove_all(Dir);
}

// rt_owen_net2_8 (a hit's AO rays, ao.cl) is a fully Owen-scrambled (0, 3, 2) net of Sobol's
// first two dimensions, as the AO node's points in Cycles' tabulated pattern are (issue 22):
// every trial's 8 points are stratified in all elementary intervals of area 1/8, and the
// estimate of the 8 rays through the concentric map for half-planes of the disk has the mean
// and the variance of a reference Owen scramble (std::mt19937_64: one random flip per node of
// the top 3 levels, random bits below per point), within 4%. rt_sobol2's hashed scramble on
// the same points: variance ratios 0.75-0.85 on the half-planes through the centre
// (bench/cycles.md, session 9).
TEST(Device, AoNetIsOwenScrambled) {
  if (!haveDevice())
    GTEST_SKIP() << "no OpenCL device";
  const char *Env = std::getenv("TEXRENDER_KERNELS");
  const std::string Common = (fs::path(Env && *Env ? Env : TEXRENDER_KERNEL_DIR) / "common").string();
  ClContext Cl(0, "");
  cl::Program P = Cl.buildProgram("aonet-test.cl", R"(
#include "rt_sampling.h"
__kernel void aonet(uint n, __global float *out) {
  uint g = get_global_id(0);
  if (g >= n)
    return;
  float8 u1, u2;
  rt_owen_net2_8((uint8)(0u, 1u, 2u, 3u, 4u, 5u, 6u, 7u), 3u, rt_hash(g ^ 0x2545f491u), &u1, &u2);
  vstore8(u1, 0, out + 16 * g), vstore8(u2, 1, out + 16 * g);
}
)", "-cl-std=CL1.2 -I " + Common);
  const cl_uint N = 1u << 17;
  std::vector<float> Dev(size_t(N) * 16);
  cl::Buffer B = Cl.allocate("aonet", Dev.size() * sizeof(float), CL_MEM_WRITE_ONLY);
  cl::Kernel K(P, "aonet");
  K.setArg(0, N), K.setArg(1, B);
  Cl.launch(K, N, "aonet");
  Cl.finish();
  Cl.read(B, Dev.data(), Dev.size() * sizeof(float));

  // The reference: Sobol's dimensions 0 and 1 of points 0-7 (3-bit fixed point), each
  // dimension scrambled by 7 independent node flips, the bits below uniform per point.
  const unsigned Sobol[2][8] = {{0, 4, 2, 6, 1, 5, 3, 7}, {0, 4, 6, 2, 5, 1, 3, 7}};
  std::mt19937_64 Rng(12345);
  std::uniform_real_distribution<double> Uni(0.0, 1.0);
  std::vector<double> Ref(size_t(N) * 16);
  for (cl_uint T = 0; T < N; ++T)
    for (int D = 0; D < 2; ++D) {
      const uint64_t Flips = Rng();
      for (int J = 0; J < 8; ++J) {
        unsigned V = Sobol[D][J], Out = 0, Node = 1;
        for (int Kb = 2; Kb >= 0; --Kb) {
          const unsigned Bit = (V >> Kb) & 1u;
          Out |= (Bit ^ unsigned((Flips >> Node) & 1u)) << Kb;
          Node = Node * 2 + Bit;
        }
        Ref[size_t(T) * 16 + size_t(D) * 8 + size_t(J)] = (Out + Uni(Rng)) / 8.0;
      }
    }

  // Stratification of every trial: one point per elementary interval (8 x 1 ... 1 x 8).
  int Unstratified = 0;
  for (cl_uint T = 0; T < N; ++T)
    for (int Bx = 0; Bx <= 3; ++Bx) {
      unsigned Seen = 0;
      for (int J = 0; J < 8; ++J) {
        const double X = Dev[size_t(T) * 16 + size_t(J)], Y = Dev[size_t(T) * 16 + 8 + size_t(J)];
        Seen |= 1u << ((int(X * (1 << Bx)) << (3 - Bx)) | int(Y * (1 << (3 - Bx))));
      }
      Unstratified += Seen != 0xffu;
    }
  EXPECT_EQ(Unstratified, 0);

  // The 8-ray estimate of half-planes of the disk (Cycles' concentric map).
  auto Disk = [](double U1, double U2, double &X, double &Y) {
    const double A = 2 * U1 - 1, Bv = 2 * U2 - 1;
    double R = 0, Phi = 0;
    if (A * A > Bv * Bv)
      R = A, Phi = M_PI / 4 * (Bv / A);
    else if (Bv != 0)
      R = Bv, Phi = M_PI / 2 - M_PI / 4 * (A / Bv);
    X = R * std::cos(Phi), Y = R * std::sin(Phi);
  };
  for (double Theta : {0.26, 0.52, 0.79, 1.1})
    for (double C : {-0.5, 0.0, 0.3}) {
      double Moments[2][2] = {{0, 0}, {0, 0}};
      for (int Which = 0; Which < 2; ++Which)
        for (cl_uint T = 0; T < N; ++T) {
          int Hits = 0;
          for (int J = 0; J < 8; ++J) {
            const size_t I = size_t(T) * 16 + size_t(J);
            double X, Y;
            if (Which == 0)
              Disk(Dev[I], Dev[I + 8], X, Y);
            else
              Disk(Ref[I], Ref[I + 8], X, Y);
            Hits += X * std::cos(Theta) + Y * std::sin(Theta) > C;
          }
          Moments[Which][0] += Hits / 8.0, Moments[Which][1] += (Hits / 8.0) * (Hits / 8.0);
        }
      double Mean[2], Var[2];
      for (int W = 0; W < 2; ++W)
        Mean[W] = Moments[W][0] / N, Var[W] = Moments[W][1] / N - Mean[W] * Mean[W];
      EXPECT_NEAR(Mean[0], Mean[1], 4 * std::sqrt(2 * Var[1] / N))
          << "theta " << Theta << ", c " << C;
      EXPECT_NEAR(Var[0] / Var[1], 1.0, 0.04) << "theta " << Theta << ", c " << C << ": variance "
                                              << Var[0] << " against " << Var[1];
    }
}
