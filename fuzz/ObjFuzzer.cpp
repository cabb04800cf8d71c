// fuzz-obj: OBJ text (or gzip data: loadObj accepts both) through texrender's loadObj: its
// one-pass OBJ reader (parseObj), triangulation, index checks, winding and generated normals.
// texrender::Error is the expected rejection; anything else is a finding.
#include "FuzzFile.h"

#include "texrender/Error.h"
#include "texrender/Scene.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *Data, size_t Size) {
  // Very long files only slow the search (normals generation is O(n log n) in triangles).
  if (Size > 65536)
    return -1;
  static const texcc::fuzz::ScratchFile File("mesh.obj");
  File.write(Data, Size);
  try {
    texrender::TriangleMesh M = texrender::loadObj(File.path());
    (void)M;
  } catch (const texrender::Error &) {
  }
  return 0;
}
