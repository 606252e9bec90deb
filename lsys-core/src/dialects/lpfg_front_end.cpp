// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// lpfg's `.l` files (Karwowski and Prusinkiewicz, "Design and implementation
// of the L+C modeling language", 2003; the lpfg manual in vlab;
// docs/dialects/lpfg.md): the C preprocessor and cpfg's view file, then
// statements that end in `;` — `derivation length: n;`, `module A(float);`,
// `Axiom: …;`, sections, `maximum depth: n;` — and rules `pred : { … }` whose
// C++ bodies `produce` their successors. lpfg compiles the C++; lsolid reads
// the part of it that its examples write (cpfg's statements with typed
// declarations, `for`, `+=`, `++`, `produce`, `nproduce`) and refuses the
// rest at its place.
#include <array>
#include <optional>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "dialects/front_ends.hpp"
#include "dialects/grammar_builder.hpp"

namespace lsys::dialects {
namespace {

// lpfg's standard modules (its stdmods.h) that lsolid draws, by their
// turtle commands; widths and the frame are cpfg's.
const std::vector<SymbolCommand> kSymbols = {
    {"F", TurtleCommand::Draw, std::nullopt},
    {"f", TurtleCommand::Move, std::nullopt},
    {"G", TurtleCommand::DrawNoVertex, std::nullopt},
    {"g", TurtleCommand::MoveNoVertex, std::nullopt},
    {"Left", TurtleCommand::TurnLeft, std::nullopt},
    {"Right", TurtleCommand::TurnRight, std::nullopt},
    {"Down", TurtleCommand::PitchDown, std::nullopt},
    {"Up", TurtleCommand::PitchUp, std::nullopt},
    {"RollL", TurtleCommand::RollLeft, std::nullopt},
    {"RollR", TurtleCommand::RollRight, std::nullopt},
    {"TurnAround", TurtleCommand::TurnAround, std::nullopt},
    {"RollToVert", TurtleCommand::RollToVertical, std::nullopt},
    {"SB", TurtleCommand::Push, std::nullopt},
    {"EB", TurtleCommand::Pop, std::nullopt},
    {"SP", TurtleCommand::PolygonBegin, std::nullopt},
    {"PP", TurtleCommand::PolygonVertex, std::nullopt},
    {"EP", TurtleCommand::PolygonEnd, std::nullopt},
    {"IncColor", TurtleCommand::ColorNext, std::nullopt},
    {"DecColor", TurtleCommand::ColorPrevious, std::nullopt},
    {"SetColor", TurtleCommand::ColorNext, std::nullopt},
    {"SetWidth", TurtleCommand::Width, std::nullopt},
    {"Cut", TurtleCommand::Cut, std::nullopt},
    // Radii, where cpfg's `@O` and `@c` take diameters.
    {"Sphere", TurtleCommand::Sphere, std::nullopt},
    {"Sphere0", TurtleCommand::Sphere, std::nullopt},
    {"Circle", TurtleCommand::DiscAcrossUp, std::nullopt},
    {"Circle0", TurtleCommand::DiscAcrossUp, std::nullopt},
    {"CircleFront", TurtleCommand::DiscFacingViewer, std::nullopt},
    {"CircleFront0", TurtleCommand::DiscFacingViewer, std::nullopt},
    {"MoveTo", TurtleCommand::MoveTo, std::nullopt},
    {"LineTo", TurtleCommand::LineTo, std::nullopt},
    {"SetHead", TurtleCommand::SetHeading, std::nullopt},
    {"Elasticity", TurtleCommand::ElasticityChange, std::nullopt},
    {"SetElasticity", TurtleCommand::MovementElasticity, std::nullopt},
    {"IncElasticity", TurtleCommand::MovementElasticityUp, std::nullopt},
    {"DecElasticity", TurtleCommand::MovementElasticityDown, std::nullopt},
    {"GetPos", TurtleCommand::QueryPosition, std::nullopt},
    {"GetHead", TurtleCommand::QueryHeading, std::nullopt},
    {"GetLeft", TurtleCommand::QueryLeft, std::nullopt},
    {"GetUp", TurtleCommand::QueryUp, std::nullopt},
    // Rendering only: textures, the camera, precisions.
    {"CurrentTexture", TurtleCommand::None, std::nullopt},
    {"TextureVCoeff", TurtleCommand::None, std::nullopt},
    {"Camera", TurtleCommand::None, std::nullopt},
    {"SetUPrecision", TurtleCommand::None, std::nullopt},
    {"SetVPrecision", TurtleCommand::None, std::nullopt},
};

const std::vector<RefusedName> kLeftOut = {{"Label", "a label"}};

const std::vector<RefusedName> kRefused = {
    {"Surface", "a predefined surface"},
    {"Surface3", "a predefined surface"},
    {"BSurface", "a B-spline surface"},
    {"DSurface", "a surface built by the program"},
    {"Mesh", "a mesh"},
    {"Mesh3", "a mesh"},
    {"StartGC", "a generalized cylinder"},
    {"PointGC", "a generalized cylinder"},
    {"EndGC", "a generalized cylinder"},
    {"CurrentContour", "a contour"},
    {"BlendedContour", "a contour"},
    {"ScaleContour", "a contour"},
    {"ContourSides", "a contour"},
    {"Line2f", "a line between points"},
    {"Line3f", "a line between points"},
    {"LineTo3f", "a line to a point"},
    {"LineRel3f", "a relative line"},
    {"MoveTo3f", "a move to a point given as a vector"},
    {"SetHead3f", "a heading given as a vector"},
    {"E1", "a query of the environment"},
    {"E2", "a query of the environment"},
    {"Rotate", "a rotation about a vector"},
    {"RotateHLU", "a rotation about a vector"},
    {"RotateXYZ", "a rotation about a vector"},
    {"Orient", "a turn toward the viewer"},
    {"Rhombus", "a rhombus"},
    {"Triangle", "a triangle"},
    {"Terrain", "a terrain"},
    {"MouseIns", "the mouse"},
    {"MouseInsPos", "the mouse"},
};

// lpfg's header and the system's, which an lpfg file includes for names
// lsolid knows or refuses where they are used; a file of the model's own
// (`#include "data.h"`) is text lsolid does not have.
constexpr std::array<std::string_view, 24> kHeaders{
    "lpfgall.h", "math.h",  "stdlib.h",  "stdio.h", "string.h", "time.h",
    "assert.h",  "float.h", "limits.h",  "cmath",   "cstdlib",  "cstdio",
    "cstring",   "ctime",   "cassert",   "climits", "iostream", "fstream",
    "sstream",   "vector",  "algorithm", "string",  "GL/gl.h",  "GL/glu.h"};

constexpr std::array<std::string_view, 7> kTypes{
    "float", "double", "int", "bool", "long", "unsigned", "const"};

// `text` between quotes, then `rest` (built with +=: GCC 12 warns of a
// chain of string additions, wrongly, under -Wrestrict).
std::string quoted(std::string_view text, std::string_view rest) {
  std::string out = "'";
  out += text;
  out += "'";
  out += rest;
  return out;
}

class LpfgReader : TextScan {
 public:
  LpfgReader(std::shared_ptr<const SourceFile> source, Draft draft,
             const ParseOptions& options)
      : TextScan(source, source->text()),
        draft_(std::move(draft)),
        options_(options) {}

