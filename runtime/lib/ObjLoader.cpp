// OBJ loading through tinyobjloader, with gzip support (zlib) and generated normals.
#include "texrender/Error.h"
#include "texrender/Scene.h"
#include "texcc/OutOfMemory.h"
#include "texcc/Support/File.h"
#include "texcc/Support/Numbers.h"

#include <tiny_obj_loader.h>
#include <zlib.h>

#include <algorithm>
#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <optional>
#include <sstream>

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

/// Blanks the `vw` (skin weight) lines, keeping their line breaks so that tinyobjloader's line
/// numbers stay right. They are a tinyobjloader extension that texrender never reads, and its
/// parser converts their joint ids from float to int unchecked: "vw 0 1e38 1" is undefined
/// behaviour inside it (found by fuzz-obj). Lines end at '\n' or '\r', as tinyobjloader's do.
void blankSkinWeightLines(std::string &Text) {
  size_t Begin = 0;
  while (Begin < Text.size()) {
    size_t End = Text.find_first_of("\r\n", Begin);
    if (End == std::string::npos)
      End = Text.size();
    size_t First = Text.find_first_not_of(" \t", Begin);
    if (First != std::string::npos && First + 2 < End && Text.compare(First, 2, "vw") == 0 &&
        (Text[First + 2] == ' ' || Text[First + 2] == '\t'))
      Text.replace(Begin, End - Begin, End - Begin, ' ');
    Begin = End + 1;
  }
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

/// tinyobjloader reads a coordinate it cannot parse ("nan", "x") as 0 and one too large for a
/// float as infinity, silently. Every number of the v, vn and vt lines must be a finite float.
void checkVertexNumbers(const std::string &Path, const std::string &Text) {
  size_t LineNo = 0;
  for (size_t Pos = 0; Pos < Text.size();) {
    size_t End = Text.find('\n', Pos);
    if (End == std::string::npos)
      End = Text.size();
    ++LineNo;
    const char *P = Text.c_str() + Pos, *Stop = Text.c_str() + End;
    while (P < Stop && (*P == ' ' || *P == '\t'))
      ++P;
    bool Vertex = P + 1 < Stop && P[0] == 'v' &&
                  (P[1] == ' ' || P[1] == '\t' ||
                   ((P[1] == 'n' || P[1] == 't') && P + 2 < Stop && (P[2] == ' ' || P[2] == '\t')));
    for (P += Vertex ? (P[1] == ' ' || P[1] == '\t' ? 1 : 2) : 0; Vertex && P < Stop;) {
      while (P < Stop && (*P == ' ' || *P == '\t' || *P == '\r'))
        ++P;
      if (P >= Stop || *P == '#')
        break;
      const char *Token = P;
      while (P < Stop && *P != ' ' && *P != '\t' && *P != '\r')
        ++P;
      std::string Word(Token, P);
      char *NumEnd = nullptr;
      double D = std::strtod(Word.c_str(), &NumEnd);
      if (NumEnd != Word.c_str() + Word.size() || !texcc::fitsInFloat(D))
        throw Error(Path + ":" + std::to_string(LineNo) + ": invalid OBJ: '" + Word +
                    "' is not a finite number");
    }
    Pos = End + 1;
  }
}

std::string formatVec3(const Vec3 &V) {
  char Buf[96];
  std::snprintf(Buf, sizeof Buf, "%g, %g, %g", V[0], V[1], V[2]);
  return Buf;
}

/// Whether a face corner gives an optional index (tinyobjloader: -1 when it does not) into an
/// array of Tuple floats each; an index to a missing element is an error (it used to be skipped
/// silently, unlike a bad vertex index).
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
  bool FileNormals = true;
};

