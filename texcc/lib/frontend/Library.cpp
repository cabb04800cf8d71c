#include "texcc/Frontend/Library.h"

#include "texcc/Frontend/Frontend.h"
#include "texcc/Graph/Types.h"
#include "texcc/Support/File.h"

#include <algorithm>
#include <cctype>
#include <cstdlib>
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

/// Parameter name -> default, from the rows of the comment's markdown tables whose first
/// three cells are names ("x, y, z"), a type and the default ("-": none). A default of as many
/// values as names ("0.5, 2" for "offsetAmount, offsetFrequency") is one per name; the first
/// row naming a parameter wins.
std::map<std::string, std::string> tableDefaults(const std::string &Comment) {
  std::map<std::string, std::string> Defaults;
  size_t Pos = 0;
  while (Pos < Comment.size()) {
    size_t Eol = Comment.find('\n', Pos);
    std::string Line = Comment.substr(Pos, Eol == std::string::npos ? std::string::npos
                                                                     : Eol - Pos);
    Pos = Eol == std::string::npos ? Comment.size() : Eol + 1;
    size_t Bar = Line.find('|');
    if (Bar == std::string::npos)
      continue;
    std::vector<std::string> Cells;
    for (size_t Next; (Next = Line.find('|', Bar + 1)) != std::string::npos; Bar = Next)
      Cells.push_back(trim(Line.substr(Bar + 1, Next - Bar - 1)));
    if (Cells.size() < 3 || Cells[0] == "name" || Cells[0].find("---") != std::string::npos)
      continue;
    const std::string &Type = Cells[1], &Default = Cells[2];
    bool IsType = false;
    for (const char *T : {"float", "int", "uint", "sam2D", "__global"})
      IsType |= Type.rfind(T, 0) == 0;
    if (!IsType || Default.empty() || Default == "-")
      continue;
    std::vector<std::string> Names = splitNames(Cells[0]);
    std::vector<std::string> Values = splitValues(Default);
    for (size_t N = 0; N < Names.size(); ++N)
      Defaults.emplace(Names[N], Values.size() == Names.size() && Names.size() > 1 ? Values[N]
                                                                                 : Default);
  }
  return Defaults;
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

bool listNodes(const std::vector<std::string> &Files, llvm::raw_ostream &OS,
               llvm::raw_ostream &Diags) {
  std::vector<LibraryFile> Scanned;
  if (!scanFiles(Files, Scanned, Diags))
    return false;
  for (const LibraryFile &F : Scanned) {
    gr::SignatureMap Sigs = textureSignatures(F);
    std::map<std::string, std::string> Defaults = tableDefaults(F.Comment);
    OS << F.Path << ":\n";
    unsigned Listed = 0;
    for (const std::string &Name : F.Documented) {
      auto It = Sigs.find(Name);
      if (It == Sigs.end())
        continue;
      const gr::FunctionSignature &Sig = It->second;
      OS << "  " << gr::spelling(Sig.Return) << " " << Name << "(";
      for (size_t P = 0; P < Sig.Params.size(); ++P) {
        const gr::Param &Param = Sig.Params[P];
        OS << (P ? ", " : "") << gr::spelling(Param.Type) << " " << Param.Name;
        if (auto D = Defaults.find(Param.Name); D != Defaults.end())
          OS << " = " << D->second;
      }
      OS << ")\n";
      ++Listed;
    }
    if (!Listed)
      OS << "  (no documented texture function)\n";
  }
  return true;
}

int listNodesCommand(const std::vector<std::string> &Files) {
  std::vector<std::string> List = Files.empty() ? libraryFiles(libraryDir()) : Files;
  if (List.empty()) {
    llvm::errs() << "texcc: error: no texture files in the library '" << libraryDir()
                 << "' (set TEXCC_LIBRARY_DIR)\n";
    return 1;
  }
  return listNodes(List, llvm::outs(), llvm::errs()) ? 0 : 1;
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