  Grammar run() {
    std::size_t i = 0;
    while (i < text_.size()) {
      skip_space(i);
      if (i >= text_.size()) break;
      if (text_[i] == '#') {
        std::size_t end = text_.find('\n', i);
        if (end == std::string_view::npos) end = text_.size();
        directive(Range{i, end});
        i = end;
        continue;
      }
      i = item(i);
    }
    // lpfg's names, not cpfg's symbols (the view's settings stay).
    draft_.symbols = kSymbols;
    draft_.refused = kRefused;
    draft_.left_out = kLeftOut;
    Settings& s = draft_.defaults;
    s.roll = RollConvention::Lpfg;
    s.sphere_diameter_per_parameter = 2.0;  // Sphere(r), Circle(r)
    draft_.syntax.single_character_modules = false;
    draft_.syntax.several_module_predecessors = true;
    draft_.syntax.identifier_modules = true;
    draft_.syntax.c_language = true;
    draft_.syntax.radians = true;  // C's sin and cos
    draft_.syntax.probability_after_successor = false;
    draft_.constants.emplace("M_PI", 3.14159265358979323846);
    draft_.constants.emplace("true", 1.0);
    draft_.constants.emplace("false", 0.0);
    return build_grammar(*this, std::move(draft_), options_);
  }

 private:
  void skip_space(std::size_t& i) const {
    while (i < text_.size() &&
           std::isspace(static_cast<unsigned char>(text_[i])) != 0) {
      ++i;
    }
  }

