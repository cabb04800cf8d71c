#include "texrender/Renderer.h"
#include "texrender/Error.h"
#include "texrender/Image.h"
#include "texrender/SlowStep.h"
#include "texrender/TextureTiers.h"
#include "texcc/Kernel/Attributes.h"

#include <algorithm>
#include <cfloat>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <unistd.h>

namespace fs = std::filesystem;

namespace texrender {

namespace {

/// The text of every shared header: part of the program-cache key of every kernel.
std::string headersDigest(const std::string &Dir) {
  std::vector<fs::path> Files;
  for (auto &E : fs::directory_iterator(fs::path(Dir) / "common"))
    if (E.path().extension() == ".h")
      Files.push_back(E.path());
  std::sort(Files.begin(), Files.end());
  std::string All;
  for (auto &F : Files)
    All += readKernelSource(F.string());
  return All;
}

struct KernelFile {
  const char *File;
  std::vector<const char *> Kernels;
};

const std::vector<KernelFile> &fixedKernels() {
  static const std::vector<KernelFile> Files = {
      {"raygen.cl", {"raygen"}},       {"closest_hit.cl", {"closest_hit"}},
      {"hit_attributes.cl", {"hit_attributes"}}, {"ao.cl", {"ao_trace", "ao_reduce", "ao_loop", "ao_rays"}},
      {"shade.cl", {"shade"}},         {"shadow.cl", {"shadow"}},
      {"compact.cl", {"compact"}},     {"accumulate.cl", {"accumulate"}}};
  return Files;
}

template <typename T> size_t bytes(const std::vector<T> &V) { return V.size() * sizeof(T); }

double now() {
  return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

} // namespace

/// The texture kernels' settings (readSetting, and bump's footprint) for an image of
/// Width x Height pixels: the one place they are filled. pixelAngle is the film's pixel pitch
/// at unit distance, 2 tan(fov / 2) / width along the fov's axis (makeCamera's right vector
/// spans half the film's width), so the bump step follows the image size and the fov; the
/// camera's unit axes place a hit on the film (the step shrinks off the centre).
TexccSettings textureSettings(const Scene &S, const RenderSettings &R) {
  const RtCamera Cam = makeCamera(S.Cam, R.Width, R.Height);
  TexccSettings Set{};
  Set.cameraPos = {{S.Cam.Position[0], S.Cam.Position[1], S.Cam.Position[2], 0}};
  Set.time = R.Time, Set.frame = R.Frame;
  const float Half = std::sqrt(Cam.right.s[0] * Cam.right.s[0] + Cam.right.s[1] * Cam.right.s[1] +
                               Cam.right.s[2] * Cam.right.s[2]);
  Set.pixelAngle = 2.0f * Half / float(std::max(R.Width, 1));
  // The camera's unit axes: where a hit lies on the film (the footprint off the centre).
  const auto Unit = [](const cl_float4 &V) {
    const float L = std::sqrt(V.s[0] * V.s[0] + V.s[1] * V.s[1] + V.s[2] * V.s[2]);
    return L > 0.0f ? cl_float4{{V.s[0] / L, V.s[1] / L, V.s[2] / L, 0.0f}} : cl_float4{};
  };
  Set.cameraForward = Unit(Cam.forward);
  Set.cameraRight = Unit(Cam.right);
  Set.cameraUp = Unit(Cam.up);
  return Set;
}

uint32_t attributeMaskOf(const Layout &L) {
  uint32_t Mask = 0;
  for (const std::string &A : L.Attributes) {
    const int Id = texcc::kernel::attributeId(A);
    if (Id < 0)
      throw Error(L.Dir + "/layout.json: /attributes: unknown attribute '" + A + "'");
    Mask |= 1u << Id;
  }
  return Mask;
}

std::string kernelDirectory() {
  if (const char *E = std::getenv("TEXRENDER_KERNELS"); E && *E)
    return E;
  std::error_code EC;
  fs::path Exe = fs::read_symlink("/proc/self/exe", EC);
  if (!EC) {
    for (fs::path C : {Exe.parent_path().parent_path() / "kernels", Exe.parent_path() / "kernels"})
      if (fs::exists(C / "raygen.cl"))
        return C.string();
  }
  throw Error("cannot find texrender's kernels (raygen.cl ...) next to the executable; set "
              "TEXRENDER_KERNELS to the kernels folder");
}

bool quickFirstBuildDefault() {
  const char *E = std::getenv("TEXRENDER_FIRST_BUILD");
  return !(E && std::string(E) == "optimised");
}

Renderer::Renderer(const Scene &S, const Layout &L, const RendererOptions &O)
    : SceneDesc(S), Lay(L), Opts(O), Settings(S.Render), Epoch(steadySeconds()) {
  KernelDir = Opts.KernelDir.empty() ? kernelDirectory() : Opts.KernelDir;
  if (Opts.Prebuilt) {
    Data = *Opts.Prebuilt;
    Opts.Prebuilt = nullptr; // not kept: the caller's may go
  } else {
    SlowStep Step("building the scene's acceleration structures");
    Data = buildSceneData(S, L);
  }
  Cl = std::make_unique<ClContext>(Opts.Device, Opts.CacheDir, Opts.Lane);
  // scripts/build.sh prebuilds the fixed kernels into build/programs, beside build/kernels;
  // $TEXRENDER_PREBUILT_DIR names another folder ("": none). --no-cache uses neither.
  if (!Opts.CacheDir.empty()) {
    const char *E = std::getenv("TEXRENDER_PREBUILT_DIR");
    Cl->setPrebuiltDir(E ? std::string(E)
                         : (fs::path(KernelDir).parent_path() / "programs").string());
  }
  try {
    {
      SlowStep Step("building the path tracer's kernels");
      buildFixedKernels();
    }
    uploadScene();
    const TraceContext Here{*Cl, K, B, Data};
    Tracer = Opts.PrebuiltTrace ? Opts.PrebuiltTrace->share(Here) : makeTrace(Opts.Trace, Here);
    Opts.PrebuiltTrace = nullptr; // not kept, as Prebuilt
    Tiers = std::make_unique<TierManager>(
        *Cl, Lay, Opts.Tier, Opts.InterpStackHeadroom, programOptions(), Epoch,
        [this](Layout &&New) {
          Lay = std::move(New);
          uploadLayoutData();
          return HasTextureWork;
        });
    Tiers->setQuickFirstBuild(Opts.QuickFirstBuild);
    uploadLayoutData();
    Tiers->build(HasTextureWork);
  } catch (const cl::Error &E) {
    throw Error(std::string("OpenCL call ") + E.what() + " failed: " + clErrorName(E.err()));
  }
}

Renderer::~Renderer() {
  Tiers.reset(); // waits for its background builds, which use Cl
}

std::string Renderer::programOptions() const {
  return "-cl-std=CL1.2 -I " + (fs::path(KernelDir) / "common").string();
}

void Renderer::buildFixedKernels() {
  std::string Digest = headersDigest(KernelDir);
  for (const KernelFile &F : fixedKernels()) {
    std::string Path = (fs::path(KernelDir) / F.File).string();
    // -cl-kernel-arg-info: warmUpAllKernels sets each argument by its kind.
    cl::Program P = Cl->buildProgram(Path, readKernelSource(Path),
                                     programOptions() + " -cl-kernel-arg-info", Digest,
                                     false, [this](const cl::Program &Q) { warmUpAllKernels(*Cl, Q); });
    for (const char *Name : F.Kernels)
      K[Name] = cl::Kernel(P, Name);
  }
}

void Renderer::uploadScene() {
  const cl_mem_flags RO = CL_MEM_READ_ONLY;
  B["bvhNodes"] = Cl->allocateWith("bvhNodes", Data.Tree.Nodes.data(), bytes(Data.Tree.Nodes), RO);
  B["triangles"] = Cl->allocateWith("triangles", Data.Tris.data(), bytes(Data.Tris), RO);
  B["triangleAttributes"] =
      Cl->allocateWith("triangleAttributes", Data.TriAttrs.data(), bytes(Data.TriAttrs), RO);
  B["meshes"] = Cl->allocateWith("meshes", Data.Meshes.data(), bytes(Data.Meshes), RO);
  B["lights"] = Cl->allocateWith("lights", Data.Lights.data(), bytes(Data.Lights), RO);
  B["lightCdf"] = Cl->allocateWith("lightCdf", Data.LightCdf.data(), bytes(Data.LightCdf), RO);
  B["envMap"] = Cl->allocateWith("envMap", Data.Env.Data.data(), bytes(Data.Env.Data), RO);
  B["camera"] = Cl->allocate("camera", sizeof(RtCamera), RO);
  B["shadeParams"] = Cl->allocate("shadeParams", sizeof(RtShadeParams), RO);
  B["counters"] = Cl->allocate("counters", RT_COUNT_SLOTS * sizeof(cl_uint), CL_MEM_READ_WRITE);
  B["activeCount"] = Cl->allocate("activeCount", sizeof(cl_int), CL_MEM_READ_WRITE);
}

void Renderer::mapMeshMaterials() {
  bool Changed = false;
  for (size_t I = 0; I < SceneDesc.Meshes.size() && I < Data.Meshes.size(); ++I) {
    const MeshInstance &Mi = SceneDesc.Meshes[I];
    int Mat = Lay.findMaterial(Mi.Material);
    if (Mat < 0)
      throw Error(SceneDesc.Path + ": " + Mi.JsonPath + "/material: the texture layout in use (" +
                  Lay.Dir + ") has no material '" + Mi.Material + "' (it has: " +
                  Lay.materialNames() + ")");
    Changed |= Data.Meshes[I].material != Mat;
    Data.Meshes[I].material = Mat;
  }
  if (Changed && B.count("meshes"))
    Cl->write(B["meshes"], Data.Meshes.data(), bytes(Data.Meshes));
}

void Renderer::uploadLayoutData() {
  buildMaterials(Lay, Data.Materials, Data.BsdfNodes);
  mapMeshMaterials();
  const cl_mem_flags RO = CL_MEM_READ_ONLY;
  B["materials"] = Cl->allocateWith("materials", Data.Materials.data(), bytes(Data.Materials), RO);
  B["bsdfNodes"] = Cl->allocateWith("bsdfNodes", Data.BsdfNodes.data(), bytes(Data.BsdfNodes), RO);
  // Read-write: texcc_uniforms (shape, interp) writes hoisted values into it.
  B["fakeStack"] = Cl->allocateWith("fakeStack", Lay.ArgsBin.data(), Lay.ArgsBin.size(),
                                    CL_MEM_READ_WRITE);
  Tiers->argumentsChanged();
  // Images: every bound image, concatenated, linear RGBA.
  std::vector<cl_float4> Texels;
  std::vector<TexccImageInfo> Infos;
  for (const LayoutImage &I : Lay.Images) {
    ImageRGBA Img = loadTexture(I.Path, I.ColorSpace);
    // What tex2DFiltered needs to read the image as Cycles reads an image file (texcc_device.h):
    // sRGB ones still encoded, 8- and 16-bit ones as integers.
    const int Flags = (Img.ColorSpace == "Non-Color" ? TEXCC_IMAGE_DATA : 0) |
                      (Img.ColorSpace == "sRGB" ? TEXCC_IMAGE_SRGB : 0) |
                      (Img.Bits == 8 ? TEXCC_IMAGE_BYTES : Img.Bits == 16 ? TEXCC_IMAGE_SHORTS : 0);
    TexccImageInfo Info{int(Texels.size()), Img.Width, Img.Height, Flags};
    Infos.push_back(Info);
    for (size_t P = 0; P < Img.Pixels.size(); P += 4)
      Texels.push_back({{Img.Pixels[P], Img.Pixels[P + 1], Img.Pixels[P + 2], Img.Pixels[P + 3]}});
  }
  if (Texels.empty())
    Texels.push_back({{0, 0, 0, 0}});
  if (Infos.empty())
    Infos.push_back({0, 0, 0, 0});
  B["texels"] = Cl->allocateWith("texels", Texels.data(), bytes(Texels), RO);
  B["images"] = Cl->allocateWith("images", Infos.data(), bytes(Infos), RO);
  TexccSettings Set = textureSettings(SceneDesc, Settings);
  B["settings"] = Cl->allocateWith("settings", &Set, sizeof Set, RO);
  AttrMask = attributeMaskOf(Lay);
  HasTextureWork = std::any_of(Data.Materials.begin(), Data.Materials.end(),
                               [](const RtMaterial &M) { return M.numOutputs > 0; });
  Capacity = 0; // the outputs and scratch buffers depend on the layout
}

void Renderer::applyArguments(const std::vector<uint8_t> &ArgsBin,
                              const std::vector<std::string> &Attributes) {
  if (Attributes != Lay.Attributes) {
    Lay.Attributes = Attributes;
    AttrMask = attributeMaskOf(Lay);
    Capacity = 0; // the AO buffer may now be needed
    // Which materials read AO may have changed: let every textured one trace AO rays.
    for (LayoutMaterial &M : Lay.Materials)
      M.ReadsAo = true;
    buildMaterials(Lay, Data.Materials, Data.BsdfNodes);
    Cl->write(B["materials"], Data.Materials.data(), bytes(Data.Materials));
  }
  Lay.ArgsBin = ArgsBin;
  size_t Have = Cl->memory().count("fakeStack") ? Cl->memory().at("fakeStack") : 0;
  if (ArgsBin.size() > Have)
    B["fakeStack"] = Cl->allocate("fakeStack", ArgsBin.size(), CL_MEM_READ_WRITE);
  Cl->write(B["fakeStack"], ArgsBin.data(), ArgsBin.size());
  Tiers->argumentsChanged();
}

void Renderer::setLayout(const Layout &L) {
  Lay = L;
  uploadLayoutData();
  Tiers->build(HasTextureWork);
}

void Renderer::switchShapes(const std::vector<uint8_t> &ArgsBin,
                            const std::vector<std::string> &Attributes,
                            std::function<Layout()> MakeLayout,
                            std::function<void(Layout &)> Reencode) {
  if (!Tiers->canSwitchShapes())
    throw Error("switchShapes: needs a shape-mode layout with its interp fallback built (tier auto)");
  applyArguments(ArgsBin, Attributes);
  Tiers->switchShapes(HasTextureWork, std::move(MakeLayout), std::move(Reencode));
}

void Renderer::allocateWorkBuffers(size_t N) {
  const cl_mem_flags RW = CL_MEM_READ_WRITE;
  B["paths"] = Cl->allocate("paths", N * sizeof(RtPath), RW);
  B["activeA"] = Cl->allocate("activeA", N * sizeof(cl_int), RW);
  B["activeB"] = Cl->allocate("activeB", N * sizeof(cl_int), RW);
  B["hits"] = Cl->allocate("hits", N * sizeof(RtHit), RW);
  B["shadowRays"] = Cl->allocate("shadowRays", N * sizeof(RtShadowRay), RW);
  // Without texture work or attributes these are never read: a token allocation each.
  const size_t PerHit = (AttrMask != 0 || HasTextureWork) ? N : 1;
  B["hitAttributes"] = Cl->allocate("hitAttributes", PerHit * sizeof(TexccHitAttrs), RW);
  B["hitMaterial"] = Cl->allocate("hitMaterial", PerHit * sizeof(cl_int), RW);
  B["textureOutputs"] = Cl->allocate("textureOutputs", (HasTextureWork ? N : 1) * Lay.MaxOutputs * sizeof(cl_float4), RW);
  // layout.json's scratch per hit (wavefront: every node's value), or the spilled value stack.
  size_t ScratchPerHit = std::max<size_t>({Lay.ScratchFloat4PerHit, Lay.Spill ? Lay.StackSlots : 0,
                                           Tiers->quickScratchFloat4PerHit()}); // + quick tier
  B["textureScratch"] = Cl->allocate("textureScratch", std::max<size_t>(1, N * ScratchPerHit) * sizeof(cl_float4), RW);
  const cl_int NoFault[TEXCC_FAULT_WORDS] = {};
  B["textureFaults"] = Cl->allocateWith("textureFaults", NoFault, sizeof NoFault, RW);
  if (runsAo() && !Opts.AoPerHitLoop)
    B["aoOccluded"] = Cl->allocate("aoOccluded", N * Settings.AoSamples, RW);
  Capacity = N;
  CapacityAo = Settings.AoSamples;
}

void Renderer::runTextures(int NumActive) {
  // Hoisted values first, once per upload of fakeStack (stats.json kernel "uniforms").
  if (cl::Kernel *U = Tiers->uniformsDue()) {
    U->setArg(0, B["fakeStack"]);
    U->setArg(1, cl_int(Lay.Materials.size()));
    Cl->launch(*U, 1, "uniforms");
    Tiers->uniformsRan();
  }
  for (cl::Kernel &T : Tiers->kernels()) {
    T.setArg(0, B["hitAttributes"]);
    T.setArg(1, B["hitMaterial"]);
    T.setArg(2, cl_int(NumActive));
    T.setArg(3, B["fakeStack"]);
    T.setArg(4, B["settings"]);
    T.setArg(5, B["texels"]);
    T.setArg(6, B["images"]);
    T.setArg(7, B["textureOutputs"]);
    T.setArg(8, B["textureScratch"]);
    if (T.getInfo<CL_KERNEL_NUM_ARGS>() > 9) // kernels made before the fault record lack it
      T.setArg(9, B["textureFaults"]);
    Cl->launch(T, NumActive, "proctex");
  }
}

void Renderer::checkTextureOutputs(const cl::Buffer &Active, int NumActive) {
  const size_t N = size_t(NumActive), Outs = Lay.MaxOutputs;
  std::vector<cl_int> Material(N);
  std::vector<cl_float4> Values(N * Outs);
  Cl->read(B["hitMaterial"], Material.data(), bytes(Material));
  Cl->read(B["textureOutputs"], Values.data(), bytes(Values));
  for (size_t I = 0; I < N; ++I) {
    if (Material[I] < 0 || size_t(Material[I]) >= Lay.Materials.size())
      continue;
    const LayoutMaterial &M = Lay.Materials[Material[I]];
    for (size_t O = 0; O < M.OutputComponents.size() && O < Outs; ++O) {
      const cl_float4 &V = Values[I * Outs + O];
      int C = 0;
      while (C < M.OutputComponents[O] && std::isfinite(V.s[C]))
        ++C;
      if (C == M.OutputComponents[O])
        continue;
      // Only now fetch which path (and so which pixel) the hit belongs to.
      cl_int Path = 0;
      RtPath P{};
      Cl->read(Active, &Path, sizeof Path, I * sizeof(cl_int));
      Cl->read(B["paths"], &P, sizeof P, size_t(Path) * sizeof(RtPath));
      const std::string Node = O < M.OutputNodes.size() ? M.OutputNodes[O] : "?";
      char Where[160];
      std::snprintf(Where, sizeof Where, "%s at pixel (%u, %u), path depth %d",
                    std::isnan(V.s[C]) ? "NaN" : V.s[C] > 0 ? "+inf" : "-inf",
                    P.pixel % unsigned(Settings.Width), P.pixel / unsigned(Settings.Width),
                    P.depth);
      throw TextureFault("--check-nan: material '" + M.Name + "': node '" + Node +
                         "' (texture output " + std::to_string(O) + ", component " +
                         std::to_string(C) + ") returned " + Where);
    }
  }
}

/// Runs the bounce loop over NumPaths fresh paths (in activeA). Returns the bounces done.
int Renderer::traceBounces(int NumPaths, FrameStats &Stats, bool StopAfterAttributes) {
  cl::Buffer Cur = B["activeA"], Next = B["activeB"];
  int Count = NumPaths;
  int Depth = 1;
  int Bounces = 0;
  const bool Attrs = AttrMask != 0 || HasTextureWork;
  // RendererOptions::CutPass, asked at the end of a bounce's stages, the device finished first
  // (launches are asynchronous). A fault of this bounce's textures is still reported.
  auto cut = [&](bool TexturesRan) {
    if (!Opts.CutPass)
      return false;
    Cl->finish();
    if (!Opts.CutPass())
      return false;
    if (TexturesRan && HasTextureWork)
      checkTextureFaults(Cur);
    Stats.PassCut = true;
    return true;
  };
  while (Count > 0 && (Settings.MaxDepth < 0 || Depth <= Settings.MaxDepth) && Depth < 4096) {
    Tracer->closestHit(Cur, Count, Depth == 1 ? "closest_hit_primary" : "closest_hit_bounce");
    (Depth == 1 ? Stats.PrimaryRays : Stats.BounceRays) += Count;
    if (Attrs) {
      cl::Kernel &HA = K["hit_attributes"];
      HA.setArg(0, B["triangles"]), HA.setArg(1, B["triangleAttributes"]);
      HA.setArg(2, B["meshes"]), HA.setArg(3, B["materials"]), HA.setArg(4, B["paths"]);
      HA.setArg(5, Cur), HA.setArg(6, cl_int(Count)), HA.setArg(7, B["hits"]);
      HA.setArg(8, cl_uint(AttrMask)), HA.setArg(9, B["hitAttributes"]);
      HA.setArg(10, B["hitMaterial"]);
      Cl->launch(HA, Count, "hit_attributes");
    }
    if (runsAo())
      runAo(Cur, Count, Stats);
    if (StopAfterAttributes)
      return 1;
    if (cut(false))
      break;
    if (HasTextureWork)
      runTextures(Count);
    if (HasTextureWork && Opts.CheckNan)
      checkTextureOutputs(Cur, Count);
    if (HasTextureWork && cut(true))
      break;
    cl::Kernel &SH = K["shade"];
    SH.setArg(0, B["triangles"]), SH.setArg(1, B["triangleAttributes"]), SH.setArg(2, B["meshes"]);
    SH.setArg(3, B["materials"]), SH.setArg(4, B["bsdfNodes"]), SH.setArg(5, B["lights"]);
    SH.setArg(6, B["lightCdf"]), SH.setArg(7, B["shadeParams"]), SH.setArg(8, B["paths"]);
    SH.setArg(9, Cur), SH.setArg(10, cl_int(Count)), SH.setArg(11, B["hits"]);
    SH.setArg(12, B["textureOutputs"]), SH.setArg(13, cl_int(Lay.MaxOutputs));
    SH.setArg(14, B["shadowRays"]), SH.setArg(15, B["counters"]), SH.setArg(16, B["envMap"]);
    Cl->launch(SH, Count, "shade");
    Tracer->shadow(Cur, Count);
    if (cut(true))
      break;
    cl_int Zero = 0;
    Cl->write(B["activeCount"], &Zero, sizeof Zero);
    cl::Kernel &CP = K["compact"];
    CP.setArg(0, B["paths"]), CP.setArg(1, Cur), CP.setArg(2, cl_int(Count));
    CP.setArg(3, Next), CP.setArg(4, B["activeCount"]);
    Cl->launch(CP, Count, "compact");
    Cl->read(B["activeCount"], &Count, sizeof Count);
    if (HasTextureWork)
      checkTextureFaults(Cur);
    std::swap(Cur, Next);
    ++Depth;
    ++Bounces;
    if (Count > 0 && cut(false))
      break;
  }
  return Bounces;
}

std::vector<float> Renderer::averageSums(size_t NumPixels, int Done) {
  std::vector<cl_float4> Sums(NumPixels);
  Cl->read(B["sums"], Sums.data(), bytes(Sums));
  std::vector<float> RGB(NumPixels * 3);
  for (size_t P = 0; P < NumPixels; ++P)
    for (int C = 0; C < 3; ++C)
      RGB[3 * P + C] = Sums[P].s[C] / float(std::max(Done, 1)); // 0 passes (a cut): black
  return RGB;
}

std::vector<float> Renderer::render(FrameStats &Stats, std::vector<float> *Variance) {
  double T0 = now();
  Stats = FrameStats();
  Stats.Tier = Tiers->beginFrame(); // adopts a background build that finished since the last frame
  Cl->finish();
  Cl->resetTimings();
  const int W = Settings.Width, H = Settings.Height, Spp = Settings.Spp;
  // --region: the pixels rendered, in full-film coordinates (raygen.cl); the image is its size.
  const bool Whole = Settings.RegionWidth == 0;
  const int RX = Whole ? 0 : Settings.RegionX, RY = Whole ? 0 : Settings.RegionY;
  const int RW = Whole ? W : Settings.RegionWidth, RH = Whole ? H : Settings.RegionHeight;
  const size_t NumPixels = size_t(RW) * RH;
  int SppPerPass = int(std::clamp<size_t>(Opts.MaxPathsPerPass / NumPixels, 1, size_t(Spp)));
  size_t Need = NumPixels * SppPerPass;
  try {
    if (Need > Capacity || Settings.AoSamples != CapacityAo)
      allocateWorkBuffers(std::max(Need, Capacity));
    RtCamera Cam = makeCamera(SceneDesc.Cam, W, H);
    Cl->write(B["camera"], &Cam, sizeof Cam);
    TexccSettings Set = textureSettings(SceneDesc, Settings);
    Cl->write(B["settings"], &Set, sizeof Set);
    RtShadeParams Prm{};
    Prm.maxDepth = Settings.MaxDepth;
    Prm.rrDepth = 5;
    Prm.numLights = int(Data.Lights.size());
    Prm.skyLight = Data.SkyLight;
    Prm.sunLight = Data.SunLight;
    Prm.epsilon = 1e-4f;
    Prm.lampFirst = Data.LampFirst;
    Prm.numLamps = Data.NumLamps;
    Prm.envLight = Data.EnvLight;
    Prm.envWidth = Data.Env.Width;
    Prm.envHeight = Data.Env.Height;
    Prm.envFlags = Data.Env.Flags;
    Cl->write(B["shadeParams"], &Prm, sizeof Prm);
    cl_uint Counters[RT_COUNT_SLOTS] = {};
    Cl->write(B["counters"], Counters, sizeof Counters);
    if (!Cl->memory().count("sums") || Cl->memory().at("sums") != NumPixels * sizeof(cl_float4)) {
      B["sums"] = Cl->allocate("sums", NumPixels * sizeof(cl_float4), CL_MEM_READ_WRITE);
      B["sumsSquared"] = Cl->allocate("sumsSquared", NumPixels * sizeof(cl_float4), CL_MEM_READ_WRITE);
    }
    std::vector<cl_float4> Zeros(NumPixels, cl_float4{{0, 0, 0, 0}});
    Cl->write(B["sums"], Zeros.data(), bytes(Zeros));
    Cl->write(B["sumsSquared"], Zeros.data(), bytes(Zeros));
    int Done = 0;
    while (Done < Spp) {
      if (Opts.OnPass)
        Opts.OnPass(true);
      int Now = std::min(SppPerPass, Spp - Done);
      int N = int(NumPixels) * Now;
      cl::Kernel &RG = K["raygen"];
      RG.setArg(0, B["paths"]), RG.setArg(1, B["activeA"]), RG.setArg(2, B["camera"]);
      RG.setArg(3, cl_int(W)), RG.setArg(4, cl_int(H)), RG.setArg(5, cl_int(Now));
      RG.setArg(6, cl_int(Done)), RG.setArg(7, cl_uint(Settings.Seed)), RG.setArg(8, cl_int(N));
      RG.setArg(9, cl_int(RX)), RG.setArg(10, cl_int(RY)), RG.setArg(11, cl_int(RW));
      RG.setArg(12, cl_int(Whole ? 1 : std::max(1, Settings.RegionRowStep)));
      Cl->launch(RG, N, "raygen");
      Stats.Bounces += traceBounces(N, Stats, false);
      if (Stats.PassCut) { // abandoned: its paths are never accumulated
        Stats.Interrupted = true;
        break;
      }
      cl::Kernel &AC = K["accumulate"];
      AC.setArg(0, B["paths"]), AC.setArg(1, cl_int(NumPixels)), AC.setArg(2, cl_int(Now));
      AC.setArg(3, B["sums"]), AC.setArg(4, B["sumsSquared"]), AC.setArg(5, B["counters"]);
      Cl->launch(AC, NumPixels, "accumulate");
      Done += Now;
      ++Stats.Passes;
      if (Opts.AfterPass && Done < Spp) {
        Cl->finish();
        PassProgress P{Done, Spp, now() - T0, [&, Done] { return averageSums(NumPixels, Done); }};
        if (!Opts.AfterPass(P)) {
          Stats.Interrupted = true;
          break;
        }
      }
      // --time-limit: stop at a pass boundary, with every pass done complete.
      if (Opts.Deadline > 0) {
        Cl->finish();
        if (steadySeconds() > Opts.Deadline && Done < Spp) {
          Stats.TimeLimited = true;
          break;
        }
      }
      if (Opts.OnPass)
        Opts.OnPass(false);
      if (Done < Spp && HasTextureWork)
        Tiers->passDone(); // the optimised build behind a quick first build: started, adopted
    }
    if (Opts.OnPass)
      Opts.OnPass(false);
    Stats.SamplesDone = Done;
    Cl->finish();
    std::vector<float> RGB = averageSums(NumPixels, Done);
    Cl->read(B["counters"], Counters, sizeof Counters);
    Stats.ShadowRays = Counters[RT_COUNT_SHADOW_RAYS];
    Stats.AoRays = Counters[RT_COUNT_AO_RAYS];
    Stats.NonFiniteSamples = Counters[RT_COUNT_NONFINITE];
    Stats.SaturatedSamples = Counters[RT_COUNT_SATURATED];
    Stats.Kernels = Cl->timings();
    if (Variance) {
      // The variance of each pixel's mean: the sample variance over its samples / spp.
      std::vector<cl_float4> Sq(NumPixels);
      Cl->read(B["sumsSquared"], Sq.data(), bytes(Sq));
      Variance->assign(NumPixels * 3, 0.0f);
      for (size_t P = 0; P < NumPixels && Done > 1; ++P)
        for (int C = 0; C < 3; ++C) {
          double M = RGB[3 * P + C];
          double S2 = (double(Sq[P].s[C]) - Done * M * M) / (Done - 1);
          // A saturated sum of squares (accumulate.cl) only bounds the variance from below.
          if (Sq[P].s[C] >= FLT_MAX)
            S2 = DBL_MAX;
          (*Variance)[3 * P + C] = float(std::min(std::max(0.0, S2) / Done, double(FLT_MAX)));
        }
    }
    Stats.Seconds = now() - T0;
    return RGB;
  } catch (const cl::Error &E) {
    throw Error(std::string("OpenCL call ") + E.what() + " failed: " + clErrorName(E.err()));
  }
}

std::vector<TexccHitAttrs> Renderer::primaryHitAttributes(uint32_t Mask, FrameStats &Stats) {
  Stats = FrameStats();
  Cl->finish();
  Cl->resetTimings();
  uint32_t Saved = AttrMask;
  AttrMask |= Mask;
  std::vector<RtMaterial> AllAo = Data.Materials;
  for (RtMaterial &M : AllAo)
    M.readsAo = 1;
  Cl->write(B["materials"], AllAo.data(), bytes(AllAo));
  size_t N = size_t(Settings.Width) * Settings.Height;
  allocateWorkBuffers(std::max(N, Capacity));
  RtCamera Cam = makeCamera(SceneDesc.Cam, Settings.Width, Settings.Height);
  Cl->write(B["camera"], &Cam, sizeof Cam);
  cl_uint Counters[RT_COUNT_SLOTS] = {};
  Cl->write(B["counters"], Counters, sizeof Counters);
  cl::Kernel &RG = K["raygen"];
  RG.setArg(0, B["paths"]), RG.setArg(1, B["activeA"]), RG.setArg(2, B["camera"]);
  RG.setArg(3, cl_int(Settings.Width)), RG.setArg(4, cl_int(Settings.Height)), RG.setArg(5, cl_int(1));
  RG.setArg(6, cl_int(0)), RG.setArg(7, cl_uint(Settings.Seed)), RG.setArg(8, cl_int(N));
  RG.setArg(9, cl_int(0)), RG.setArg(10, cl_int(0)), RG.setArg(11, cl_int(Settings.Width));
  RG.setArg(12, cl_int(1));
  Cl->launch(RG, N, "raygen");
  traceBounces(int(N), Stats, true);
  Cl->finish();
  std::vector<TexccHitAttrs> Out(N);
  Cl->read(B["hitAttributes"], Out.data(), bytes(Out));
  Cl->read(B["counters"], Counters, sizeof Counters);
  Stats.AoRays = Counters[RT_COUNT_AO_RAYS];
  Stats.Kernels = Cl->timings();
  AttrMask = Saved;
  Cl->write(B["materials"], Data.Materials.data(), bytes(Data.Materials));
  Capacity = 0; // the AO buffer may be missing for the normal mask
  return Out;
}

} // namespace texrender
