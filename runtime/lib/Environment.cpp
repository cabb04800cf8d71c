#include "texrender/Environment.h"
#include "texrender/Error.h"
#include "texrender/Image.h"

#include <algorithm>
#include <cmath>

extern "C" {
#include "rt_types.h"
}

namespace texrender {

namespace {

/// The luminance (Rec. 709) of a linear RGB texel; negative values count as 0.
double texelLuminance(const std::vector<float> &Linear, size_t K) {
  return std::max(0.0, 0.2126 * Linear[3 * K] + 0.7152 * Linear[3 * K + 1] +
                           0.0722 * Linear[3 * K + 2]);
}

/// The texels as the kernel interpolates them, in Cycles' row order (row 0 the bottom).
/// Colour images (not Non-Color) have their alpha associated as Cycles associates it (an 8- or
/// 16-bit image's on its integers, rounded down, as texcc_texel_filtered does); an 8- or 16-bit
/// sRGB image keeps its encoded values (decoded after interpolation, RT_ENV_SRGB); a float
/// image in sRGB is decoded here, as Cycles converts float images when it loads them.
void prepareTexels(const ImageRGBA &Img, const std::string &Space, EnvironmentMap &M,
                   std::vector<float> &Linear) {
  const int W = Img.Width, H = Img.Height;
  const bool Ints = Img.Bits != 32, Data = Space == "Non-Color";
  const bool Srgb = Space == "sRGB";
  if (Srgb && Ints)
    M.Flags |= RT_ENV_SRGB;
  const float Scale = Img.Bits == 8 ? 255.0f : 65535.0f;
  M.Data.assign(size_t(W) * H * 4, 0.0f);
  Linear.assign(size_t(W) * H * 3, 0.0f);
  for (int Y = 0; Y < H; ++Y)
    for (int X = 0; X < W; ++X) {
      const float *P = &Img.Pixels[(size_t(Y) * W + X) * 4];
      float C[3] = {P[0], P[1], P[2]};
      const float A = P[3];
      if (Srgb && !Ints)
        for (float &V : C)
          V = srgbToLinear(V);
      if (!Data && A != 1.0f) {
        for (float &V : C)
          V = Ints ? std::floor(std::rint(V * Scale) * std::rint(A * Scale) / Scale) / Scale
                   : V * A;
      }
      const size_t K = size_t(H - 1 - Y) * W + X;
      for (int I = 0; I < 3; ++I) {
        M.Data[4 * K + I] = C[I];
        Linear[3 * K + I] = (M.Flags & RT_ENV_SRGB) ? srgbToLinear(C[I]) : C[I];
      }
    }
}

/// The weight of every texel: its luminance (negative values count as 0) spread as bilinear
/// interpolation spreads it (the mean of the interpolated value over the texel's cell is
/// [1 6 1] / 8 in each axis, wrapping as the lookup wraps), so that every direction whose
/// interpolated radiance is positive has a positive density; times sin(theta) at the row's
/// centre (the cell's solid angle).
std::vector<double> texelWeights(const std::vector<float> &Linear, int W, int H, bool Closest) {
  std::vector<double> L(size_t(W) * H);
  for (size_t K = 0; K < L.size(); ++K)
    L[K] = texelLuminance(Linear, K);
  if (!Closest) {
    std::vector<double> T(L.size());
    for (int Y = 0; Y < H; ++Y)
      for (int X = 0; X < W; ++X)
        T[size_t(Y) * W + X] = (L[size_t(Y) * W + (X + W - 1) % W] + 6 * L[size_t(Y) * W + X] +
                                L[size_t(Y) * W + (X + 1) % W]) / 8;
    for (int Y = 0; Y < H; ++Y)
      for (int X = 0; X < W; ++X)
        L[size_t(Y) * W + X] = (T[size_t((Y + H - 1) % H) * W + X] + 6 * T[size_t(Y) * W + X] +
                                T[size_t((Y + 1) % H) * W + X]) / 8;
  }
  for (int Y = 0; Y < H; ++Y) {
    const double S = std::sin(M_PI * (Y + 0.5) / H);
    for (int X = 0; X < W; ++X)
      L[size_t(Y) * W + X] *= S;
  }
  return L;
}

/// Appends the density (texels' w), the rows' marginal CDF and each row's conditional CDF.
void buildDensity(std::vector<double> F, int W, int H, EnvironmentMap &M) {
  double Total = 0;
  for (double V : F)
    Total += V;
  if (!(Total > 0) || !std::isfinite(Total)) { // a black map: any density (it adds nothing)
    for (int Y = 0; Y < H; ++Y)
      for (int X = 0; X < W; ++X)
        F[size_t(Y) * W + X] = std::sin(M_PI * (Y + 0.5) / H);
    Total = 0;
    for (double V : F)
      Total += V;
  }
  const double Mean = Total / (double(W) * H);
  for (size_t K = 0; K < F.size(); ++K)
    M.Data[4 * K + 3] = float(F[K] / Mean);
  std::vector<double> Rows(H, 0.0);
  for (int Y = 0; Y < H; ++Y)
    for (int X = 0; X < W; ++X)
      Rows[Y] += F[size_t(Y) * W + X];
  double Acc = 0;
  for (int Y = 0; Y < H; ++Y) {
    Acc += Rows[Y];
    M.Data.push_back(Y + 1 == H ? 1.0f : float(Acc / Total));
  }
  for (int Y = 0; Y < H; ++Y) {
    double RowAcc = 0;
    for (int X = 0; X < W; ++X) {
      RowAcc += F[size_t(Y) * W + X];
      M.Data.push_back(X + 1 == W ? 1.0f
                                  : float(Rows[Y] > 0 ? RowAcc / Rows[Y] : double(X + 1) / W));
    }
  }
}

} // namespace

EnvironmentMap loadEnvironmentMap(const Light &L, const std::string &Where) {
  ImageRGBA Img;
  try {
    Img = loadTexture(L.Image, "Non-Color"); // the values as stored
  } catch (const Error &E) {
    throw Error(Where + "/image: " + E.what());
  }
  const std::string Space =
      !L.ColorSpace.empty() ? L.ColorSpace : Img.Bits == 32 ? "Linear Rec.709" : "sRGB";
  for (size_t K = 0; K < Img.Pixels.size(); ++K)
    if (!std::isfinite(Img.Pixels[K])) {
      const size_t P = K / 4;
      throw Error(Where + "/image: '" + L.Image + "' has a NaN or infinite value at pixel (" +
                  std::to_string(P % size_t(Img.Width)) + ", " +
                  std::to_string(P / size_t(Img.Width)) + ")");
    }
  EnvironmentMap M;
  M.Width = Img.Width;
  M.Height = Img.Height;
  const bool Closest = L.Interpolation == "closest";
  if (Closest)
    M.Flags |= RT_ENV_CLOSEST;
  std::vector<float> Linear;
  prepareTexels(Img, Space, M, Linear);
  double Sum = 0;
  for (int Y = 0; Y < M.Height; ++Y) {
    const double S = std::sin(M_PI * (Y + 0.5) / M.Height);
    for (int X = 0; X < M.Width; ++X) {
      Sum += S * texelLuminance(Linear, size_t(Y) * M.Width + X);
    }
  }
  // The mean over the sphere: each texel's solid angle is (2 pi / W)(pi / H) sin(theta).
  M.MeanLuminance = Sum * M_PI / (2.0 * M.Width * M.Height) * L.Strength;
  buildDensity(texelWeights(Linear, M.Width, M.Height, Closest), M.Width, M.Height, M);
  return M;
}

} // namespace texrender