  // The first `;` or `{` at paren depth 0 from `from`; npos if none.
  std::size_t end_of_item(std::size_t from) const {
    int depth = 0;
    for (std::size_t k = from; k < text_.size(); ++k) {
      const char c = text_[k];
      if (c == '(' || c == '[') ++depth;
      if (c == ')' || c == ']') --depth;
      if (depth == 0 && (c == ';' || c == '{')) return k;
    }
    return std::string_view::npos;
  }

  // The `}` that closes the `{` at `open`.
  std::size_t closing_brace(std::size_t open) const {
    int depth = 0;
    for (std::size_t k = open; k < text_.size(); ++k) {
      if (text_[k] == '{') ++depth;
      if (text_[k] == '}' && --depth == 0) return k;
    }
    fail(open, "unclosed '{'");
  }

  void directive(Range line) {
    const auto [word, rest] = directive_parts(line);
    if (word == "define") {
      draft_.defines.push_back(define_directive(rest));
      return;
    }
    if (word == "include") {
      const std::string_view what = view(rest);
      for (std::string_view header : kHeaders) {
        if (what.find(header) != std::string_view::npos) return;
      }
      fail(line.begin,
           "#include of a file lsolid does not have: copy its text into "
           "this one");
    }
    fail(line.begin, "unknown directive " + quoted(word, ""));
  }

  // `keyword:` at i, case as written, then blanks: the end of the colon.
  std::optional<std::size_t> label(std::size_t i,
                                   std::string_view keyword) const {
    const auto end = match_words(i, text_.size(), keyword);
    if (!end) return std::nullopt;
    std::size_t k = *end;
    while (k < text_.size() && is_blank(text_[k])) ++k;
    if (k >= text_.size() || text_[k] != ':') return std::nullopt;
    return k + 1;
  }

  // One statement or rule from i; returns where the next begins.
  std::size_t item(std::size_t i) {
    for (const auto& [keyword, section] :
         {std::pair{"production", Section::Productions},
          std::pair{"productions", Section::Productions},
          std::pair{"decomposition", Section::Decomposition},
          std::pair{"interpretation", Section::Homomorphism},
          std::pair{"homomorphism", Section::Homomorphism}}) {
      if (const auto after = label(i, keyword)) {
        section_ = section;
        return *after;
      }
    }
    for (const auto& [keyword, kind] :
         {std::pair{"start each", BlockKind::StartEach},
          std::pair{"starteach", BlockKind::StartEach},
          std::pair{"start", BlockKind::Start},
          std::pair{"end each", BlockKind::EndEach},
          std::pair{"endeach", BlockKind::EndEach},
          std::pair{"end", BlockKind::End}}) {
      if (const auto after = label(i, keyword)) {
        std::size_t open = *after;
        skip_space(open);
        if (open >= text_.size() || text_[open] != '{') {
          fail(open, "expected '{' and statements after ':'");
        }
        const std::size_t close = closing_brace(open);
        draft_.blocks.push_back(StatementBlock{kind, Range{open, close + 1}});
        return skip_semicolon(close + 1);
      }
    }
    if (const auto after = match_words(i, text_.size(), "group")) {
      // `group n:` … `endgroup`: lpfg runs group 0 unless the program
      // picks another (useGroup), which lsolid cannot know.
      std::size_t k = *after;
      while (k < text_.size() && is_blank(text_[k])) ++k;
      const std::size_t number = k;
      while (k < text_.size() &&
             std::isdigit(static_cast<unsigned char>(text_[k])) != 0) {
        ++k;
      }
      if (k > number && k < text_.size() && text_[k] == ':') {
        skipped_ = view(Range{number, k}) != "0";
        if (skipped_) {
          draft_.warnings.push_back(
              "rules of 'group " + std::string(view(Range{number, k})) +
              "' are left out: they apply only when the program selects "
              "their group");
        }
        return k + 1;
      }
    }
    if (match_words(i, text_.size(), "vgroup")) {
      fail(i, "lpfg's view groups (vgroup) are not supported");
    }
    if (const auto after = match_words(i, text_.size(), "endgroup")) {
      skipped_ = false;
      return skip_semicolon(*after);
    }
    const std::size_t end = end_of_item(i);
    if (end == std::string_view::npos) {
      fail(i, "expected ';' at the end of the statement");
    }
    const Range head = trim(Range{i, end});
    if (text_[end] == '{') return braced(head, end);
    statement(head);
    return end + 1;
  }

  std::size_t skip_semicolon(std::size_t i) const {
    std::size_t k = i;
    while (k < text_.size() && is_blank(text_[k])) ++k;
    return k < text_.size() && text_[k] == ';' ? k + 1 : i;
  }

