// texrender-compare: compares a render with a reference by a per-block z-test with a
// false-positive budget (as Mitsuba 3's test_renders.py), and by mean radiance per channel.
//
//   texrender-compare IMAGE.exr IMAGE_VAR.exr REF.exr REF_VAR.exr
//                     [--block N] [--alpha A] [--mean-tolerance T]
//   texrender-compare --mean IMAGE.exr      prints "mean R G B" (for tests of edits)
//   texrender-compare --exact A.exr B.exr   bit-for-bit: prints the pixels that differ and the
//                     largest difference (absolute, and in units in the last place); exit 0
//                     only when every value is identical (the tier tests)
//
// Both images come with the per-pixel variance of their value (texrender --variance;
// scripts/mitsuba_reference.py). Pixels are grouped in N x N blocks (default 8); for each block
// and channel z = (mean_image - mean_ref) / sqrt(var_image + var_ref), with the block variances
// the mean of the pixel variances / N^2. The p-value of every test is compared with
// alpha / (number of tests) (Bonferroni: the whole comparison fails by chance with probability
// at most alpha, default 0.01). The mean radiance per channel must agree within T (default 1%).
// Exit 0 when both hold, 1 otherwise.
#include "texrender/Error.h"
#include "texrender/Image.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

using namespace texrender;

namespace {

struct Args {
  std::string Image, ImageVar, Ref, RefVar;
  int Block = 8;
  double Alpha = 0.01, MeanTolerance = 0.01;
};

Args parse(int Argc, char **Argv) {
  Args A;
  std::vector<std::string> Pos;
  for (int I = 1; I < Argc; ++I) {
    std::string S = Argv[I];
    auto Next = [&]() -> std::string {
      if (I + 1 >= Argc)
        throw Error(S + ": missing value");
      return Argv[++I];
    };
    if (S == "--block")
      A.Block = std::stoi(Next());
    else if (S == "--alpha")
      A.Alpha = std::stod(Next());
    else if (S == "--mean-tolerance")
      A.MeanTolerance = std::stod(Next());
    else if (!S.empty() && S[0] == '-')
      throw Error("unknown option '" + S + "'");
    else
      Pos.push_back(S);
  }
  if (Pos.size() != 4)
    throw Error("usage: texrender-compare IMAGE.exr IMAGE_VAR.exr REF.exr REF_VAR.exr "
                "[--block N] [--alpha A] [--mean-tolerance T]");
  A.Image = Pos[0], A.ImageVar = Pos[1], A.Ref = Pos[2], A.RefVar = Pos[3];
  return A;
}

void sameSize(const ImageRGBA &A, const ImageRGBA &B, const std::string &NA, const std::string &NB) {
  if (A.Width != B.Width || A.Height != B.Height)
    throw Error(NA + " is " + std::to_string(A.Width) + "x" + std::to_string(A.Height) + " but " +
                NB + " is " + std::to_string(B.Width) + "x" + std::to_string(B.Height));
}

int compare(const Args &A) {
  ImageRGBA Im = loadExr(A.Image), ImV = loadExr(A.ImageVar), Rf = loadExr(A.Ref),
            RfV = loadExr(A.RefVar);
  sameSize(Im, Rf, A.Image, A.Ref);
  sameSize(Im, ImV, A.Image, A.ImageVar);
  sameSize(Rf, RfV, A.Ref, A.RefVar);
  const int W = Im.Width, H = Im.Height, N = A.Block;
  const int BX = W / N, BY = H / N;
  const int Tests = BX * BY * 3;
  const double Threshold = A.Alpha / Tests;
  int Failed = 0;
  double WorstP = 1.0;
  int WorstX = 0, WorstY = 0, WorstC = 0;
  double WorstZ = 0;
  for (int By = 0; By < BY; ++By)
    for (int Bx = 0; Bx < BX; ++Bx)
      for (int C = 0; C < 3; ++C) {
        double Mi = 0, Mr = 0, Vi = 0, Vr = 0;
        for (int Y = By * N; Y < (By + 1) * N; ++Y)
          for (int X = Bx * N; X < (Bx + 1) * N; ++X) {
            size_t P = 4 * (size_t(Y) * W + X) + C;
            Mi += Im.Pixels[P], Mr += Rf.Pixels[P], Vi += ImV.Pixels[P], Vr += RfV.Pixels[P];
          }
        double K = double(N) * N;
        Mi /= K, Mr /= K, Vi /= K * K, Vr /= K * K;
        double Sd = std::sqrt(Vi + Vr);
        double Z = Sd > 0 ? (Mi - Mr) / Sd : (Mi == Mr ? 0.0 : INFINITY);
        double PValue = std::erfc(std::fabs(Z) / std::sqrt(2.0));
        if (PValue < Threshold)
          ++Failed;
        if (PValue < WorstP)
          WorstP = PValue, WorstX = Bx, WorstY = By, WorstC = C, WorstZ = Z;
      }
  double MeanI[3] = {0, 0, 0}, MeanR[3] = {0, 0, 0};
  for (size_t P = 0; P < size_t(W) * H; ++P)
    for (int C = 0; C < 3; ++C)
      MeanI[C] += Im.Pixels[4 * P + C], MeanR[C] += Rf.Pixels[4 * P + C];
  bool MeanOk = true;
  std::printf("mean radiance:");
  for (int C = 0; C < 3; ++C) {
    MeanI[C] /= double(W) * H, MeanR[C] /= double(W) * H;
    double Rel = MeanR[C] != 0 ? (MeanI[C] - MeanR[C]) / MeanR[C] : 0;
    MeanOk &= std::fabs(Rel) <= A.MeanTolerance;
    std::printf(" %c %.5f vs %.5f (%+.2f%%)", "RGB"[C], MeanI[C], MeanR[C], 100 * Rel);
  }
  std::printf("\n");
  std::printf("z-test: %d blocks of %dx%d, %d tests, %d failed at p < %.3g (alpha %.3g); worst: "
              "block (%d, %d) %c z = %.2f p = %.3g\n",
              BX * BY, N, N, Tests, Failed, Threshold, A.Alpha, WorstX, WorstY, "RGB"[WorstC],
              WorstZ, WorstP);
  bool Ok = Failed == 0 && MeanOk;
  std::printf("%s\n", Ok ? "PASS" : (Failed ? "FAIL: blocks differ" : "FAIL: mean radiance differs"));
  return Ok ? 0 : 1;
}

} // namespace

