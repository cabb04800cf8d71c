// OBJ loading: one pass over the text (plain or gzip-compressed, through zlib), triangulated,
// with generated normals where the file gives none.
#include "texrender/Error.h"
#include "texrender/Scene.h"
#include "texcc/OutOfMemory.h"
#include "texcc/Support/File.h"
#include "texcc/Support/Numbers.h"

#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>

namespace texrender {

namespace {

std::string readMaybeGzipped(const std::string &Path) {
  std::string NotRegular; // gzopen() of a FIFO would block, a folder would read as empty
  if (!texcc::checkRegularFile(Path, NotRegular))
    throw Error(Path + ": cannot open OBJ file: " + NotRegular);
  gzFile F = gzopen(Path.c_str(), "rb"); // reads plain files unchanged too
  if (!F)
    throw Error(Path + ": cannot open OBJ file: " + std::strerror(errno));
  // Read straight into the string, sized from the file (a plain file is read in one go; a
  // compressed one grows it by doubling): no 64 KiB staging copies, no append reallocations.
  std::error_code EC;
  const uintmax_t FileSize = std::filesystem::file_size(Path, EC);
  std::string Out;
  Out.resize(size_t(std::clamp<uintmax_t>(EC ? 0 : FileSize + 1, 1 << 16, 1u << 30)));
  size_t Len = 0;
  int N;
  for (;;) {
    if (Len == Out.size())
      Out.resize(2 * Out.size());
    const unsigned Want = unsigned(std::min<size_t>(Out.size() - Len, 1u << 30));
    if ((N = gzread(F, &Out[Len], Want)) <= 0)
      break;
    Len += size_t(N);
  }
  Out.resize(Len);
  int Err = 0;
  const char *Msg = gzerror(F, &Err);
  bool Failed = N < 0 || (Err != Z_OK && Err != Z_STREAM_END);
  std::string Why = Failed ? Msg : "";
  gzclose(F);
  if (Failed)
    throw Error(Path + ": cannot decompress OBJ file: " + Why);
  return Out;
}

Vec3 sub(const Vec3 &A, const Vec3 &B) { return {A[0] - B[0], A[1] - B[1], A[2] - B[2]}; }
Vec3 cross(const Vec3 &A, const Vec3 &B) {
  return {A[1] * B[2] - A[2] * B[1], A[2] * B[0] - A[0] * B[2], A[0] * B[1] - A[1] * B[0]};
}
float dot(const Vec3 &A, const Vec3 &B) { return A[0] * B[0] + A[1] * B[1] + A[2] * B[2]; }
Vec3 normalized(const Vec3 &V) {
  float L = std::sqrt(dot(V, V));
  return L > 0 ? Vec3{V[0] / L, V[1] / L, V[2] / L} : Vec3{0, 0, 0};
}

std::string formatVec3(const Vec3 &V) {
  char Buf[96];
  std::snprintf(Buf, sizeof Buf, "%g, %g, %g", V[0], V[1], V[2]);
  return Buf;
}

/// Whether a face corner gives an optional index (-1 when it does not) into an array of Tuple
/// floats each; an index to a missing element is an error.
bool hasIndex(int Index, size_t Tuple, size_t Size, const std::string &Path, const char *What) {
  if (Index == -1)
    return false;
  if (Index < 0 || Tuple * size_t(Index) + Tuple > Size)
    throw Error(Path + ": invalid OBJ: " + What + " index out of range");
  return true;
}

/// One triangle's corners as the file gives them (FileNormals: every corner has a normal).
struct Face {
  Vec3 P[3], N[3];
  Vec2 UV[3];
  Vec4 T[3]; // the tangents of the corners' normals (vtan); w = 0 without them
  bool FileNormals = true;
};

Face readFace(const ObjText &A, const ObjCorner *Idx, const std::string &Path) {
  Face Fc;
  for (int C = 0; C < 3; ++C) {
    const ObjCorner &I = Idx[C];
    if (I.V < 0 || 3 * size_t(I.V) + 2 >= A.Positions.size())
      throw Error(Path + ": invalid OBJ: vertex index out of range");
    Fc.P[C] = {A.Positions[3 * I.V], A.Positions[3 * I.V + 1], A.Positions[3 * I.V + 2]};
    if (!std::isfinite(Fc.P[C][0]) || !std::isfinite(Fc.P[C][1]) || !std::isfinite(Fc.P[C][2]))
      throw Error(Path + ": invalid OBJ: vertex " + std::to_string(I.V + 1) +
                  " has a non-finite coordinate (" + formatVec3(Fc.P[C]) + ")");
    Fc.T[C] = {0, 0, 0, 0};
    if (hasIndex(I.N, 3, A.Normals.size(), Path, "normal")) {
      Fc.N[C] = normalized({A.Normals[3 * I.N], A.Normals[3 * I.N + 1], A.Normals[3 * I.N + 2]});
      if (!A.Tangents.empty()) // parseObj checked: one vtan per vn
        Fc.T[C] = {A.Tangents[4 * I.N], A.Tangents[4 * I.N + 1], A.Tangents[4 * I.N + 2],
                   A.Tangents[4 * I.N + 3]};
    } else {
      Fc.FileNormals = false;
    }
    Fc.UV[C] = {0, 0};
    if (hasIndex(I.T, 2, A.TexCoords.size(), Path, "texture coordinate"))
      Fc.UV[C] = {A.TexCoords[2 * I.T], A.TexCoords[2 * I.T + 1]};
  }
  return Fc;
}

/// Smooth normals for the triangles whose file gave none: the area-weighted average of the
/// normals of the faces sharing the corner's position within 60 degrees (creases stay sharp).
/// The faces of a position are visited in triangle order (a counting sort of the corners by
/// position index), so that every sum adds the same terms in the same order as ever.
void generateNormals(TriangleMesh &M, const std::vector<int> &PosIndex,
                     const std::vector<bool> &HasNormals) {
  if (std::find(HasNormals.begin(), HasNormals.end(), false) == HasNormals.end())
    return; // the file gave every normal
  size_t NT = M.triangleCount();
  std::vector<Vec3> FaceN(NT); // area-weighted
  int MaxPos = -1;
  for (int P : PosIndex)
    MaxPos = std::max(MaxPos, P); // readFace checked: 0 <= P
  std::vector<size_t> First(size_t(MaxPos) + 2, 0), Faces(PosIndex.size());
  for (size_t T = 0; T < NT; ++T) {
    FaceN[T] = cross(sub(M.Positions[3 * T + 1], M.Positions[3 * T]),
                     sub(M.Positions[3 * T + 2], M.Positions[3 * T]));
    for (int C = 0; C < 3; ++C)
      ++First[size_t(PosIndex[3 * T + C]) + 1];
  }
  for (size_t I = 1; I < First.size(); ++I)
    First[I] += First[I - 1];
  {
    std::vector<size_t> Fill(First.begin(), First.end() - 1);
    for (size_t T = 0; T < NT; ++T)
      for (int C = 0; C < 3; ++C)
        Faces[Fill[size_t(PosIndex[3 * T + C])]++] = T;
  }
  const float CosCrease = 0.5f;
  for (size_t T = 0; T < NT; ++T) {
    if (HasNormals[T])
      continue;
    Vec3 Own = normalized(FaceN[T]);
    for (int C = 0; C < 3; ++C) {
      Vec3 Sum{0, 0, 0};
      const size_t Pos = size_t(PosIndex[3 * T + C]);
      for (size_t K = First[Pos]; K < First[Pos + 1]; ++K) {
        const size_t O = Faces[K];
        if (dot(normalized(FaceN[O]), Own) >= CosCrease)
          for (int D = 0; D < 3; ++D)
            Sum[D] += FaceN[O][D];
      }
      Vec3 N = normalized(Sum);
      M.Normals[3 * T + C] = dot(N, N) > 0 ? N : Own;
    }
  }
}

// --- The reader ------------------------------------------------------------------------------
//
// Lines end at '\n', "\r\n" or a lone '\r'; blanks are spaces and tabs. Read: v, vn and vt (every
// number a finite float; the first three, three and two kept, missing ones 0; a '#' ends the
// numbers), vtan (texrender's extension, docs/scene.md "Tangents": x y z w, the tangent and
// bitangent sign of the vn of the same index; exactly four finite numbers, w 1 or -1, and as
// many vtan as vn when there is any), and f (corners v, v/t, v//n or v/t/n; a negative index
// counts back from the elements
// read so far; faces of fewer than three corners are skipped, quads split along the shorter
// diagonal, larger polygons fanned from their first corner). Every other statement (comments,
// g, o, s, usemtl, mtllib, l, p, vp, curves, tinyobjloader's vw ...) is ignored. Numbers are
// converted as tinyobjloader, the reader before this one, converts them (digit by digit in
// double, then 5^e and 2^e: not correctly rounded) and quads split by its rule, so that meshes
// (and images) stay the same bit for bit; runtime/unittests/ObjFastTest.cpp checks this
// against tinyobjloader.

bool isBlank(char C) { return C == ' ' || C == '\t'; }
bool isDigit(char C) { return C >= '0' && C <= '9'; }

/// One token [P, End) as a number, or false: sign? (digits ('.' digits*)? | '.' digits)
/// ([eE] sign? digits)?, all of the token, whose value is a finite float.
bool parseNumber(const char *P, const char *End, float &Out) {
  static const double Tenths[] = {1.0, 0.1, 0.01, 0.001, 0.0001, 0.00001, 0.000001, 0.0000001};
  bool Negative = false;
  if (P < End && (*P == '+' || *P == '-'))
    Negative = *P++ == '-';
  double Mantissa = 0.0;
  bool AnyDigit = false;
  while (P < End && isDigit(*P)) {
    Mantissa *= 10;
    Mantissa += static_cast<int>(*P++ - '0');
    AnyDigit = true;
  }
  if (P < End && *P == '.') {
    ++P;
    for (int Read = 1; P < End && isDigit(*P); ++Read, ++P) {
      Mantissa += static_cast<int>(*P - '0') * (Read < 8 ? Tenths[Read] : std::pow(10.0, -Read));
      AnyDigit = true;
    }
  }
  if (!AnyDigit)
    return false;
  int Exponent = 0;
  if (P < End && (*P == 'e' || *P == 'E')) {
    ++P;
    bool NegativeExp = false;
    if (P < End && (*P == '+' || *P == '-'))
      NegativeExp = *P++ == '-';
    if (P == End || !isDigit(*P))
      return false;
    for (; P < End && isDigit(*P); ++P)
      Exponent = std::min(10 * Exponent + (*P - '0'), 100000); // far past any float
    Exponent = NegativeExp ? -Exponent : Exponent;
  }
  if (P != End)
    return false;
  double V = (Negative ? -1 : 1) *
             (Exponent ? std::ldexp(Mantissa * std::pow(5.0, Exponent), Exponent) : Mantissa);
  if (!texcc::fitsInFloat(V)) // also NaN (0e999: 0 * inf)
    return false;
  Out = static_cast<float>(V);
  return true;
}

/// One index of a corner, [P, End) its digits ([+-]?digits), zero-based as OBJ defines it (a
/// negative one counts back from the N elements read so far); false when it is not one or 0.
bool parseIndex(const char *P, const char *End, int N, int &Out) {
  bool Negative = P < End && *P == '-';
  if (P < End && (*P == '-' || *P == '+'))
    ++P;
  if (P == End || End - P > 9)
    return false;
  int V = 0;
  for (; P < End; ++P) {
    if (!isDigit(*P))
      return false;
    V = 10 * V + (*P - '0');
  }
  if (V == 0)
    return false;
  Out = Negative ? N - V : V - 1;
  return true;
}

/// A token for a message: control bytes (a NUL, a lone CR ...) as \xNN.
std::string printable(const char *P, const char *End) {
  std::string Out;
  for (; P < End; ++P) {
    if (static_cast<unsigned char>(*P) < 0x20 || *P == 0x7f) {
      char Buf[8];
      std::snprintf(Buf, sizeof Buf, "\\x%02x", static_cast<unsigned char>(*P));
      Out += Buf;
    } else {
      Out += *P;
    }
  }
  return Out;
}

struct Reader {
  const std::string &Path;
  ObjText &Out;
  size_t Line = 0;
  std::vector<ObjCorner> Poly;
  std::vector<size_t> Quads; // where in Out.Corners each quad's two triangles start
  size_t LastTangentLine = 0;