  // `head { … }`: a rule `pred : { … }`, or a C function.
  std::size_t braced(Range head, std::size_t open) {
    const std::size_t close = closing_brace(open);
    const Range body{open, close + 1};
    const std::string_view h = view(head);
    if (h.starts_with("struct ") || h.starts_with("class ") ||
        h.starts_with("union ") || h.starts_with("enum ") ||
        h.starts_with("typedef ") || h == "struct" || h == "typedef") {
      fail(head.begin,
           quoted(h,
                  ": a C++ type; lsolid reads modules of numbers only "
                  "(docs/dialects/lpfg.md)"));
    }
    if (!h.empty() && h.back() == ':') {
      if (skipped_) return skip_semicolon(close + 1);
      refuse_new_contexts(head);
      ProductionText p{trim(Range{head.begin, head.end - 1}),
                       std::nullopt,
                       {Range{close + 1, close + 1}},
                       section_};
      p.python_body = body;
      p.python_builds = true;
      p.c_body = true;
      draft_.productions.push_back(std::move(p));
      return skip_semicolon(close + 1);
    }
    function(head, body);
    return skip_semicolon(close + 1);
  }

  void refuse_new_contexts(Range head) const {
    if (find_in(head, "<<") != std::string::npos ||
        find_in(head, ">>") != std::string::npos) {
      fail(head.begin, "new contexts '<<' and '>>' are not supported");
    }
  }

  // `float name(float a, int b) { return e; }`: a function compiled where
  // it is called, as L-Py's functions of one return.
  void function(Range head, Range body) {
    const std::size_t open = find_in(head, "(");
    const std::size_t close = open == std::string::npos
                                  ? std::string::npos
                                  : text_.rfind(')', head.end);
    const auto refuse = [&] {
      fail(head.begin,
           quoted(view(head),
                  ": a C++ function; lsolid reads functions of one 'return' "
                  "only (docs/dialects/lpfg.md)"));
    };
    if (open == std::string::npos || close == std::string::npos ||
        close < open) {
      refuse();
    }
    std::vector<Range> words = split_blanks(Range{head.begin, open});
    if (words.size() < 2) refuse();
    const std::string name(view(words.back()));
    PythonFunction f;
    const Range list = trim(Range{open + 1, close});
    if (!list.empty() && view(list) != "void") {
      for (const Range& p : split_top(list, ',')) {
        const std::vector<Range> parts = split_blanks(trim(p));
        if (parts.empty() || !is_identifier(view(parts.back()))) refuse();
        f.parameters.emplace_back(view(parts.back()));
      }
    }
    const Range inner = trim(Range{body.begin + 1, body.end - 1});
    const std::string_view code = view(inner);
    if (!code.starts_with("return") || !code.ends_with(";") ||
        find_in(Range{inner.begin, inner.end - 1}, ";") != std::string::npos) {
      refuse();
    }
    f.begin = inner.begin + 6;
    f.end = inner.end - 1;
    draft_.python_functions[name] = std::move(f);
  }

  std::vector<Range> split_blanks(Range r) const {
    std::vector<Range> out;
    std::size_t i = r.begin;
    while (i < r.end) {
      while (i < r.end && std::isspace(static_cast<unsigned char>(text_[i])))
        ++i;
      const std::size_t at = i;
      while (i < r.end && !std::isspace(static_cast<unsigned char>(text_[i])))
        ++i;
      if (i > at) out.push_back(Range{at, i});
    }
    return out;
  }