int printMean(const std::string &Path) {
  ImageRGBA Im = loadExr(Path);
  double M[3] = {0, 0, 0};
  for (size_t P = 0; P < size_t(Im.Width) * Im.Height; ++P)
    for (int C = 0; C < 3; ++C)
      M[C] += Im.Pixels[4 * P + C];
  double N = double(Im.Width) * Im.Height;
  std::printf("mean %.6f %.6f %.6f\n", M[0] / N, M[1] / N, M[2] / N);
  return 0;
}

/// The distance between two floats in representable values (0: identical bits).
uint64_t ulpDistance(float A, float B) {
  auto Ordered = [](float F) {
    int32_t I;
    std::memcpy(&I, &F, sizeof I);
    return I < 0 ? int64_t(INT32_MIN) - I : int64_t(I);
  };
  int64_t D = Ordered(A) - Ordered(B);
  return uint64_t(D < 0 ? -D : D);
}

int compareExact(const std::string &PathA, const std::string &PathB) {
  ImageRGBA A = loadExr(PathA), B = loadExr(PathB);
  if (A.Width != B.Width || A.Height != B.Height)
    throw Error(PathA + " is " + std::to_string(A.Width) + "x" + std::to_string(A.Height) + ", " +
                PathB + " is " + std::to_string(B.Width) + "x" + std::to_string(B.Height));
  size_t Differ = 0;
  double MaxAbs = 0;
  uint64_t MaxUlp = 0;
  for (size_t P = 0; P < size_t(A.Width) * A.Height; ++P) {
    bool Same = true;
    for (int C = 0; C < 3; ++C) {
      float X = A.Pixels[4 * P + C], Y = B.Pixels[4 * P + C];
      uint64_t U = ulpDistance(X, Y);
      Same &= U == 0;
      MaxUlp = std::max(MaxUlp, U);
      MaxAbs = std::max(MaxAbs, std::fabs(double(X) - Y));
    }
    Differ += !Same;
  }
  std::printf("exact: %zu of %zu pixels differ; max |difference| %.3g, %llu ulp\n%s\n", Differ,
              size_t(A.Width) * A.Height, MaxAbs, (unsigned long long)MaxUlp,
              Differ ? "FAIL: images differ" : "PASS");
  return Differ ? 1 : 0;
}

int main(int Argc, char **Argv) {
  try {
    if (Argc == 3 && std::strcmp(Argv[1], "--mean") == 0)
      return printMean(Argv[2]);
    if (Argc == 4 && std::strcmp(Argv[1], "--exact") == 0)
      return compareExact(Argv[2], Argv[3]);
    return compare(parse(Argc, Argv));
  } catch (const std::exception &E) {
    std::fprintf(stderr, "texrender-compare: error: %s\n", E.what());
    return 1;
  }
}
