#ifndef TEXRENDER_LAYOUT_H
#define TEXRENDER_LAYOUT_H

// What the runtime reads from texcc's output folder (docs/abi.md): layout.json, args.bin and
// the generated kernel's source.

#include "texcc/Kernel/Manifest.h"

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace texrender {

/// A BSDF input: a constant or a texture output of the material.
struct LayoutInput {
  bool IsOutput = false;
  int Output = -1;
  std::vector<float> Constant; // 1..4 values
};

struct LayoutBsdf {
  std::string Type; // diffuse | glossy | mirror | emission | blend
  std::vector<std::pair<std::string, LayoutInput>> Inputs;
  std::vector<std::pair<std::string, LayoutBsdf>> Children; // blend: a, b
  const LayoutInput *input(const std::string &Name) const;
};

struct LayoutMaterial {
  std::string Name;
  int Index = 0;
  std::vector<int> OutputComponents; // per texture output: 1..4
  std::vector<std::string> OutputNodes; // per texture output: the id of the node computing it
  bool ReadsAo = false;              // a node its outputs depend on reads AO
  LayoutBsdf Bsdf;
};

struct LayoutImage {
  std::string Name;
  std::string Path; // resolved
  std::string ColorSpace; // graph.json's "colorspace"; empty: the file's default
};

/// What the kernel of a layout can absorb without being made again: layout.json "capabilities",
/// written by the mode's backend (texcc/Kernel/Manifest.h); the live editor plans with these
/// (EditPlan.h), never with the mode's name.
using KernelCapabilities = texcc::kernel::Capabilities;

struct Layout {
  std::string Dir;        // the texcc output folder
  std::string Mode;       // interp | inline | wavefront | shape
  std::string GraphPath;  // graph.json the kernel was made from
  // compileOptions: texcc's arguments besides --graph, -o and the sources, replayed when a live
  // edit regenerates the kernel (from an older layout: just --mode).
  std::vector<std::string> CompileOptions;
  KernelCapabilities Caps;
  std::string KernelSource; // resolved path of proctex.cl
  std::string Entry;
  std::vector<std::string> WavefrontLaunches; // kernel names, in order
  // Shape mode: the interp kernel of the same graph (kernel.interpFallback, resolved), which
  // runs the same args.bin and renders while the shape kernel builds; and the shape count.
  std::string InterpFallback;
  unsigned NumShapes = 0;
  std::string ShapeHash;  // kernel.shapeHash: the shapes the shape kernel was made for
  // kernel.uniforms: the shape kernel's texcc_uniforms, which computes hoisted values into
  // fakeStack; run after every upload of args.bin, before the shape kernel ("" when none).
  std::string Uniforms;
  unsigned StackSlots = 0;
  unsigned StackLimit = 32;
  bool Spill = false;
  unsigned MaxOutputs = 1;
  unsigned ScratchFloat4PerHit = 0;
  std::vector<std::string> Attributes;
  std::vector<std::string> Settings;
  std::vector<LayoutImage> Images;
  std::vector<LayoutMaterial> Materials;
  std::string Text;              // layout.json as read
  texcc::kernel::Manifest Manifest; // layout.json, typed (the kernel library's one reader)
  std::vector<uint8_t> ArgsBin;  // args.bin

  /// Index of the material called Name, or -1.
  int findMaterial(const std::string &Name) const;
  /// "white, red, green" (for messages).
  std::string materialNames() const;
};

/// Reads OUTDIR/layout.json and OUTDIR/args.bin. Errors name the file, the position and the field (texcc::kernel::readManifest).
Layout loadLayout(const std::string &OutDir);

} // namespace texrender

#endif