  // A statement that ends in `;`.
  void statement(Range s) {
    if (s.empty()) return;
    const std::size_t i = s.begin;
    const Key depth = section_ == Section::Homomorphism ? Key::HomomorphismDepth
                                                        : Key::MaximumDepth;
    for (const auto& [keyword, key] :
         {std::pair{"derivation length", Key::DerivationLength},
          std::pair{"maximum depth", depth},
          std::pair{"consider", Key::Consider},
          std::pair{"ignore", Key::Ignore}}) {
      if (const auto after = label(i, keyword)) {
        draft_.settings.push_back(SettingText{
            key, {}, Range{i, *after - 1}, trim(Range{*after, s.end})});
        return;
      }
    }
    if (const auto after = label(i, "axiom")) {
      draft_.axiom = trim(Range{*after, s.end});
      return;
    }
    if (label(i, "ring l-system") || label(i, "ring lsystem")) {
      fail(i,
           "a ring L-system (contexts that wrap around the string) is not "
           "supported");
    }
    const std::string_view t = view(s);
    if (const std::size_t colon = find_top(s, ":");
        colon != std::string::npos) {
      // `pred : produce …;`, a rule whose body is one statement.
      std::size_t k = colon + 1;
      while (k < s.end && std::isspace(static_cast<unsigned char>(text_[k])))
        ++k;
      const auto word = match_words(k, s.end, "produce");
      const auto nword = match_words(k, s.end, "nproduce");
      if ((word || nword) && skipped_) return;
      if (word || nword) {
        refuse_new_contexts(Range{s.begin, colon});
        ProductionText p{trim(Range{s.begin, colon}),
                         std::nullopt,
                         {Range{s.end + 1, s.end + 1}},
                         section_};
        p.python_body = Range{colon + 1, s.end + 1};  // with its `;`
        p.python_builds = true;
        p.c_body = true;
        draft_.productions.push_back(std::move(p));
        return;
      }
    }
    if (t.starts_with("module ")) {
      read_modules(Range{i + 7, s.end});
      return;
    }
    // `using namespace std;`, `using std::sin;`: names brought into scope,
    // which lsolid's expressions know by their plain names anyway.
    if (t.starts_with("using ")) return;
    // The rest is refused naming what it is (a published file's `using`
    // got a message about groups, structures and types at once).
    const auto refuse = [&](std::string_view what) {
      fail(i, quoted(t, std::string(": ") + std::string(what) +
                            " (docs/dialects/lpfg.md)"));
    };
    if (t.starts_with("group ") || t == "endgroup") {
      refuse(
          "a group statement lsolid does not read (groups are 'group N:' "
          "… 'endgroup')");
    }
    if (t.starts_with("struct ") || t.starts_with("typedef ")) {
      refuse("a C++ type; lsolid reads modules of numbers only");
    }
    if (t.starts_with("#")) {
      refuse("a preprocessor directive lsolid does not read");
    }
    std::size_t k = i;
    bool is_const = false;
    bool typed = false;
    for (;;) {
      std::size_t e = k;
      while (e < s.end && is_word_char(text_[e])) ++e;
      const std::string_view word = text_.substr(k, e - k);
      if (std::find(kTypes.begin(), kTypes.end(), word) == kTypes.end()) {
        break;
      }
      typed = true;
      is_const = is_const || word == "const";
      k = e;
      while (k < s.end && is_blank(text_[k])) ++k;
    }
    if (!typed) {
      std::size_t e = i;
      while (e < s.end && is_word_char(text_[e])) ++e;
      if (e > i && e < s.end &&
          (is_blank(text_[e]) || text_[e] == '*' || text_[e] == '&')) {
        fail(i, quoted(t, ": a variable of the C++ type '" +
                              std::string(view(Range{i, e})) +
                              "'; lsolid reads variables of numbers only "
                              "(docs/dialects/lpfg.md)"));
      }
      fail(i, quoted(t,
                     ": expected a setting, a module declaration, a "
                     "variable, the axiom or a rule"));
    }
    // `float a = 1, b;`: globals that start at their value (0 without),
    // or constants when `const`.
    for (const Range& piece : split_top(Range{k, s.end}, ',')) {
      const std::size_t equals = find_equals(piece);
      const Range name = trim(
          Range{piece.begin, equals == std::string::npos ? piece.end : equals});
      if (!is_identifier(view(name))) {
        fail(name.begin, "expected a variable's name");
      }
      if (equals == std::string::npos) {
        draft_.defines.emplace_back(name, Range{name.end, name.end});  // 0
      } else {
        draft_.defines.emplace_back(name, trim(Range{equals + 1, piece.end}));
      }
      if (!is_const) draft_.variables.insert(std::string(view(name)));
    }
  }

  // `module A(float), B(float, int);`: names and parameter counts.
  void read_modules(Range names) {
    draft_.module_lines.push_back(trim(names));
    for (const DeclaredName& declared : module_names(*this, trim(names))) {
      draft_.declared_modules.insert(std::string(view(declared.name)));
    }
  }

  Draft draft_;
  const ParseOptions& options_;
  Section section_ = Section::Productions;
  bool skipped_ = false;  // in a group other than 0
};

}  // namespace

Grammar read_lpfg(std::shared_ptr<const SourceFile> source,
                  const ParseOptions& options) {
  return read_with_view(
      std::move(source), options,
      [&](std::shared_ptr<const SourceFile> preprocessed, Draft draft) {
        return LpfgReader(std::move(preprocessed), std::move(draft), options)
            .run();
      },
      std::vector<std::string>(kHeaders.begin(), kHeaders.end()));
}

}  // namespace lsys::dialects
