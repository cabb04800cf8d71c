#include "texcc/Frontend/Library.h"

#include "texcc/Frontend/Frontend.h"
#include "texcc/Graph/Types.h"
#include "texcc/Support/File.h"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <set>

namespace fs = std::filesystem;

namespace gr = texcc::graph;

namespace texcc::frontend {

std::string libraryDir() {
  if (const char *Env = std::getenv("TEXCC_LIBRARY_DIR"); Env && *Env)
    return Env;
  return TEXCC_LIBRARY_DIR;
}

std::vector<std::string> libraryFiles(const std::string &Dir) {
  std::vector<std::string> Top, Nested;
  std::error_code EC;
  for (fs::recursive_directory_iterator It(Dir, EC), End; !EC && It != End; It.increment(EC)) {
    if (!It->is_regular_file(EC) || It->path().extension() != ".cl")
      continue;
    (It.depth() == 0 ? Top : Nested).push_back(It->path().string());
  }
  std::sort(Top.begin(), Top.end());
  std::sort(Nested.begin(), Nested.end());
  Top.insert(Top.end(), Nested.begin(), Nested.end());
  return Top;
}

namespace {

/// The comment block a file opens with (one /* */ block or consecutive // lines), or "".
std::string openingComment(const std::string &Text) {
  size_t I = Text.find_first_not_of(" \t\r\n");
  if (I == std::string::npos)
    return "";
  if (Text.compare(I, 2, "/*") == 0) {
    size_t End = Text.find("*/", I + 2);
    return Text.substr(I, End == std::string::npos ? std::string::npos : End + 2 - I);
  }
  std::string Block;
  while (I < Text.size() && Text.compare(I, 2, "//") == 0) {
    size_t Eol = Text.find('\n', I);
    Block += Text.substr(I, Eol == std::string::npos ? std::string::npos : Eol + 1 - I);
    if (Eol == std::string::npos)
      break;
    I = Text.find_first_not_of(" \t\r", Eol + 1);
    if (I == std::string::npos)
      break;
  }
  return Block;
}

bool isIdentChar(char C) { return std::isalnum(static_cast<unsigned char>(C)) || C == '_'; }

/// Where Name occurs as a whole word in Text, or npos.
size_t findWord(const std::string &Text, const std::string &Name, size_t From = 0) {
  for (size_t I = Text.find(Name, From); I != std::string::npos; I = Text.find(Name, I + 1)) {
    bool Before = I > 0 && isIdentChar(Text[I - 1]);
    bool After = I + Name.size() < Text.size() && isIdentChar(Text[I + Name.size()]);
    if (!Before && !After)
      return I;
  }
  return std::string::npos;
}

std::string trim(const std::string &S) {
  size_t B = S.find_first_not_of(" \t*`"), E = S.find_last_not_of(" \t`");
  return B == std::string::npos ? "" : S.substr(B, E + 1 - B);
}

/// Whether the comment names Name as a function: the word followed by "(", ",", "/", ":" or
/// the end of its line (a word in running text, like "the quintic fade 6t^5", is not a
/// listing).
bool namesFunction(const std::string &Comment, const std::string &Name) {
  for (size_t I = findWord(Comment, Name); I != std::string::npos;
       I = findWord(Comment, Name, I + 1)) {
    size_t After = Comment.find_first_not_of(" \t", I + Name.size());
    if (After == std::string::npos || std::string("(,/:\r\n").find(Comment[After]) !=
                                          std::string::npos)
      return true;
    if (Comment.compare(After, 2, "*/") == 0)
      return true;
  }
  return false;
}

/// Splits at top-level separators: commas outside parentheses, or " / ".
std::vector<std::string> splitValues(const std::string &S) {
  std::vector<std::string> Parts;
  std::string Cur;
  int Depth = 0;
  for (size_t I = 0; I < S.size(); ++I) {
    char C = S[I];
    Depth += C == '(' ? 1 : C == ')' ? -1 : 0;
    bool Slash = C == '/' && I > 0 && S[I - 1] == ' ' && I + 1 < S.size() && S[I + 1] == ' ';
    if (Depth == 0 && (C == ',' || Slash)) {
      Parts.push_back(trim(Cur));
      Cur.clear();
      continue;
    }
    Cur += C;
  }
  Parts.push_back(trim(Cur));
  return Parts;
}

/// The parameter names of a table's first cell: "x, y, z"; "color1/2" is color1 and color2.
std::vector<std::string> splitNames(std::string Cell) {
  for (char &C : Cell)
    if (!isIdentChar(C))
      C = ' ';
  std::vector<std::string> Names;
  size_t I = 0;
  while ((I = Cell.find_first_not_of(' ', I)) != std::string::npos) {
    size_t E = std::min(Cell.find(' ', I), Cell.size());
    std::string Word = Cell.substr(I, E - I);
    I = E;
    bool Digits = Word.find_first_not_of("0123456789") == std::string::npos;
    if (Digits && !Names.empty() && std::isdigit(static_cast<unsigned char>(Names.back().back()))) {
      std::string Stem = Names.back();
      Stem.erase(Stem.find_last_not_of("0123456789") + 1);
      Names.push_back(Stem + Word);
    } else if (!Digits) {
      Names.push_back(Word);
    }
  }
  return Names;
}

/// Where a parameter table's cells are: from its header row ("| name | type | default | range |
/// meaning |"); a table without one has name, type and default in its first three cells.
struct TableColumns {
  int Name = 0, Type = 1, Default = 2, Range = -1, Text = -1;
};

/// The cells of a markdown table row ("| a | b |" -> a, b), or none when Line is not one.
std::vector<std::string> tableCells(const std::string &Line) {
  std::vector<std::string> Cells;
  size_t Bar = Line.find('|');
  if (Bar == std::string::npos)
    return Cells;
  for (size_t Next; (Next = Line.find('|', Bar + 1)) != std::string::npos; Bar = Next)
    Cells.push_back(trim(Line.substr(Bar + 1, Next - Bar - 1)));
  return Cells;
}

/// The header row's columns, if Cells is one (it names "name" and "type").
std::optional<TableColumns> headerColumns(const std::vector<std::string> &Cells) {
  TableColumns C;
  C.Name = C.Type = C.Default = -1;
  for (size_t I = 0; I < Cells.size(); ++I) {
    std::string H = Cells[I];
    std::transform(H.begin(), H.end(), H.begin(), [](unsigned char X) { return std::tolower(X); });
    const int Col = static_cast<int>(I);
    if (H == "name")
      C.Name = Col;
    else if (H == "type")
      C.Type = Col;
    else if (H == "default")
      C.Default = Col;
    else if (H == "range")
      C.Range = Col;
    else if (H == "meaning" || H == "description")
      C.Text = Col;
  }
  if (C.Name < 0 || C.Type < 0)
    return std::nullopt;
  return C;
}

std::string cell(const std::vector<std::string> &Cells, int Col) {
  return Col >= 0 && static_cast<size_t>(Col) < Cells.size() ? Cells[Col] : std::string();
}

/// Parameter name -> its row, from the rows of the comment's markdown tables whose type cell
/// names a type: the default as written ("-": none), the range and the meaning. A default of as
/// many values as names ("0.5, 2" for "offsetAmount, offsetFrequency") is one per name; the
/// first row naming a parameter wins.
std::map<std::string, kernel::ParamDoc> parameterTable(const std::string &Comment) {
  std::map<std::string, kernel::ParamDoc> Rows;
  TableColumns Cols;
  size_t Pos = 0;
  while (Pos < Comment.size()) {
    size_t Eol = Comment.find('\n', Pos);
    std::string Line = Comment.substr(Pos, Eol == std::string::npos ? std::string::npos
                                                                     : Eol - Pos);
    Pos = Eol == std::string::npos ? Comment.size() : Eol + 1;
    std::vector<std::string> Cells = tableCells(Line);
    if (Cells.size() < 3) {
      Cols = TableColumns(); // a table ends
      continue;
    }
    if (std::optional<TableColumns> Header = headerColumns(Cells)) {
      Cols = *Header;
      continue;
    }
    if (Cells[0].find("---") != std::string::npos)
      continue;
    const std::string Type = cell(Cells, Cols.Type);
    bool IsType = false;
    for (const char *T : {"float", "int", "uint", "sam2D", "__global"})
      IsType |= Type.rfind(T, 0) == 0;
    if (!IsType)
      continue;
    std::string Default = cell(Cells, Cols.Default);
    if (Default == "-")
      Default.clear();
    std::vector<std::string> Names = splitNames(cell(Cells, Cols.Name));
    std::vector<std::string> Values = splitValues(Default);
    for (size_t N = 0; N < Names.size(); ++N) {
      kernel::ParamDoc D;
      D.DefaultText =
          Values.size() == Names.size() && Names.size() > 1 ? Values[N] : Default;
      D.RangeText = cell(Cells, Cols.Range);
      if (D.RangeText == "-")
        D.RangeText.clear();
      D.Text = cell(Cells, Cols.Text);
      Rows.emplace(Names[N], std::move(D));
    }
  }
  return Rows;
}

/// Text as a number, if all of it is one.
std::optional<double> number(std::string Text) {
  Text = trim(Text);
  if (Text.empty())
    return std::nullopt;
  char *End = nullptr;
  double V = std::strtod(Text.c_str(), &End);
  if (End != Text.c_str() + Text.size() || !std::isfinite(V))
    return std::nullopt;
  return V;
}

/// A default as written ("(0.7, 0.3, 0.2)", "0.8 gray", "-1, -1, -1", "0 (color 0.5)") as a
/// value of type T: the numbers it starts with, one per component or one for all; empty when
/// it is not that (a word, a count that does not fit, a fraction for an int, an array).
std::vector<double> readDefault(const std::string &Text, const gr::ValueType &T) {
  if (T.IsGlobalArray || T.Base == gr::BaseType::Sampler)
    return {};
  const size_t Width = gr::componentCount(T.Base);
  std::string Flat = Text;
  for (char &C : Flat)
    if (C == '(' || C == ')' || C == ',')
      C = ' ';
  std::vector<double> Values;
  size_t I = 0;
  while ((I = Flat.find_first_not_of(" \t", I)) != std::string::npos) {
    size_t E = std::min(Flat.find_first_of(" \t", I), Flat.size());
    std::optional<double> V = number(Flat.substr(I, E - I));
    if (!V)
      break; // "gray", "color 0.5": words end the value
    Values.push_back(*V);
    I = E;
  }
  if (Values.size() == 1 && Width > 1)
    Values.assign(Width, Values[0]);
  if (Values.size() != Width)
    return {};
  if (T.Base == gr::BaseType::Int)
    for (double V : Values)
      if (V != std::floor(V) || std::fabs(V) > 2147483647.0)
        return {};
  return Values;
}

/// The bounds a range states: "0..1", "1..len" (a lower bound), "> 0", ">= 1", "0, 1, 2"
/// (the smallest and largest); nothing for "any", "!= 0" and other words.
void readRange(const std::string &Text, kernel::ParamDoc &D) {
  size_t Dots = Text.find("..");
  if (Dots != std::string::npos) {
    D.Min = number(Text.substr(0, Dots));
    D.Max = number(Text.substr(Dots + 2));
    return;
  }
  std::string T = trim(Text);
  for (const char *Op : {">=", ">", "<=", "<"})
    if (T.rfind(Op, 0) == 0) {
      (Op[0] == '>' ? D.Min : D.Max) = number(T.substr(std::strlen(Op)));
      return;
    }
  std::vector<std::string> Items = splitValues(T);
  if (Items.size() < 2)
    return;
  for (const std::string &Item : Items) {
    std::optional<double> V = number(Item);
    if (!V) {
      D.Min = D.Max = std::nullopt;
      return;
    }
    D.Min = std::min(D.Min.value_or(*V), *V);
    D.Max = std::max(D.Max.value_or(*V), *V);
  }
}

/// Param's row of Table (none: an empty row), its default read for its type.
kernel::ParamDoc paramDoc(const std::map<std::string, kernel::ParamDoc> &Table,
                          const gr::Param &P) {
  auto It = Table.find(P.Name);
  if (It == Table.end())
    return {};
  kernel::ParamDoc D = It->second;
  D.Default = readDefault(D.DefaultText, P.Type);
  if (!P.Type.IsGlobalArray && P.Type.Base != gr::BaseType::Sampler)
    readRange(D.RangeText, D);
  return D;
}

/// The functions File defines that its opening comment names, in order of definition.
std::vector<std::string> documentedFunctions(const frontend::TranslatedSource &Source,
                                             const std::string &Text,
                                             const std::string &Comment) {
  std::vector<std::pair<size_t, std::string>> Found;
  for (const auto &KV : Source.Functions) {
    if (!namesFunction(Comment, KV.first))
      continue;
    size_t Def = findWord(Text, KV.first, Comment.size());
    Found.push_back({Def, KV.first});
  }
  std::sort(Found.begin(), Found.end());
  std::vector<std::string> Names;
  for (auto &F : Found)
    Names.push_back(F.second);
  return Names;
}

struct LibraryFile {
  std::string Path, Text, Comment;
  std::vector<std::string> Documented;
};

/// Reads and parses Files (one front-end run) and finds each file's documented functions.
bool scanFiles(const std::vector<std::string> &Files, std::vector<LibraryFile> &Out,
               llvm::raw_ostream &Diags) {
  frontend::FrontendOptions Opts;
  auto FR = frontend::runFrontend(Files, {}, Opts, Diags);
  if (!FR) {
    Diags << "texcc: error: " << llvm::toString(FR.takeError()) << "\n";
    return false;
  }
  for (size_t I = 0; I < Files.size() && I < FR->Sources.size(); ++I) {
    LibraryFile F;
    F.Path = Files[I];
    std::string Why;
    if (!texcc::readRegularFile(F.Path, F.Text, Why)) {
      Diags << "texcc: error: cannot read '" << F.Path << "': " << Why << "\n";
      return false;
    }
    F.Comment = openingComment(F.Text);
    F.Documented = documentedFunctions(FR->Sources[I], F.Text, F.Comment);
    Out.push_back(std::move(F));
  }
  return true;
}

/// The signatures of F's documented functions that are texture functions: one front-end run
/// for the file, and, if some name is not a texture function (a helper the comment mentions),
/// one per name, keeping those that pass.
gr::SignatureMap textureSignatures(const LibraryFile &F) {
  frontend::FrontendOptions Opts;
  std::set<std::string> Names(F.Documented.begin(), F.Documented.end());
  if (auto FR = frontend::runFrontend({F.Path}, Names, Opts, llvm::nulls()))
    return FR->Textures;
  else
    llvm::consumeError(FR.takeError());
  gr::SignatureMap Sigs;
  for (const std::string &Name : F.Documented) {
    auto FR = frontend::runFrontend({F.Path}, {Name}, Opts, llvm::nulls());
    if (!FR) {
      llvm::consumeError(FR.takeError());
      continue;
    }
    Sigs.insert(FR->Textures.begin(), FR->Textures.end());
  }
  return Sigs;
}

} // namespace

namespace {

/// A function's parameters and their rows, as --list-nodes --json writes them (the fields of
/// layout.json's functions[].params[].doc, docs/abi.md).
nlohmann::ordered_json paramJson(const gr::Param &P, const kernel::ParamDoc &D) {
  nlohmann::ordered_json J = {{"name", P.Name}, {"type", gr::spelling(P.Type)}};
  J.update(kernel::paramDocJson(D));
  return J;
}

} // namespace

bool listNodes(const std::vector<std::string> &Files, llvm::raw_ostream &OS,
               llvm::raw_ostream &Diags, bool Json) {
  std::vector<LibraryFile> Scanned;
  if (!scanFiles(Files, Scanned, Diags))
    return false;
  nlohmann::ordered_json JsonFiles = nlohmann::ordered_json::array();
  for (const LibraryFile &F : Scanned) {
    gr::SignatureMap Sigs = textureSignatures(F);
    std::map<std::string, kernel::ParamDoc> Table = parameterTable(F.Comment);
    nlohmann::ordered_json Functions = nlohmann::ordered_json::array();
    if (!Json)
      OS << F.Path << ":\n";
    unsigned Listed = 0;
    for (const std::string &Name : F.Documented) {
      auto It = Sigs.find(Name);
      if (It == Sigs.end())
        continue;
      const gr::FunctionSignature &Sig = It->second;
      ++Listed;
      if (Json) {
        nlohmann::ordered_json Params = nlohmann::ordered_json::array();
        for (const gr::Param &P : Sig.Params)
          Params.push_back(paramJson(P, paramDoc(Table, P)));
        Functions.push_back(
            {{"name", Name}, {"return", gr::spelling(Sig.Return)}, {"params", Params}});
        continue;
      }
      OS << "  " << gr::spelling(Sig.Return) << " " << Name << "(";
      for (size_t P = 0; P < Sig.Params.size(); ++P) {
        const gr::Param &Param = Sig.Params[P];
        OS << (P ? ", " : "") << gr::spelling(Param.Type) << " " << Param.Name;
        if (auto D = Table.find(Param.Name); D != Table.end() && !D->second.DefaultText.empty())
          OS << " = " << D->second.DefaultText;
      }
      OS << ")\n";
    }
    if (Json)
      JsonFiles.push_back({{"file", F.Path}, {"functions", Functions}});
    else if (!Listed)
      OS << "  (no documented texture function)\n";
  }
  if (Json)
    OS << nlohmann::ordered_json{{"files", JsonFiles}}.dump(1, ' ', false,
                                                            nlohmann::json::error_handler_t::replace)
       << "\n";
  return true;
}

std::map<std::string, std::vector<kernel::ParamDoc>>
parameterDocs(const gr::SignatureMap &Sigs) {
  std::map<std::string, std::map<std::string, kernel::ParamDoc>> Tables; // by file
  std::map<std::string, std::vector<kernel::ParamDoc>> Docs;
  for (const auto &[Name, Sig] : Sigs) {
    auto T = Tables.find(Sig.File);
    if (T == Tables.end()) {
      std::string Text, Why;
      std::map<std::string, kernel::ParamDoc> Table;
      if (texcc::readRegularFile(Sig.File, Text, Why))
        Table = parameterTable(openingComment(Text));
      T = Tables.emplace(Sig.File, std::move(Table)).first;
    }
    std::vector<kernel::ParamDoc> &Out = Docs[Name];
    for (const gr::Param &P : Sig.Params)
      Out.push_back(paramDoc(T->second, P));
  }
  return Docs;
}

int listNodesCommand(const std::vector<std::string> &Files, bool Json) {
  std::vector<std::string> List = Files.empty() ? libraryFiles(libraryDir()) : Files;
  if (List.empty()) {
    llvm::errs() << "texcc: error: no texture files in the library '" << libraryDir()
                 << "' (set TEXCC_LIBRARY_DIR)\n";
    return 1;
  }
  return listNodes(List, llvm::outs(), llvm::errs(), Json) ? 0 : 1;
}

std::map<std::string, std::string> libraryTextureFiles(const std::string &Dir) {
  std::vector<LibraryFile> Scanned;
  std::map<std::string, std::string> Where;
  if (!scanFiles(libraryFiles(Dir), Scanned, llvm::nulls()))
    return Where;
  fs::path Root = fs::path(Dir).lexically_normal().parent_path();
  if (Root.filename().empty()) // "textures/" normalises to "textures/", its parent "textures"
    Root = Root.parent_path();
  for (const LibraryFile &F : Scanned)
    for (const std::string &Name : F.Documented)
      Where.emplace(Name, fs::path(F.Path).lexically_relative(Root).generic_string());
  return Where;
}

} // namespace texcc::frontend