Face readFace(const tinyobj::attrib_t &A, const tinyobj::index_t *Idx, const std::string &Path) {
  Face Fc;
  for (int C = 0; C < 3; ++C) {
    const tinyobj::index_t &I = Idx[C];
    if (I.vertex_index < 0 || 3 * size_t(I.vertex_index) + 2 >= A.vertices.size())
      throw Error(Path + ": invalid OBJ: vertex index out of range");
    Fc.P[C] = {A.vertices[3 * I.vertex_index], A.vertices[3 * I.vertex_index + 1],
               A.vertices[3 * I.vertex_index + 2]};
    if (!std::isfinite(Fc.P[C][0]) || !std::isfinite(Fc.P[C][1]) || !std::isfinite(Fc.P[C][2]))
      throw Error(Path + ": invalid OBJ: vertex " + std::to_string(I.vertex_index + 1) +
                  " has a non-finite coordinate (" + formatVec3(Fc.P[C]) + ")");
    if (hasIndex(I.normal_index, 3, A.normals.size(), Path, "normal"))
      Fc.N[C] = normalized({A.normals[3 * I.normal_index], A.normals[3 * I.normal_index + 1],
                            A.normals[3 * I.normal_index + 2]});
    else
      Fc.FileNormals = false;
    Fc.UV[C] = {0, 0};
    if (hasIndex(I.texcoord_index, 2, A.texcoords.size(), Path, "texture coordinate"))
      Fc.UV[C] = {A.texcoords[2 * I.texcoord_index], A.texcoords[2 * I.texcoord_index + 1]};
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

// --- The fast reader --------------------------------------------------------------------------
//
// Most OBJ files (every one texrender's scripts and Blender exporter write) use a small part of
// the format: v/vn/vt lines with plain decimal numbers, triangles, comments, g/o/s/usemtl/mtllib.
// The fast reader parses exactly that part in one pass over the text; on anything else (another
// statement, a polygon, an unusual number or index, a stray '\r', or any input the full reader
// would reject) it declines, and the full reader (tinyobjloader with texrender's checks before
// it) reads the file as before. Where it accepts, it gives what tinyobjloader gives, bit for bit:
// the same vertex arrays (numbers converted with tinyobjloader's own arithmetic, which is not
// correctly rounded: a correctly rounded conversion would move some coordinates by an ulp and
// change images) and the same face indices (its index rules), so the mesh built from them is
// the same (testsuite: ObjFast gtests compare the two on every construct).

bool isBlank(char C) { return C == ' ' || C == '\t'; }
bool isDigit(char C) { return C >= '0' && C <= '9'; }

/// One number of a v, vn or vt line, [P, End) the line's rest; on success *Out is the float
/// tinyobjloader computes for it and P is past it. Accepted: sign? (digits ('.' digits*)? |
/// '.' digits) ([eE] sign? digits{1,3})?, whose value (and so strtod's) is a finite float.
bool fastNumber(const char *&P, const char *End, float &Out) {
  static const double Tenths[] = {1.0, 0.1, 0.01, 0.001, 0.0001, 0.00001, 0.000001, 0.0000001};
  const char *Q = P;
  bool Negative = false;
  if (Q < End && (*Q == '+' || *Q == '-'))
    Negative = *Q++ == '-';
  double Mantissa = 0.0;
  bool AnyDigit = false;
  while (Q < End && isDigit(*Q)) {
    Mantissa *= 10;
    Mantissa += static_cast<int>(*Q++ - '0');
    AnyDigit = true;
  }
  if (Q < End && *Q == '.') {
    ++Q;
    for (int Read = 1; Q < End && isDigit(*Q); ++Read, ++Q) {
      Mantissa += static_cast<int>(*Q - '0') * (Read < 8 ? Tenths[Read] : std::pow(10.0, -Read));
      AnyDigit = true;
    }
  }
  if (!AnyDigit)
    return false;
  int Exponent = 0;
  if (Q < End && (*Q == 'e' || *Q == 'E')) {
    ++Q;
    bool NegativeExp = false;
    if (Q < End && (*Q == '+' || *Q == '-'))
      NegativeExp = *Q++ == '-';
    int Digits = 0;
    for (; Q < End && isDigit(*Q); ++Q, ++Digits)
      Exponent = 10 * Exponent + (*Q - '0');
    if (Digits == 0 || Digits > 3)
      return false;
    Exponent = NegativeExp ? -Exponent : Exponent;
  }
  if (Q < End && !isBlank(*Q))
    return false; // the token goes on ("1.5x", "1e5.5", "nan", a '\r' or NUL ...)
  double V = (Negative ? -1 : 1) *
             (Exponent ? std::ldexp(Mantissa * std::pow(5.0, Exponent), Exponent) : Mantissa);
  if (!(std::fabs(V) < 1e38))
    return false; // near or past FLT_MAX: the full reader's check decides
  Out = static_cast<float>(V);
  P = Q;
  return true;
}

/// Count numbers (Count..MaxCount) separated by blanks up to the line's end, appended to Out.
bool fastNumbers(const char *P, const char *End, size_t Count, size_t MaxCount,
                 std::vector<float> &Out) {
  for (size_t I = 0;; ++I) {
    while (P < End && isBlank(*P))
      ++P;
    if (P == End)
      return I >= Count;
    float F;
    if (I == MaxCount || !fastNumber(P, End, F))
      return false;
    if (I < Count)
      Out.push_back(F);
  }
}

/// One OBJ index (-?[1-9 digits]{1,9}, not 0) made zero-based as tinyobjloader does: a
/// negative one counts back from the N elements read so far.
bool fastIndex(const char *&P, const char *End, int N, int &Out) {
  bool Negative = P < End && *P == '-';
  P += Negative;
  int V = 0, Digits = 0;
  for (; P < End && isDigit(*P) && Digits < 9; ++P, ++Digits)
    V = 10 * V + (*P - '0');
  if (Digits == 0 || (P < End && isDigit(*P)) || V == 0)
    return false; // index 0 is an error the full reader reports with its line
  Out = Negative ? N - V : V - 1;
  return true;
}

/// A face line's corners (exactly three: v, v/t, v//n or v/t/n each), appended to Idx.
bool fastFace(const char *P, const char *End, const tinyobj::attrib_t &A,
              std::vector<tinyobj::index_t> &Idx) {
  const int NV = int(A.vertices.size() / 3), NN = int(A.normals.size() / 3),
            NT = int(A.texcoords.size() / 2);
  for (int C = 0;; ++C) {
    while (P < End && isBlank(*P))
      ++P;
    if (P == End)
      return C == 3;
    if (C == 3)
      return false; // a polygon: tinyobjloader's triangulation, in the full reader
    tinyobj::index_t I;
    I.vertex_index = I.normal_index = I.texcoord_index = -1;
    if (!fastIndex(P, End, NV, I.vertex_index))
      return false;
    if (P < End && *P == '/') {
      ++P;
      if (P < End && *P != '/' && !fastIndex(P, End, NT, I.texcoord_index))
        return false;
      if (P < End && *P == '/') {
        ++P;
        if (!fastIndex(P, End, NN, I.normal_index))
          return false;
      } else if (I.texcoord_index == -1) {
        return false; // "v/" with nothing after
      }
    }
    if (P < End && !isBlank(*P))
      return false;
    Idx.push_back(I);
  }
}

bool startsWord(const char *P, const char *End, const char *Word) {
  size_t N = std::strlen(Word);
  return size_t(End - P) >= N && std::memcmp(P, Word, N) == 0 && (P + N == End || isBlank(P[N]));
}

/// The fast reader over the whole text; false: declined (the full reader reads it).
bool readFast(const std::string &Text, tinyobj::attrib_t &A, std::vector<tinyobj::index_t> &Idx) {
  const char *P = Text.data(), *TextEnd = P + Text.size();
  // About 30 bytes a line: reserving from the size saves most reallocations of big files.
  A.vertices.reserve(Text.size() / 32), Idx.reserve(Text.size() / 32);
  while (P < TextEnd) {
    const char *Eol = static_cast<const char *>(std::memchr(P, '\n', size_t(TextEnd - P)));
    if (!Eol)
      Eol = TextEnd;
    const char *End = Eol > P && Eol[-1] == '\r' ? Eol - 1 : Eol;
    const char *Next = Eol == TextEnd ? TextEnd : Eol + 1;
    while (P < End && isBlank(*P))
      ++P;
    bool Ok = true;
    if (P == End) {
      // blank line
    } else if (*P == 'v' && End - P > 1 && isBlank(P[1])) {
      Ok = fastNumbers(P + 2, End, 3, 3, A.vertices);
    } else if (*P == 'v' && End - P > 2 && P[1] == 'n' && isBlank(P[2])) {
      Ok = fastNumbers(P + 3, End, 3, 3, A.normals);
    } else if (*P == 'v' && End - P > 2 && P[1] == 't' && isBlank(P[2])) {
      Ok = fastNumbers(P + 3, End, 2, 3, A.texcoords); // a third (w) is read and dropped
    } else if (*P == 'f' && End - P > 1 && isBlank(P[1])) {
      Ok = fastFace(P + 2, End, A, Idx);
    } else if (*P == '#' || startsWord(P, End, "g") || startsWord(P, End, "o") ||
               startsWord(P, End, "s") || startsWord(P, End, "usemtl") ||
               startsWord(P, End, "mtllib")) {
      // Nothing the mesh uses; a '\r' or NUL inside would end or cut the line differently.
      Ok = !std::memchr(P, '\r', size_t(End - P)) && !std::memchr(P, '\0', size_t(End - P));
    } else {
      Ok = false;
    }
    if (!Ok)
      return false;
    P = Next;
  }
  return true;
}

/// The mesh of the faces Idx[0, N) (corners, three a triangle) over A: zero-area faces are
/// dropped, the winding made to agree with the file's normals.
void appendFaces(const tinyobj::attrib_t &A, const tinyobj::index_t *Idx, size_t N,
                 const std::string &Path, TriangleMesh &M, std::vector<int> &PosIndex,
                 std::vector<bool> &HasNormals, size_t &Degenerate) {
  for (size_t F = 0; F + 2 < N; F += 3) {
    Face Fc = readFace(A, &Idx[F], Path);
    const bool FileNormals = Fc.FileNormals;
    const Vec3 *P = Fc.P, *Nr = Fc.N;
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
      Vec3 Sum = {Nr[0][0] + Nr[1][0] + Nr[2][0], Nr[0][1] + Nr[1][1] + Nr[2][1],
                  Nr[0][2] + Nr[1][2] + Nr[2][2]};
      if (dot(Fn, Sum) < 0)
        Order[1] = 2, Order[2] = 1;
    }
    for (int C : Order) {
      M.Positions.push_back(P[C]);
      M.Normals.push_back(FileNormals ? Nr[C] : Vec3{0, 0, 0});
      M.UVs.push_back(UV[C]);
      PosIndex.push_back(Idx[F + C].vertex_index);
    }
    HasNormals.push_back(FileNormals);
  }
}

} // namespace