  [[noreturn]] void fail(const std::string &What) const {
    throw Error(Path + ":" + std::to_string(Line) + ": invalid OBJ: " + What);
  }

  /// Every number of [P, End) up to a '#', each token checked finite; Take(Count, F) gets each
  /// in turn (Count: the ones before it).
  template <typename TakeFn> size_t readNumbers(const char *P, const char *End, TakeFn Take) {
    size_t Count = 0;
    while (true) {
      while (P < End && isBlank(*P))
        ++P;
      if (P == End || *P == '#')
        return Count;
      const char *Token = P;
      while (P < End && !isBlank(*P))
        ++P;
      float F;
      if (!parseNumber(Token, P, F))
        fail("'" + printable(Token, P) + "' is not a finite number");
      Take(Count++, F);
    }
  }

  /// The numbers of a v, vn or vt line: the first Keep appended (0 for missing ones).
  void numbers(const char *P, const char *End, size_t Keep, std::vector<float> &To) {
    size_t Count = readNumbers(P, End, [&](size_t I, float F) {
      if (I < Keep)
        To.push_back(F);
    });
    for (; Count < Keep; ++Count)
      To.push_back(0.0f);
  }

  /// A vtan line: x y z w, exactly four finite numbers, w (the bitangent sign) 1 or -1.
  void tangent(const char *P, const char *End) {
    LastTangentLine = Line;
    float V[4];
    size_t Count = readNumbers(P, End, [&](size_t I, float F) {
      if (I == 4)
        fail("vtan has more than four numbers (x y z w: the tangent and the bitangent sign)");
      V[I] = F;
    });
    if (Count < 4)
      fail("vtan has " + std::to_string(Count) +
           " numbers; it needs four: x y z w (the tangent and the bitangent sign)");
    if (V[3] != 1.0f && V[3] != -1.0f) {
      char Buf[48];
      std::snprintf(Buf, sizeof Buf, "%g", V[3]);
      fail(std::string("vtan's bitangent sign w is ") + Buf + "; it must be 1 or -1");
    }
    Out.Tangents.insert(Out.Tangents.end(), V, V + 4);
  }

