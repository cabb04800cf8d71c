// layout.json (docs/abi.md): the graph part, and reading the signatures back for live edits.

#include "texcc/Graph/Compile.h"
#include "texcc/Graph/Passes.h"
#include "texcc/Kernel/Attributes.h"
#include "texcc/Kernel/Manifest.h"

#include <algorithm>
#include <map>
#include <set>
#include <tuple>
#include <filesystem>
#include <limits>

namespace texcc::graph {

namespace {

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

/// One function's layout: its parameters' and hoisted values' places in the record.
kernel::FunctionLayout functionLayout(unsigned Id, const FunctionSignature &Sig) {
  kernel::FunctionLayout F;
  std::vector<uint32_t> Offsets = parameterOffsets(Sig, F.BlockSize);
  for (size_t I = 0; I < Sig.Params.size(); ++I) {
    const Param &P = Sig.Params[I];
    F.Params.push_back(
        {P.Name, spelling(P.Type), sizeOf(P.Type), alignOf(P.Type), Offsets[I], {}});
  }
  F.Id = Id;
  F.Name = Sig.Name;
  F.Renamed = Sig.RenamedName;
  F.File = Sig.File;
  F.Return = spelling(Sig.Return);
  F.Attributes = Sig.Attributes;
  F.Settings = Sig.Settings;
  F.Cost = Sig.Cost;
  if (!Sig.Hoisted.empty()) {
    F.HasHoisted = true;
    const std::vector<uint32_t> HOffsets = hoistedOffsets(Sig);
    for (size_t I = 0; I < Sig.Hoisted.size(); ++I) {
      const ValueType T{Sig.Hoisted[I].Type, false};
      F.Hoisted.push_back({Sig.Hoisted[I].Name, spelling(T), sizeOf(T), HOffsets[I]});
    }
    for (unsigned P : Sig.HoistedFrom)
      F.HoistedFrom.push_back(Sig.Params.at(P).Name);
  }
  return F;
}

kernel::ArgLayout argLayout(const CompiledGraph &CG, const CompiledArg &A) {
  kernel::ArgLayout J;
  J.Name = A.Name;
  switch (A.Src) {
  case CompiledArg::Source::Attribute:
    J.Src = kernel::ArgLayout::Source::Attribute;
    J.Attr = kernel::attributeName(static_cast<unsigned>(A.AttrId));
    J.Broadcast = A.Broadcast;
    break;
  case CompiledArg::Source::Node:
    J.Src = kernel::ArgLayout::Source::Node;
    J.Node = A.NodeIndex;
    J.Broadcast = A.Broadcast;
    break;
  case CompiledArg::Source::Constant:
    J.Src = kernel::ArgLayout::Source::Constant;
    if (A.Type.Base == BaseType::Sampler && !A.Values.empty()) {
      size_t Index = static_cast<size_t>(A.Values[0]);
      if (Index < CG.Images.size())
        J.Image = CG.Images[Index].first;
    }
    if (A.Type.IsGlobalArray) {
      J.IsArray = true;
      J.ArrayOffset = A.ArrayByteOffset;
      J.ArrayCount = A.ArrayCount;
    }
    J.IntValue = A.Type.Base == BaseType::Int || A.Type.Base == BaseType::Sampler;
    J.Value = A.Values;
    if (J.IntValue) // written as integers: truncated as the writer always did
      for (double &V : J.Value)
        V = static_cast<double>(static_cast<long long>(V));
    J.Bake = A.Bake;
    break;
  }
  J.Offset = A.BlockOffset;
  return J;
}

kernel::Bsdf bsdfLayout(const CompiledBsdf &B) {
  kernel::Bsdf J;
  J.Type = B.Type;
  for (const CompiledBsdfInput &In : B.Inputs) {
    kernel::BsdfInput I;
    I.IsOutput = In.IsOutput;
    I.Output = In.Output;
    if (!In.IsOutput)
      I.Constant = In.Constant;
    J.Inputs.push_back({In.Name, I});
  }
  for (const auto &[Name, Child] : B.Children)
    J.Children.push_back({Name, bsdfLayout(Child)});
  return J;
}

} // namespace

kernel::Manifest layoutManifest(const CompiledGraph &CG) {
  kernel::Manifest M;
  M.Graph = absolutePath(CG.GraphPath);
  M.StackSlots = CG.StackSlots;
  M.StackLimit = CG.StackLimit;
  M.Spill = CG.Spill;
  M.ValueStack = CG.Spill ? "global" : "private";
  M.MaxOutputs = CG.MaxOutputs;
  M.ScratchFloat4PerHit = CG.Spill ? CG.StackSlots : 0;
  M.ArgsBinSize = CG.ArgsBin.size();
  M.ProgramWords = CG.ProgramWords;
  M.RecordsOffset = CG.RecordsOffset;
  M.Attributes = CG.Attributes;
  M.Settings = CG.Settings;
  for (size_t I = 0; I < CG.Images.size(); ++I) {
    auto Cs = CG.ImageColorSpaces.find(CG.Images[I].first);
    M.Images.push_back({CG.Images[I].first, imagePath(CG.GraphPath, CG.Images[I].second),
                        static_cast<unsigned>(I),
                        Cs == CG.ImageColorSpaces.end() ? std::string() : Cs->second});
  }
  for (size_t Id = 0; Id < CG.FunctionsById.size(); ++Id) {
    auto It = CG.Signatures.find(CG.FunctionsById[Id]);
    if (It != CG.Signatures.end())
      M.Functions.push_back(functionLayout(static_cast<unsigned>(Id), It->second));
  }
  for (const QuickenedOp &Q : CG.Quickened) {
    kernel::QuickenedLayout L;
    L.Opcode = Q.Opcode;
    L.Function = Q.Fn;
    for (const ArgumentSource &S : Q.Sources)
      L.Sources.push_back(spellSource(S));
    M.Quickened.push_back(L);
  }
  for (size_t I = 0; I < CG.Nodes.size(); ++I) {
    const CompiledNode &N = CG.Nodes[I];
    kernel::NodeLayout L;
    L.Index = static_cast<unsigned>(I);
    L.Id = N.Id;
    L.Merged = N.MergedIds;
    L.Fn = N.Fn;
    L.FnId = N.FnId;
    L.RecordOffset = N.RecordOffset;
    L.RecordSize = N.RecordSize;
    L.Copies.assign(N.RecordCopies.begin(), N.RecordCopies.end());
    for (const CompiledArg &A : N.Args)
      L.Args.push_back(argLayout(CG, A));
    M.Nodes.push_back(std::move(L));
  }
  M.WavefrontOrder = CG.WavefrontOrder;
  for (const CompiledMaterial &Mat : CG.Materials) {
    kernel::MaterialLayout L;
    L.Name = Mat.Name;
    L.Index = Mat.Index;
    L.ProgramWordOffset = Mat.ProgramWordOffset;
    L.ProgramInstructions = static_cast<unsigned>(Mat.Program.size());
    L.ProgramStackSlots = Mat.StackSlots;
    for (const MaterialOutput &O : Mat.Outputs)
      L.Outputs.push_back({O.Node, O.Slot, spelling(O.Type)});
    L.Surface = bsdfLayout(Mat.Bsdf);
    M.Materials.push_back(std::move(L));
  }
  return M;
}

std::string layoutJson(const CompiledGraph &CG) { return kernel::writeManifest(layoutManifest(CG)); }

bool readLayoutQuickened(const kernel::Manifest &M, std::vector<QuickenedOp> &Table,
                         std::string &Error) {
  // The editor writes these opcodes into args.bin for the kernel's cases: an entry that names
  // a function the layout lacks, has a source per parameter wrong, or reuses an opcode would
  // run the wrong case (or none) silently, so it is an error here.
  std::map<std::string, std::vector<std::string>> ParamTypes;
  std::set<unsigned> Taken;
  for (const kernel::FunctionLayout &F : M.Functions) {
    std::vector<std::string> &Types = ParamTypes[F.Name];
    for (const kernel::ParamLayout &P : F.Params)
      Types.push_back(P.Type);
    Taken.insert(F.Id);
  }
  // A layout of texcc before 2026-12 may list superinstructions, and quickened pairs of them
  // ("second"): their opcodes stay the kernel's, but edits encode plain and single quickened
  // opcodes only, which that kernel has too.
  Taken.insert(M.LegacySuperinstructions.begin(), M.LegacySuperinstructions.end());
  for (size_t K = 0; K < M.Quickened.size(); ++K) {
    const kernel::QuickenedLayout &E = M.Quickened[K];
    const std::string Where = "/quickened/" + std::to_string(K) + ": ";
    if (E.Legacy) {
      Taken.insert(E.Opcode);
      continue;
    }
    QuickenedOp Q;
    Q.Opcode = E.Opcode;
    Q.Fn = E.Function;
    // One source per parameter, each a kind the kernel has a case for; "int:N" only for an int
    // parameter.
    auto It = ParamTypes.find(Q.Fn);
    if (It == ParamTypes.end()) {
      Error = Where + "function '" + Q.Fn + "' is not in /functions";
      return false;
    }
    if (E.Sources.size() != It->second.size()) {
      Error = Where + std::to_string(E.Sources.size()) + " sources for the " +
              std::to_string(It->second.size()) + " parameters of '" + Q.Fn + "'";
      return false;
    }
    for (size_t P = 0; P < E.Sources.size(); ++P) {
      const std::string &S = E.Sources[P];
      ArgumentSource T;
      if (!parseSource(S, T) ||
          (T.K == ArgumentSource::Kind::IntValue && It->second[P] != "int")) {
        Error = Where + "source '" + S + "' of parameter " + std::to_string(P) + " of '" + Q.Fn +
                "' (expected const, slot, slot.x, attr:Name, attr:Name.x" +
                (It->second[P] == "int" ? " or int:N" : "") + ")";
        return false;
      }
      Q.Sources.push_back(T);
    }
    if (!Taken.insert(Q.Opcode).second) {
      Error = Where + "opcode " + std::to_string(Q.Opcode) +
              " is already a function id, a superinstruction's or another entry's";
      return false;
    }
    Table.push_back(Q);
  }
  return true;
}

bool readLayoutSignatures(const kernel::Manifest &M, SignatureMap &Sigs,
                          std::map<std::string, unsigned> &FnIds, std::string &Error) {
  for (const kernel::FunctionLayout &F : M.Functions) {
    FunctionSignature S;
    S.Name = F.Name;
    S.RenamedName = F.Renamed;
    S.File = F.File;
    auto Ret = parseSpelling(F.Return);
    if (!Ret || Ret->IsGlobalArray) {
      Error = "function '" + S.Name + "': bad return type";
      return false;
    }
    S.Return = Ret->Base;
    for (const kernel::ParamLayout &P : F.Params) {
      auto T = parseSpelling(P.Type);
      if (!T) {
        Error = "function '" + S.Name + "': bad parameter type '" + P.Type + "'";
        return false;
      }
      S.Params.push_back({P.Name, *T});
    }
    S.Attributes = F.Attributes;
    S.Settings = F.Settings;
    S.Cost = F.Cost;
    for (const kernel::HoistedLayout &V : F.Hoisted) {
      auto T = parseSpelling(V.Type);
      if (!T || T->IsGlobalArray || T->Base == BaseType::Sampler) {
        Error = "function '" + S.Name + "': bad hoisted type '" + V.Type + "'";
        return false;
      }
      S.Hoisted.push_back({V.Name, T->Base});
    }
    for (const std::string &Name : F.HoistedFrom) {
      auto It = std::find_if(S.Params.begin(), S.Params.end(),
                             [&](const Param &Q) { return Q.Name == Name; });
      if (It == S.Params.end()) {
        Error = "function '" + S.Name + "': hoisted from an unknown parameter '" + Name + "'";
        return false;
      }
      S.HoistedFrom.push_back(static_cast<unsigned>(It - S.Params.begin()));
    }
    FnIds[S.Name] = F.Id;
    Sigs[S.Name] = std::move(S);
  }
  return true;
}

namespace {
bool readText(const std::string &Text, kernel::Manifest &M, std::string &Error) {
  kernel::ManifestError E;
  if (kernel::readManifest(Text, "layout.json", M, E))
    return true;
  Error = "malformed " + E.str();
  return false;
}
} // namespace

bool readLayoutQuickened(const std::string &LayoutJsonText, std::vector<QuickenedOp> &Table,
                         std::string &Error) {
  kernel::Manifest M;
  return readText(LayoutJsonText, M, Error) && readLayoutQuickened(M, Table, Error);
}

bool readLayoutSignatures(const std::string &LayoutJsonText, SignatureMap &Sigs,
                          std::map<std::string, unsigned> &FnIds, std::string &Error) {
  kernel::Manifest M;
  return readText(LayoutJsonText, M, Error) && readLayoutSignatures(M, Sigs, FnIds, Error);
}

} // namespace texcc::graph