static TriangleMesh readObj(const std::string &Path);

TriangleMesh loadObj(const std::string &Path) {
  const std::string Step = "loading OBJ '" + Path + "'";
  return texcc::whileAllocating(Step.c_str(), [&] { return readObj(Path); });
}

static TriangleMesh readObj(const std::string &Path) {
  std::string Text = readMaybeGzipped(Path);
  if (std::optional<TriangleMesh> M = objFromTextFast(Path, Text))
    return std::move(*M);
  return objFromTextFull(Path, std::move(Text));
}

/// The mesh of the faces (one index list a shape), normals generated where the file gave none.
static TriangleMesh meshOf(const std::string &Path, const tinyobj::attrib_t &A,
                           const std::vector<std::pair<const tinyobj::index_t *, size_t>> &Shapes) {
  size_t Corners = 0;
  for (const auto &S : Shapes)
    Corners += S.second;
  TriangleMesh M;
  M.Positions.reserve(Corners), M.Normals.reserve(Corners), M.UVs.reserve(Corners);
  std::vector<int> PosIndex;
  PosIndex.reserve(Corners);
  std::vector<bool> HasNormals;
  HasNormals.reserve(Corners / 3);
  size_t Degenerate = 0;
  for (const auto &S : Shapes)
    appendFaces(A, S.first, S.second, Path, M, PosIndex, HasNormals, Degenerate);
  if (M.Positions.empty() && Degenerate > 0)
    throw Error(Path + ": OBJ file has no faces of non-zero area (" + std::to_string(Degenerate) +
                " degenerate)");
  if (M.Positions.empty())
    throw Error(Path + ": OBJ file has no faces");
  generateNormals(M, PosIndex, HasNormals);
  return M;
}

std::optional<TriangleMesh> objFromTextFast(const std::string &Path, const std::string &Text) {
  tinyobj::attrib_t A;
  std::vector<tinyobj::index_t> Idx;
  if (!readFast(Text, A, Idx))
    return std::nullopt;
  return meshOf(Path, A, {{Idx.data(), Idx.size()}});
}

TriangleMesh objFromTextFull(const std::string &Path, std::string Text) {
  checkVertexNumbers(Path, Text);
  blankSkinWeightLines(Text);
  tinyobj::ObjReaderConfig Cfg;
  Cfg.triangulate = true;
  Cfg.vertex_color = false;
  tinyobj::ObjReader Reader;
  if (!Reader.ParseFromString(Text, "", Cfg)) {
    std::string E = Reader.Error();
    while (!E.empty() && E.back() == '\n')
      E.pop_back();
    throw Error(Path + ": invalid OBJ: " + E);
  }
  std::vector<std::pair<const tinyobj::index_t *, size_t>> Shapes;
  for (const auto &Shape : Reader.GetShapes())
    Shapes.push_back({Shape.mesh.indices.data(), Shape.mesh.indices.size()});
  return meshOf(Path, Reader.GetAttrib(), Shapes);
}

} // namespace texrender