  /// Every vn has its vtan, once the file is read (a file without vtan has no tangents).
  void checkTangents() {
    const size_t NT = Out.Tangents.size() / 4, NN = Out.Normals.size() / 3;
    if (NT == 0 || NT == NN)
      return;
    Line = LastTangentLine;
    fail("the file has " + std::to_string(NT) + " vtan and " + std::to_string(NN) +
         " vn; each vn needs its vtan (the tangent of the vn of the same index)");
  }

  void face(const char *P, const char *End) {
    Poly.clear();
    const int NV = int(Out.Positions.size() / 3), NN = int(Out.Normals.size() / 3),
              NT = int(Out.TexCoords.size() / 2);
    while (true) {
      while (P < End && isBlank(*P))
        ++P;
      if (P == End)
        break;
      const char *Token = P;
      while (P < End && !isBlank(*P))
        ++P;
      const char *S1 = static_cast<const char *>(std::memchr(Token, '/', size_t(P - Token)));
      const char *S2 =
          S1 ? static_cast<const char *>(std::memchr(S1 + 1, '/', size_t(P - S1 - 1))) : nullptr;
      ObjCorner C;
      bool Ok = parseIndex(Token, S1 ? S1 : P, NV, C.V);
      if (Ok && S1 && (S2 ? S2 > S1 + 1 : true))
        Ok = parseIndex(S1 + 1, S2 ? S2 : P, NT, C.T); // v/t or v/t/n
      if (Ok && S2)
        Ok = parseIndex(S2 + 1, P, NN, C.N);
      if (!Ok)
        fail("face corner '" + printable(Token, P) +
             "' is not v, v/t, v//n or v/t/n with non-zero indices");
      Poly.push_back(C);
    }
    if (Poly.size() < 3)
      return; // no area: skipped
    if (Poly.size() == 4)
      Quads.push_back(Out.Corners.size()); // split once every vertex is known
    if (Poly.size() == 4) {
      for (int K : {0, 1, 2, 0, 2, 3})
        Out.Corners.push_back(Poly[size_t(K)]);
      return;
    }
    for (size_t K = 1; K + 1 < Poly.size(); ++K) {
      Out.Corners.push_back(Poly[0]);
      Out.Corners.push_back(Poly[K]);
      Out.Corners.push_back(Poly[K + 1]);
    }
  }

