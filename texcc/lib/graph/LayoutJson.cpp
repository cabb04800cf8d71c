// layout.json (docs/abi.md): the graph part, and reading the signatures back for live edits.

#include "texcc/Graph/Compile.h"
#include "texcc/Graph/Passes.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <filesystem>
#include <limits>

namespace texcc::graph {

namespace {

using OJson = nlohmann::ordered_json;
namespace fs = std::filesystem;

std::string absolutePath(const std::string &P) {
  if (P.empty())
    return P;
  std::error_code EC;
  fs::path Abs = fs::absolute(fs::path(P), EC);
  return EC ? P : Abs.lexically_normal().string();
}

/// Image paths are relative to the graph's folder.
std::string imagePath(const std::string &GraphPath, const std::string &Image) {
  fs::path P(Image);
  if (P.is_absolute() || GraphPath.empty())
    return absolutePath(Image);
  return absolutePath((fs::path(GraphPath).parent_path() / P).string());
}

/// {"values": [{name, type, size, offset}], "from": [parameter names]}.
OJson hoistedJson(const FunctionSignature &Sig) {
  const std::vector<uint32_t> Offsets = hoistedOffsets(Sig);
  OJson Values = OJson::array(), From = OJson::array();
  for (size_t I = 0; I < Sig.Hoisted.size(); ++I) {
    const ValueType T{Sig.Hoisted[I].Type, false};
    Values.push_back({{"name", Sig.Hoisted[I].Name},
                      {"type", spelling(T)},
                      {"size", sizeOf(T)},
                      {"offset", Offsets[I]}});
  }
  for (unsigned P : Sig.HoistedFrom)
    From.push_back(Sig.Params.at(P).Name);
  return {{"values", Values}, {"from", From}};
}

OJson functionJson(unsigned Id, const FunctionSignature &Sig) {
  uint32_t BlockSize = 0;
  std::vector<uint32_t> Offsets = parameterOffsets(Sig, BlockSize);
  OJson Params = OJson::array();
  for (size_t I = 0; I < Sig.Params.size(); ++I) {
    const Param &P = Sig.Params[I];
    Params.push_back({{"name", P.Name},
                      {"type", spelling(P.Type)},
                      {"size", sizeOf(P.Type)},
                      {"align", alignOf(P.Type)},
                      {"offset", Offsets[I]}});
  }
  OJson F = {{"id", Id},
             {"name", Sig.Name},
             {"renamed", Sig.RenamedName},
             {"file", Sig.File},
             {"return", spelling(Sig.Return)},
             {"blockSize", BlockSize},
             {"params", Params},
             {"attributes", Sig.Attributes},
             {"settings", Sig.Settings},
             {"cost", Sig.Cost}};
  if (!Sig.Hoisted.empty())
    F["hoisted"] = hoistedJson(Sig);
  return F;
}

OJson argJson(const CompiledGraph &CG, const CompiledArg &A) {
  OJson J = {{"name", A.Name}};
  switch (A.Src) {
  case CompiledArg::Source::Attribute:
    J["source"] = "attr";
    J["attr"] = attributeTable()[A.AttrId].first;
    J["broadcast"] = A.Broadcast;
    break;
  case CompiledArg::Source::Node:
    J["source"] = "node";
    J["node"] = A.NodeIndex;
    J["broadcast"] = A.Broadcast;
    break;
  case CompiledArg::Source::Constant:
    J["source"] = "const";
    if (A.Type.Base == BaseType::Sampler && !A.Values.empty()) {
      size_t Index = static_cast<size_t>(A.Values[0]);
      if (Index < CG.Images.size())
        J["image"] = CG.Images[Index].first;
    }
    if (A.Type.IsGlobalArray)
      J["array"] = {{"offset", A.ArrayByteOffset}, {"count", A.ArrayCount}};
    if (A.Type.Base == BaseType::Int || A.Type.Base == BaseType::Sampler) {
      std::vector<long long> Ints(A.Values.begin(), A.Values.end());
      J["value"] = Ints;
    } else {
      J["value"] = A.Values;
    }
    if (A.Bake)
      J["bake"] = true;
    break;
  }
  J["offset"] = A.BlockOffset;
  return J;
}

OJson bsdfJson(const CompiledBsdf &B) {
  OJson J = {{"type", B.Type}};
  for (const CompiledBsdfInput &In : B.Inputs) {
    if (In.IsOutput)
      J[In.Name] = {{"output", In.Output}};
    else
      J[In.Name] = {{"const", In.Constant}};
  }
  for (const auto &[Name, Child] : B.Children)
    J[Name] = bsdfJson(Child);
  return J;
}

} // namespace

std::string layoutJson(const CompiledGraph &CG) {
  OJson J;
  J["texcc"] = 1;
  J["target"] = "opencl";
  J["graph"] = absolutePath(CG.GraphPath);
  J["stackSlots"] = CG.StackSlots;
  J["stackLimit"] = CG.StackLimit;
  J["spill"] = CG.Spill;
  J["valueStack"] = CG.Spill ? "global" : CG.LocalStack ? "local" : "private";
  J["maxOutputs"] = CG.MaxOutputs;
  J["scratchFloat4PerHit"] = CG.Spill ? CG.StackSlots : 0;
  J["argsBin"] = {{"size", CG.ArgsBin.size()},
                  {"programWords", CG.ProgramWords},
                  {"recordsOffset", CG.RecordsOffset}};
  J["attributes"] = CG.Attributes;
  J["settings"] = CG.Settings;
  OJson Images = OJson::array();
  for (size_t I = 0; I < CG.Images.size(); ++I)
    Images.push_back({{"name", CG.Images[I].first},
                      {"path", imagePath(CG.GraphPath, CG.Images[I].second)},
                      {"index", I}});
  J["images"] = Images;
  OJson Functions = OJson::array();
  for (size_t Id = 0; Id < CG.FunctionsById.size(); ++Id) {
    auto It = CG.Signatures.find(CG.FunctionsById[Id]);
    if (It != CG.Signatures.end())
      Functions.push_back(functionJson(static_cast<unsigned>(Id), It->second));
  }
  J["functions"] = Functions;
  OJson Quick = OJson::array();
  for (const QuickenedOp &Q : CG.Quickened) {
    std::vector<std::string> Sources;
    for (const ArgumentSource &S : Q.Sources)
      Sources.push_back(spellSource(S));
    Quick.push_back({{"opcode", Q.Opcode}, {"function", Q.Fn}, {"sources", Sources}});
  }
  J["quickened"] = Quick;
  OJson Nodes = OJson::array();
  for (size_t I = 0; I < CG.Nodes.size(); ++I) {
    const CompiledNode &N = CG.Nodes[I];
    OJson Args = OJson::array();
    for (const CompiledArg &A : N.Args)
      Args.push_back(argJson(CG, A));
    Nodes.push_back({{"index", I},
                     {"id", N.Id},
                     {"merged", N.MergedIds},
                     {"fn", N.Fn},
                     {"fnId", N.FnId},
                     {"record", {{"offset", N.RecordOffset}, {"size", N.RecordSize}}},
                     {"copies", N.RecordCopies},
                     {"args", Args}});
  }
  J["nodes"] = Nodes;
  J["wavefrontOrder"] = CG.WavefrontOrder;
  OJson Materials = OJson::array();
  for (const CompiledMaterial &M : CG.Materials) {
    OJson Outputs = OJson::array();
    for (const MaterialOutput &O : M.Outputs)
      Outputs.push_back({{"node", O.Node}, {"slot", O.Slot}, {"type", spelling(O.Type)}});
    Materials.push_back({{"name", M.Name},
                         {"index", M.Index},
                         {"program",
                          {{"wordOffset", M.ProgramWordOffset},
                           {"instructions", M.Program.size()},
                           {"stackSlots", M.StackSlots}}},
                         {"outputs", Outputs},
                         {"bsdf", bsdfJson(M.Bsdf)}});
  }
  J["materials"] = Materials;
  return J.dump(2) + "\n";
}

bool readLayoutQuickened(const std::string &LayoutJsonText, std::vector<QuickenedOp> &Table,
                         std::string &Error) {
  try {
    nlohmann::json J = nlohmann::json::parse(LayoutJsonText);
    if (!J.contains("quickened"))
      return true; // a kernel without them (older texcc, or --max-quickened=0)
    // The editor writes these opcodes into args.bin for the kernel's cases: an entry that names
    // a function the layout lacks, has a source per parameter wrong, or reuses an opcode would
    // run the wrong case (or none) silently, so it is an error here.
    std::map<std::string, std::vector<std::string>> ParamTypes;
    std::set<unsigned> Taken;
    for (const auto &F : J.at("functions")) {
      std::vector<std::string> &Types = ParamTypes[F.at("name").get<std::string>()];
      for (const auto &P : F.at("params"))
        Types.push_back(P.at("type").get<std::string>());
      Taken.insert(F.at("id").get<unsigned>());
    }
    // A layout of texcc before 2026-12 may list superinstructions, and quickened pairs of them
    // ("second"): their opcodes stay the kernel's, but edits encode plain and single quickened
    // opcodes only, which that kernel has too.
    if (J.contains("superinstructions"))
      for (const auto &S : J.at("superinstructions"))
        Taken.insert(S.at("opcode").get<unsigned>());
    // One function's sources: one per parameter, each a kind the kernel has a case for; "int:N"
    // only for an int parameter.
    auto ReadSources = [&](const std::string &Where, const std::string &Fn,
                           const std::vector<std::string> &Sources,
                           std::vector<ArgumentSource> &Typed) {
      auto It = ParamTypes.find(Fn);
      if (It == ParamTypes.end()) {
        Error = Where + "function '" + Fn + "' is not in /functions";
        return false;
      }
      if (Sources.size() != It->second.size()) {
        Error = Where + std::to_string(Sources.size()) + " sources for the " +
                std::to_string(It->second.size()) + " parameters of '" + Fn + "'";
        return false;
      }
      for (size_t P = 0; P < Sources.size(); ++P) {
        const std::string &S = Sources[P];
        ArgumentSource T;
        if (!parseSource(S, T) ||
            (T.K == ArgumentSource::Kind::IntValue && It->second[P] != "int")) {
          Error = Where + "source '" + S + "' of parameter " + std::to_string(P) + " of '" + Fn +
                  "' (expected const, slot, slot.x, attr:Name, attr:Name.x" +
                  (It->second[P] == "int" ? " or int:N" : "") + ")";
          return false;
        }
        Typed.push_back(T);
      }
      return true;
    };
    for (size_t K = 0; K < J.at("quickened").size(); ++K) {
      const auto &E = J.at("quickened").at(K);
      const std::string Where = "/quickened/" + std::to_string(K) + ": ";
      QuickenedOp Q;
      Q.Opcode = E.at("opcode").get<unsigned>();
      Q.Fn = E.at("function").get<std::string>();
      if (E.contains("second")) { // a quickened superinstruction of an older texcc (above)
        Taken.insert(Q.Opcode);
        continue;
      }
      if (!ReadSources(Where, Q.Fn, E.at("sources").get<std::vector<std::string>>(), Q.Sources))
        return false;
      if (!Taken.insert(Q.Opcode).second) {
        Error = Where + "opcode " + std::to_string(Q.Opcode) +
                " is already a function id, a superinstruction's or another entry's";
        return false;
      }
      Table.push_back(Q);
    }
  } catch (const nlohmann::json::exception &E) {
    Error = std::string("malformed layout.json: ") + E.what();
    return false;
  }
  return true;
}

bool readLayoutSignatures(const std::string &LayoutJsonText, SignatureMap &Sigs,
                          std::map<std::string, unsigned> &FnIds, std::string &Error) {
  try {
    nlohmann::json J = nlohmann::json::parse(LayoutJsonText);
    for (const auto &F : J.at("functions")) {
      FunctionSignature S;
      S.Name = F.at("name").get<std::string>();
      S.RenamedName = F.value("renamed", "");
      S.File = F.value("file", "");
      auto Ret = parseSpelling(F.at("return").get<std::string>());
      if (!Ret || Ret->IsGlobalArray) {
        Error = "function '" + S.Name + "': bad return type";
        return false;
      }
      S.Return = Ret->Base;
      for (const auto &P : F.at("params")) {
        auto T = parseSpelling(P.at("type").get<std::string>());
        if (!T) {
          Error = "function '" + S.Name + "': bad parameter type '" +
                  P.at("type").get<std::string>() + "'";
          return false;
        }
        S.Params.push_back({P.at("name").get<std::string>(), *T});
      }
      if (F.contains("attributes"))
        S.Attributes = F.at("attributes").get<std::vector<std::string>>();
      if (F.contains("settings"))
        S.Settings = F.at("settings").get<std::vector<std::string>>();
      S.Cost = F.value("cost", 0u);
      if (F.contains("hoisted") && !F.at("hoisted").is_null()) {
        const auto &H = F.at("hoisted");
        for (const auto &V : H.at("values")) {
          auto T = parseSpelling(V.at("type").get<std::string>());
          if (!T || T->IsGlobalArray || T->Base == BaseType::Sampler) {
            Error = "function '" + S.Name + "': bad hoisted type '" +
                    V.at("type").get<std::string>() + "'";
            return false;
          }
          S.Hoisted.push_back({V.at("name").get<std::string>(), T->Base});
        }
        for (const auto &P : H.at("from")) {
          const std::string Name = P.get<std::string>();
          auto It = std::find_if(S.Params.begin(), S.Params.end(),
                                 [&](const Param &Q) { return Q.Name == Name; });
          if (It == S.Params.end()) {
            Error = "function '" + S.Name + "': hoisted from an unknown parameter '" + Name + "'";
            return false;
          }
          S.HoistedFrom.push_back(static_cast<unsigned>(It - S.Params.begin()));
        }
      }
      FnIds[S.Name] = F.at("id").get<unsigned>();
      Sigs[S.Name] = std::move(S);
    }
  } catch (const nlohmann::json::exception &E) {
    Error = std::string("malformed layout.json: ") + E.what();
    return false;
  }
  return true;
}

} // namespace texcc::graph
