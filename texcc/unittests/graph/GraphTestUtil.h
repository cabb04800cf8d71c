#ifndef TEXCC_UNITTESTS_GRAPH_GRAPHTESTUTIL_H
#define TEXCC_UNITTESTS_GRAPH_GRAPHTESTUTIL_H

// Helpers for the graph library's tests: signatures and graphs from short JSON texts, and the
// diagnostics as one string.

#include "texcc/Graph/Compile.h"
#include "texcc/Graph/Passes.h"

#include <gtest/gtest.h>

#include <cstring>
#include <sstream>

namespace texcc::graph::test {

/// Signatures written compactly: "name: ret (type name, type name) [attr,...]".
inline SignatureMap sigs(const std::string &Json) {
  SignatureMap S;
  DiagnosticSink D;
  EXPECT_TRUE(readSignaturesJson("sigs.json", Json, S, D));
  std::ostringstream OS;
  D.print(OS);
  EXPECT_EQ(OS.str(), "");
  return S;
}

/// The signatures most tests use.
inline const SignatureMap &stdSigs() {
  static const SignatureMap S = sigs(R"([
    {"name": "fbm3", "return": "float", "params": [{"name": "p", "type": "float3"},
      {"name": "scale", "type": "float"}, {"name": "octaves", "type": "int"}]},
    {"name": "ramp", "return": "float3", "params": [{"name": "t", "type": "float"},
      {"name": "stops", "type": "__global const float4*"}, {"name": "count", "type": "int"}]},
    {"name": "mix3", "return": "float3", "params": [{"name": "a", "type": "float3"},
      {"name": "b", "type": "float3"}, {"name": "t", "type": "float"}]},
    {"name": "add", "return": "float", "params": [{"name": "a", "type": "float"},
      {"name": "b", "type": "float"}]},
    {"name": "leaf", "return": "float", "params": [{"name": "x", "type": "float"}]},
    {"name": "neg", "return": "float", "params": [{"name": "x", "type": "float"}]},
    {"name": "tint", "return": "float4", "params": [{"name": "c", "type": "float4"}]},
    {"name": "uv", "return": "float2", "params": [{"name": "s", "type": "float2"}]},
    {"name": "image", "return": "float4", "params": [{"name": "img", "type": "sam2D"},
      {"name": "uv", "type": "float2"}], "attributes": ["TexCoord0"]},
    {"name": "weights", "return": "float", "params": [{"name": "w", "type": "__global const float*"},
      {"name": "dirs", "type": "__global const float3*"}, {"name": "n", "type": "int"}],
      "settings": ["Time"]}
  ])");
  return S;
}

inline std::string text(const DiagnosticSink &D) {
  std::ostringstream OS;
  D.print(OS);
  return OS.str();
}

inline std::optional<Graph> parse(const std::string &Json, DiagnosticSink &D) {
  return parseGraph("g.json", Json, D);
}

/// Parses and resolves (validation only); fails the test on any error.
inline CompiledGraph resolved(const std::string &Json, const SignatureMap &S = stdSigs()) {
  DiagnosticSink D;
  std::optional<Graph> G = parse(Json, D);
  EXPECT_TRUE(G.has_value()) << text(D);
  if (!G)
    return {};
  std::optional<CompiledGraph> CG = resolveGraph(*G, S, CompileOptions(), D);
  EXPECT_TRUE(CG.has_value()) << text(D);
  return CG ? *CG : CompiledGraph();
}

/// Parses and compiles; fails the test on any error.
inline CompiledGraph compiled(const std::string &Json, CompileOptions Opts = CompileOptions(),
                              const SignatureMap &S = stdSigs()) {
  DiagnosticSink D;
  std::optional<Graph> G = parse(Json, D);
  EXPECT_TRUE(G.has_value()) << text(D);
  if (!G)
    return {};
  std::optional<CompiledGraph> CG = compileGraph(*G, S, Opts, D);
  EXPECT_TRUE(CG.has_value()) << text(D);
  return CG ? *CG : CompiledGraph();
}

/// The diagnostics of compiling Json (parse and compile), expected to fail.
inline std::string errorsOf(const std::string &Json, const SignatureMap &S = stdSigs()) {
  DiagnosticSink D;
  std::optional<Graph> G = parse(Json, D);
  if (G) {
    CompileOptions Opts;
    for (const auto &KV : S)
      Opts.KnownFunctions.push_back(KV.first);
    EXPECT_FALSE(compileGraph(*G, S, Opts, D).has_value());
  }
  EXPECT_TRUE(D.hasErrors());
  return text(D);
}

inline int nodeIndex(const CompiledGraph &CG, const std::string &Id) { return CG.findNode(Id); }

inline uint32_t word(const std::vector<uint8_t> &Bin, uint32_t Offset) {
  uint32_t W;
  std::memcpy(&W, Bin.data() + Offset, 4);
  return W;
}

inline float floatAt(const std::vector<uint8_t> &Bin, uint32_t Offset) {
  float F;
  std::memcpy(&F, Bin.data() + Offset, 4);
  return F;
}

/// A graph JSON: nodes (already JSON objects) and materials (already JSON).
inline std::string graphJson(const std::vector<std::string> &Nodes,
                             const std::string &Materials) {
  std::string S = "{\"texcc\": 1, \"nodes\": [";
  for (size_t I = 0; I < Nodes.size(); ++I)
    S += (I ? ",\n" : "\n") + Nodes[I];
  return S + "],\n\"materials\": " + Materials + "}";
}

} // namespace texcc::graph::test

#endif