  /// A quad [0, 1, 2, 3] becomes [0, 1, 2] [0, 2, 3] when the diagonal 0-2 is the shorter, else
  /// [0, 1, 3] [1, 2, 3] (tinyobjloader's rule, its float arithmetic); a quad with a vertex out
  /// of range is left for readFace's error.
  void splitQuads() {
    const std::vector<float> &V = Out.Positions;
    for (size_t At : Quads) {
      ObjCorner Q[4] = {Out.Corners[At], Out.Corners[At + 1], Out.Corners[At + 2],
                        Out.Corners[At + 5]};
      bool InRange = true;
      for (const ObjCorner &C : Q)
        InRange &= C.V >= 0 && 3 * size_t(C.V) + 2 < V.size();
      if (!InRange)
        continue;
      const float *P0 = &V[3 * size_t(Q[0].V)], *P1 = &V[3 * size_t(Q[1].V)],
                  *P2 = &V[3 * size_t(Q[2].V)], *P3 = &V[3 * size_t(Q[3].V)];
      float E02x = P2[0] - P0[0], E02y = P2[1] - P0[1], E02z = P2[2] - P0[2];
      float E13x = P3[0] - P1[0], E13y = P3[1] - P1[1], E13z = P3[2] - P1[2];
      float Sqr02 = E02x * E02x + E02y * E02y + E02z * E02z;
      float Sqr13 = E13x * E13x + E13y * E13y + E13z * E13z;
      if (Sqr02 < Sqr13)
        continue; // as placed
      const int Order[6] = {0, 1, 3, 1, 2, 3};
      for (int K = 0; K < 6; ++K)
        Out.Corners[At + size_t(K)] = Q[Order[K]];
    }
  }
};

} // namespace

ObjText parseObj(const std::string &Path, const std::string &Text) {
  ObjText Out;
  Reader R{Path, Out, 0, {}, {}};
  const char *P = Text.data(), *TextEnd = P + Text.size();
  Out.Positions.reserve(Text.size() / 32), Out.Corners.reserve(Text.size() / 32);
  const char *NL = nullptr; // the next '\n' (or the end) at or after P
  while (P < TextEnd) {
    // The line: up to '\n', "\r\n" or a lone '\r'.
    if (!NL || NL < P) {
      NL = static_cast<const char *>(std::memchr(P, '\n', size_t(TextEnd - P)));
      if (!NL)
        NL = TextEnd;
    }
    const char *End = NL;
    const char *CR = static_cast<const char *>(std::memchr(P, '\r', size_t(End - P)));
    const char *Next;
    if (CR && CR + 1 == End && End < TextEnd) // "\r\n"
      Next = End + 1, End = CR;
    else if (CR) // a lone '\r'
      End = CR, Next = CR + 1;
    else
      Next = End < TextEnd ? End + 1 : TextEnd;
    ++R.Line;
    while (P < End && isBlank(*P))
      ++P;
    if (P + 1 < End && P[0] == 'v' && isBlank(P[1]))
      R.numbers(P + 2, End, 3, Out.Positions);
    else if (P + 2 < End && P[0] == 'v' && P[1] == 'n' && isBlank(P[2]))
      R.numbers(P + 3, End, 3, Out.Normals);
    else if (P + 2 < End && P[0] == 'v' && P[1] == 't' && isBlank(P[2]))
      R.numbers(P + 3, End, 2, Out.TexCoords);
    else if (End - P >= 4 && std::memcmp(P, "vtan", 4) == 0 && (End - P == 4 || isBlank(P[4])))
      R.tangent(P + 4, End);
    else if (P + 1 < End && P[0] == 'f' && isBlank(P[1]))
      R.face(P + 2, End);
    P = Next;
  }
  R.splitQuads();
  R.checkTangents();
  return Out;
}

static TriangleMesh readObj(const std::string &Path);

TriangleMesh loadObj(const std::string &Path) {
  const std::string Step = "loading OBJ '" + Path + "'";
  return texcc::whileAllocating(Step.c_str(), [&] { return readObj(Path); });
}

static TriangleMesh readObj(const std::string &Path) {
  const ObjText A = parseObj(Path, readMaybeGzipped(Path));
  const size_t Corners = A.Corners.size();
  TriangleMesh M;
  M.Positions.reserve(Corners), M.Normals.reserve(Corners), M.UVs.reserve(Corners);
  const bool Tangents = !A.Tangents.empty();
  if (Tangents)
    M.Tangents.reserve(Corners);
  std::vector<int> PosIndex;
  PosIndex.reserve(Corners);
  std::vector<bool> HasNormals;
  HasNormals.reserve(Corners / 3);
  size_t Degenerate = 0;
  for (size_t F = 0; F + 2 < Corners; F += 3) {
    Face Fc = readFace(A, &A.Corners[F], Path);
    const bool FileNormals = Fc.FileNormals;
    const Vec3 *P = Fc.P, *N = Fc.N;
    const Vec2 *UV = Fc.UV;
    // A zero-area face is never hit, has no normal, and as a light would have an infinite
    // sampling density: drop it.
    Vec3 Area = cross(sub(P[1], P[0]), sub(P[2], P[0]));
    if (!(dot(Area, Area) > 0)) {
      ++Degenerate;
      continue;
    }
    int Order[3] = {0, 1, 2};
    if (FileNormals) {
      // The winding defines the front (the emitting side of an area light); make it agree
      // with the normals the file gives.
      Vec3 Fn = cross(sub(P[1], P[0]), sub(P[2], P[0]));
      Vec3 Sum = {N[0][0] + N[1][0] + N[2][0], N[0][1] + N[1][1] + N[2][1],
                  N[0][2] + N[1][2] + N[2][2]};
      if (dot(Fn, Sum) < 0)
        Order[1] = 2, Order[2] = 1;
    }
    for (int C : Order) {
      M.Positions.push_back(P[C]);
      M.Normals.push_back(FileNormals ? N[C] : Vec3{0, 0, 0});
      M.UVs.push_back(UV[C]);
      if (Tangents) // a face without normals has none
        M.Tangents.push_back(FileNormals ? Fc.T[C] : Vec4{0, 0, 0, 0});
      PosIndex.push_back(A.Corners[F + size_t(C)].V);
    }
    HasNormals.push_back(FileNormals);
  }
  if (M.Positions.empty() && Degenerate > 0)
    throw Error(Path + ": OBJ file has no faces of non-zero area (" + std::to_string(Degenerate) +
                " degenerate)");
  if (M.Positions.empty())
    throw Error(Path + ": OBJ file has no faces");
  generateNormals(M, PosIndex, HasNormals);
  return M;
}

} // namespace texrender
