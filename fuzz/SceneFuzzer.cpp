// fuzz-scene: scene.json text through texrender's loadScene (camera, film, render settings,
// lights, meshes, transforms). loadScene reads a path, so each input is written to a file in a
// private temporary folder first; texrender::Error is the expected way to reject an input,
// any other exception escapes and is a finding.
#include "FuzzFile.h"

#include "texrender/Error.h"
#include "texrender/Scene.h"

#include <cstdint>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t *Data, size_t Size) {
  static const texcc::fuzz::ScratchFile File("scene.json");
  File.write(Data, Size);
  try {
    texrender::Scene S = texrender::loadScene(File.path());
    (void)S;
  } catch (const texrender::Error &) {
  }
  return 0;
}
