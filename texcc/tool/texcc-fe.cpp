// texcc-fe: a development driver for the front end alone. Prints the rewritten user code of
// every file (as it would be pasted into proctex.cl), then the texture signatures as JSON.
#include "texcc/Frontend/Frontend.h"
#include "texcc/StackGuard.h"

#include "llvm/Support/CommandLine.h"
#include "llvm/Support/JSON.h"
#include "llvm/Support/raw_ostream.h"

using namespace llvm;
namespace fe = texcc::frontend;

static cl::OptionCategory FeCategory("texcc-fe options");
static cl::list<std::string> Sources(cl::Positional, cl::desc("FILE.cl..."), cl::OneOrMore,
                                     cl::cat(FeCategory));
static cl::list<std::string> Textures("texture", cl::desc("A texture function to describe"),
                                      cl::value_desc("NAME"), cl::cat(FeCategory));
static cl::list<std::string> IncludeDirs("I", cl::Prefix, cl::desc("Add an include directory"),
                                         cl::value_desc("DIR"), cl::cat(FeCategory));
static cl::list<std::string> Defines("D", cl::Prefix, cl::desc("Define a macro"),
                                     cl::value_desc("NAME[=V]"), cl::cat(FeCategory));

static json::Array strings(const std::vector<std::string> &V) {
  return json::Array(std::vector<json::Value>(V.begin(), V.end()));
}

static json::Object describe(const texcc::graph::FunctionSignature &Sig,
                             const std::set<std::string> &Reachable) {
  json::Array Params;
  for (const auto &P : Sig.Params)
    Params.push_back(json::Object{{"name", P.Name}, {"type", texcc::graph::spelling(P.Type)}});
  return json::Object{
      {"renamed", Sig.RenamedName},
      {"file", Sig.File},
      {"return", texcc::graph::spelling(Sig.Return)},
      {"params", std::move(Params)},
      {"attributes", strings(Sig.Attributes)},
      {"settings", strings(Sig.Settings)},
      {"reachable", strings({Reachable.begin(), Reachable.end()})}};
}

static int run() {
  fe::FrontendOptions Opts;
  Opts.IncludeDirs.assign(IncludeDirs.begin(), IncludeDirs.end());
  Opts.Defines.assign(Defines.begin(), Defines.end());
  std::set<std::string> Names(Textures.begin(), Textures.end());
  auto Result = fe::runFrontend({Sources.begin(), Sources.end()}, Names, Opts, errs());
  if (!Result) {
    errs() << "texcc-fe: error: " << toString(Result.takeError()) << "\n";
    return 1;
  }
  for (const fe::TranslatedSource &S : Result->Sources)
    outs() << S.render();
  json::Object Sigs;
  for (const auto &[Name, Sig] : Result->Textures)
    Sigs[Name] = describe(Sig, Result->Reachable[Name]);
  outs() << "// texcc-fe signatures:\n" << formatv("{0:2}", json::Value(std::move(Sigs))) << "\n";
  return 0;
}

int main(int argc, char **argv) {
  cl::HideUnrelatedOptions(FeCategory);
  cl::ParseCommandLineOptions(argc, argv, "texcc-fe: runs texcc's front end on user textures\n");
  return texcc::runWithLargeStack(run, "texcc-fe");
}
