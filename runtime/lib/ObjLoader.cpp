// OBJ loading through tinyobjloader, with gzip support (zlib) and generated normals.
#include "texrender/Error.h"
#include "texrender/Scene.h"
#include "texcc/OutOfMemory.h"
#include "texcc/Support/File.h"
#include "texcc/Support/Numbers.h"

#include <tiny_obj_loader.h>
#include <zlib.h>

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
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
  std::string Out;
  char Buf[1 << 16];
  int N;
  while ((N = gzread(F, Buf, sizeof Buf)) > 0)
    Out.append(Buf, N);
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
void generateNormals(TriangleMesh &M, const std::vector<int> &PosIndex,
                     const std::vector<bool> &HasNormals) {
  size_t NT = M.triangleCount();
  std::vector<Vec3> FaceN(NT); // area-weighted
  std::map<int, std::vector<size_t>> Adj;
  for (size_t T = 0; T < NT; ++T) {
    FaceN[T] = cross(sub(M.Positions[3 * T + 1], M.Positions[3 * T]),
                     sub(M.Positions[3 * T + 2], M.Positions[3 * T]));
    for (int C = 0; C < 3; ++C)
      Adj[PosIndex[3 * T + C]].push_back(T);
  }
  const float CosCrease = 0.5f;
  for (size_t T = 0; T < NT; ++T) {
    if (HasNormals[T])
      continue;
    Vec3 Own = normalized(FaceN[T]);
    for (int C = 0; C < 3; ++C) {
      Vec3 Sum{0, 0, 0};
      for (size_t O : Adj[PosIndex[3 * T + C]])
        if (dot(normalized(FaceN[O]), Own) >= CosCrease)
          for (int K = 0; K < 3; ++K)
            Sum[K] += FaceN[O][K];
      Vec3 N = normalized(Sum);
      M.Normals[3 * T + C] = dot(N, N) > 0 ? N : Own;
    }
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
  const auto &A = Reader.GetAttrib();
  TriangleMesh M;
  std::vector<int> PosIndex;
  std::vector<bool> HasNormals;
  size_t Degenerate = 0;
  for (const auto &Shape : Reader.GetShapes()) {
    const auto &Idx = Shape.mesh.indices;
    for (size_t F = 0; F + 2 < Idx.size(); F += 3) {
      Face Fc = readFace(A, &Idx[F], Path);
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
        PosIndex.push_back(Idx[F + C].vertex_index);
      }
      HasNormals.push_back(FileNormals);
    }
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
