// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The declarative part of L-Py (openalea/lpy: its parser lpy_parser.cpp and
// its symbol table predefinedmodules.cpp; PlantGL's turtle for defaults;
// docs/dialects/lpy.md). An L-Py file is Python with L-system sections.
// lsolid reads the sections (`Axiom:`, `derivation length:`,
// `production:`, `decomposition:`, `interpretation:`/`homomorphism:`,
// `maximum depth:`, `endlsystem`, `module`, `ignore:`/`consider:`, rules
// `pred --> succ`) and, of the Python, the assignments of constants
// (`angle = 30`, `extern(a=1)`) and the turtle's settings
// (`context().turtle.setAngleIncrement(90)`). Rule bodies, an axiom and
// hooks written in Python are compiled from a subset of Python
// (parse_python_statements); any other Python is refused at its line:
// lsolid does not run Python.
#include <algorithm>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dialects/front_ends.hpp"
#include "dialects/grammar_builder.hpp"
#include "lsys/surface.hpp"

namespace lsys::dialects {
namespace {

// PlantGL's turtle as L-Py drives it. `f` is never a polygon vertex (only
// `F` and `.` are); `G` and `g` are not turtle modules in L-Py; `_` and
// `!` widen and narrow by the width increment, or set the width; `$` is a
// pattern module, not cpfg's roll.
const std::vector<SymbolCommand> kSymbols = {
    {"F", TurtleCommand::Draw, std::nullopt},
    {"f", TurtleCommand::MoveNoVertex, std::nullopt},
    {"+", TurtleCommand::TurnLeft, std::nullopt},
    {"-", TurtleCommand::TurnRight, std::nullopt},
    {"&", TurtleCommand::PitchDown, std::nullopt},
    {"^", TurtleCommand::PitchUp, std::nullopt},
    {"/", TurtleCommand::RollRight, std::nullopt},
    {"\\", TurtleCommand::RollLeft, std::nullopt},
    {"|", TurtleCommand::TurnAround, std::nullopt},
    {"[", TurtleCommand::Push, std::nullopt},
    {"]", TurtleCommand::Pop, std::nullopt},
    {"{", TurtleCommand::PolygonBegin, std::nullopt},
    {".", TurtleCommand::PolygonVertex, std::nullopt},
    {"}", TurtleCommand::PolygonEnd, std::nullopt},
    {"_", TurtleCommand::Widen, std::nullopt},
    {"!", TurtleCommand::Width, std::nullopt},
    {"SetWidth", TurtleCommand::Width, std::nullopt},
    // Sphere(radius), of the width without one.
    {"@O", TurtleCommand::Sphere, std::nullopt},
    {"Sphere", TurtleCommand::Sphere, std::nullopt},
    // Circle(radius), of the width without one, across the heading
    // (PlantGL's turtle).
    {"@o", TurtleCommand::DiscAcrossHeading, std::nullopt},
    {"Circle", TurtleCommand::DiscAcrossHeading, std::nullopt},
    {";", TurtleCommand::ColorNext, std::nullopt},
    {",", TurtleCommand::ColorPrevious, std::nullopt},
    {"SetColor", TurtleCommand::ColorNext, std::nullopt},
    {"%", TurtleCommand::Cut, std::nullopt},
    // PlantGL's one predefined surface, its leaf, of the scale given
    // (kLeaf).
    {"~l", TurtleCommand::Surface, std::nullopt, 1},
    {"@v", TurtleCommand::RollToVertical, std::nullopt},
    {"@Ts", TurtleCommand::SetElasticity, std::nullopt},
    {"@M", TurtleCommand::MoveTo, std::nullopt},
    {"MoveTo", TurtleCommand::MoveTo, std::nullopt},
    {"@R", TurtleCommand::SetHeading, std::nullopt},
    {"SetHead", TurtleCommand::SetHeading, std::nullopt},
    {"LineTo", TurtleCommand::LineTo, std::nullopt},
    {"@Tp", TurtleCommand::SetTropism, std::nullopt},
    // A generalized cylinder joins its segments into one smooth tube,
    // which lsolid's joined tubes already are; a frame is a drawing aid.
    {"@Gs", TurtleCommand::None, std::nullopt},
    {"@Gc", TurtleCommand::None, std::nullopt},
    {"@Ge", TurtleCommand::None, std::nullopt},
    {"Frame", TurtleCommand::None, std::nullopt},
    // Queries: the turtle's position and frame, written into the module
    // before each step, in PlantGL's coordinates.
    {"?P", TurtleCommand::QueryPosition, std::nullopt},
    {"?H", TurtleCommand::QueryHeading, std::nullopt},
    {"?L", TurtleCommand::QueryLeft, std::nullopt},
    {"?U", TurtleCommand::QueryUp, std::nullopt},
};

// L-Py modules lsolid knows by name but cannot build: refused where they
// stand rather than split into letters.
const std::vector<RefusedName> kRefused = {
    {"@B", "a box"},
    {"@b", "a quad"},
    {"@h", "a roll to horizontal"},
    {"@D", "a scale"},
    {"@Di", "a scale"},
    {"@Dd", "a scale"},
    {"@g", "a PlantGL shape"},
    {"~", "a predefined surface other than ~l, PlantGL's leaf"},
    {"nF", "a path of steps"},
    {"$", "a pattern module"},
    {"MoveRel", "a move"},
    {"LineRel", "a line"},
    {"Pinpoint", "an orientation"},
    {"EulerAngles", "an orientation"},
    {"Sweep", "a swept surface"},
    {"SetGuide", "a guide curve"},
    {"SetContour", "a contour"},
    {"?", "a query other than ?P, ?H, ?L, ?U"},
};

// Drawn as nothing, their arguments (Python's strings) unread.
const std::vector<RefusedName> kLeftOut = {
    {"@L", "a label"},
    {"Label", "a label"},
};

// PlantGL's predefined surface `l` (its PglTurtle::defaultValue): a flat
// hexagon 1 long along the heading and 0.5 wide, made of six triangles
// about its centre. PlantGL places a surface's x along up, y along −left
// and z along the heading; lsolid's Surface has x along left, y along the
// heading.
Surface plantgl_leaf() {
  Surface leaf;
  leaf.points = {{0.0, 0.5, 0.0},        {0.0, 0.0, 0.0},
                 {0.25, 1.0 / 3.0, 0.0}, {0.25, 2.0 / 3.0, 0.0},
                 {0.0, 1.0, 0.0},        {-0.25, 2.0 / 3.0, 0.0},
                 {-0.25, 1.0 / 3.0, 0.0}};
  leaf.triangles = {{0, 2, 1}, {0, 3, 2}, {0, 4, 3},
                    {0, 5, 4}, {0, 6, 5}, {0, 1, 6}};
  return leaf;
}

// Blanks `#` comments to the end of the line (outside strings), keeping
// offsets.
std::string clean_text(const std::string& text) {
  std::string out = text;
  char quote = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    const char c = out[i];
    if (c == '\n') quote = 0;
    if (quote != 0) {
      if (c == quote) quote = 0;
      continue;
    }
    if (c == '\'' || c == '"') {
      // An apostrophe inside an L-string is a module, not a quote; only a
      // quote after `=`, `(` or `,` opens a Python string.
      std::size_t j = i;
      while (j > 0 && (out[j - 1] == ' ' || out[j - 1] == '\t')) --j;
      if (j > 0 &&
          (out[j - 1] == '=' || out[j - 1] == '(' || out[j - 1] == ',')) {
        quote = c;
      }
      continue;
    }
    if (c == '#') {
      for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
      if (i < out.size()) --i;
    }
  }
  return out;
}

constexpr std::string_view kInitialisation = "###### INITIALISATION ######";

class LpyReader : TextScan {
 public:
  LpyReader(std::shared_ptr<const SourceFile> source,
            const ParseOptions& options)
      : TextScan(source, clean_text(source->text())), options_(options) {}

  Grammar run() {
    // The editor's trailing block (materials, options) is not the model.
    std::size_t end = source_->text().find(kInitialisation);
    if (end == std::string::npos) end = text_.size();
    for (const Range& line : lines(Range{0, end})) read_line(line);
    finish_body();
    // Of the editor's block, the turtle's settings count: L-Py applies them
    // before the L-system runs.
    // (materials and other calls there are the editor's, not the model's).
    for (const Range& line : lines(Range{end, text_.size()})) {
      const std::string_view text = view(trim(line));
      if (text.starts_with("scalars = [") && text.ends_with("]")) {
        read_scalars(trim(line));
        continue;
      }
      if (text.starts_with("context.turtle.set") &&
          (text.find("AngleIncrement(") != std::string_view::npos ||
           text.find("DefaultStep(") != std::string_view::npos ||
           text.find("WidthIncrement(") != std::string_view::npos)) {
        turtle_setting(trim(line));
      }
    }
    Settings& s = draft_.defaults;
    s.angle_deg = 60.0;
    s.step = 1.0;
    s.initial_width = 0.1;
    s.width_scale = 2.0;                    // L-Py's widths are radii
    s.sphere_diameter_per_parameter = 2.0;  // and so are its spheres
    s.width_increment = 1.0;
    s.initial_color = 1;
    s.tropism = glm::dvec3(0.0, 0.0, 1.0);
    s.roll = RollConvention::Lpfg;
    s.query_frame = QueryFrame::PlantGL;
    draft_.symbols = kSymbols;
    draft_.refused = kRefused;
    draft_.left_out = kLeftOut;
    draft_.syntax.radians = true;
    draft_.syntax.python = true;
    draft_.syntax.several_module_predecessors = true;
    // L-Py matches a module by its name and its number of parameters:
    // `S` and `S(1)` may both stand in one file.
    draft_.syntax.fixed_arity = false;
    // PlantGL's turtle reads the parameters it knows and ignores the rest
    // (L-Py's predefinedmodules.cpp: `-(a, t)` turns by a).
    draft_.syntax.extra_turtle_parameters = true;
    draft_.warnings = std::move(grammar_warnings_);
    draft_.constants.insert(
        {{"True", 1.0}, {"False", 0.0}, {"pi", 3.14159265358979323846}});
    Grammar grammar = build_grammar(*this, std::move(draft_), options_);
    if (const auto leaf = grammar.alphabet.find("~l")) {
      grammar.surfaces[*leaf] = plantgl_leaf();
    }
    return grammar;
  }

 private:
  enum class Mode { Python, Rules, Skipped };

  bool starts_line(Range line, std::string_view keyword,
                   Range* rest = nullptr) const {
    const auto end = match_words(line.begin, line.end, keyword);
    if (!end) return false;
    std::size_t pos = *end;
    while (pos < line.end && is_blank(text_[pos])) ++pos;
    if (keyword.back() != ':' && pos < line.end && text_[pos] != ':') {
      return false;
    }
    if (keyword.back() != ':' && pos < line.end) ++pos;
    if (rest != nullptr) *rest = trim(Range{pos, line.end});
    return true;
  }

  [[noreturn]] void refuse_python(std::size_t at, std::string_view what) const {
    fail(at, std::string(what) +
                 ": this is Python code, and lsolid does not run Python; it "
                 "reads the declarative part of L-Py (docs/dialects/lpy.md)");
  }

  void read_line(Range raw) {
    const Range line = trim(raw);
    if (line.empty()) return;
    const bool indented = line.begin > raw.begin;
    if (body_) {
      if (indented) {
        body_->end = line.end;
        return;
      }
      finish_body();
    }
    Range rest;
    if (starts_line(line, "endlsystem")) {
      mode_ = Mode::Python;
      return;
    }
    for (const auto& [keyword, section] :
         {std::pair{"production", Section::Productions},
          std::pair{"decomposition", Section::Decomposition},
          std::pair{"interpretation", Section::Homomorphism},
          std::pair{"homomorphism", Section::Homomorphism}}) {
      if (!indented && starts_line(line, keyword, &rest) && rest.empty()) {
        mode_ = Mode::Rules;
        section_ = section;
        return;
      }
    }
    if (!indented && starts_line(line, "axiom", &rest)) {
      if (draft_.axiom || draft_.axiom_python) {
        fail(line.begin, "a second axiom");
      }
      if (rest.empty()) {
        // `Axiom:` above a Python body that produces the axiom.
        axiom_at_ = line.begin;
        body_ = Range{line.end, line.end};
        return;
      }
      draft_.axiom = rest;
      return;
    }
    if (!indented && starts_line(line, "derivation length", &rest)) {
      setting(Key::DerivationLength, line, rest);
      return;
    }
    if (!indented && starts_line(line, "maximum depth", &rest)) {
      if (mode_ != Mode::Rules || section_ == Section::Productions) {
        fail(line.begin,
             "'maximum depth:' belongs in a decomposition or "
             "interpretation section");
      }
      setting(Key::MaximumDepth, line, rest);
      return;
    }
    for (const auto& [keyword, key] : {std::pair{"ignore", Key::Ignore},
                                       std::pair{"consider", Key::Consider}}) {
      if (!indented && starts_line(line, keyword, &rest)) {
        setting(key, line, rest);
        return;
      }
    }
    if (!indented) {
      for (std::string_view keyword : {"module ", "modules "}) {
        if (view(line).starts_with(keyword)) {
          Range names = trim(Range{line.begin + keyword.size(), line.end});
          if (const std::size_t colon = find_top(names, ":");
              colon != std::string::npos) {
            names.end = colon;  // `module A : scale = 2`
          }
          if (find_equals(names) != std::string::npos) {
            draft_.alias_lines.push_back(names);  // `module A = F`
            return;
          }
          draft_.module_lines.push_back(names);
          for (const DeclaredName& d : module_names(*this, names)) {
            draft_.declared_modules.insert(std::string(view(d.name)));
          }
          return;
        }
      }
    }
    if (mode_ == Mode::Skipped) {
      if (starts_line(line, "endgroup")) mode_ = Mode::Rules;
      return;
    }
    if (mode_ == Mode::Rules) {
      read_rule(line, indented);
    } else {
      read_python(line, indented);
    }
  }

  void setting(Key key, Range line, Range value) {
    draft_.settings.push_back(
        SettingText{key, {}, Range{line.begin, value.begin}, value});
  }

  void read_rule(Range line, bool indented) {
    if (view(line).starts_with("group ")) {
      // Rules of group n > 0 apply only when Python calls useGroup(n).
      const std::string_view text = view(line);
      if (!text.starts_with("group 0")) {
        mode_ = Mode::Skipped;
        grammar_warnings_.push_back("rules of '" + std::string(text) +
                                    "' are left out: they apply only when "
                                    "Python code selects their group");
      }
      return;
    }
    if (starts_line(line, "endgroup")) return;
    if (indented) refuse_python(line.begin, "an indented rule body");
    if (view(line).starts_with("def ")) {
      refuse_python(line.begin, "a function definition");
    }
    const std::size_t arrow = find_top(line, "-->");
    const std::size_t colon = find_top(line, ":");
    if (colon != std::string::npos &&
        (arrow == std::string::npos || colon < arrow)) {
      // `pred :` and a Python body, on the rest of the line or below it.
      head_ = Range{line.begin, colon};
      body_ = Range{colon + 1, line.end};
      return;
    }
    if (arrow == std::string::npos) {
      fail(line.begin, "expected a rule 'predecessor --> successor'");
    }
    if (find_in(line, "<<") != std::string::npos ||
        find_in(line, ">>") != std::string::npos) {
      fail(line.begin, "new contexts '<<' and '>>' are not supported");
    }
    draft_.productions.push_back(ProductionText{Range{line.begin, arrow},
                                                std::nullopt,
                                                {Range{arrow + 3, line.end}},
                                                section_});
  }

  // A rule with a Python body becomes one production per `produce`
  // (ProductionText::python_body); a body without one never rewrites.
  void finish_body() {
    if (!body_) return;
    const Range body = *body_;
    body_.reset();
    if (axiom_at_) {
      const std::size_t at = *axiom_at_;
      axiom_at_.reset();
      if (trim(body).empty()) fail(at, "'Axiom:' without modules");
      if (!python_builds_successor(*source_, body.begin, body.end) &&
          python_successors(*source_, body.begin, body.end).empty()) {
        refuse_python(at,
                      "an axiom built by Python statements without "
                      "'nproduce' or 'produce'");
      }
      draft_.axiom_python = body;
      return;
    }
    if (hook_) {
      if (!hook_->parameter.empty() &&
          uses_outside_print(body, hook_->parameter)) {
        refuse_python(hook_->at, "'" + hook_->line +
                                     "', a hook that reads the string L-Py "
                                     "passes it");
      }
      draft_.blocks.push_back(StatementBlock{hook_->kind, body, true});
      hook_.reset();
      return;
    }
    if (function_) {
      // Only a function of returns is kept (compiled where it is called);
      // any other body is Python lsolid does not run.
      if (!read_returns(body, function_->function)) {
        refuse_python(function_->at, "'" + function_->line + "'");
      }
      draft_.python_functions[function_->name] = function_->function;
      function_.reset();
      return;
    }
    if (python_builds_successor(*source_, body.begin, body.end)) {
      // One production whose body produces its successor as it runs.
      ProductionText p{
          head_, std::nullopt, {Range{body.end, body.end}}, section_};
      p.python_body = body;
      p.python_builds = true;
      draft_.productions.push_back(std::move(p));
      return;
    }
    int branch = 0;
    const auto successors = python_successors(*source_, body.begin, body.end);
    for (const auto& [begin, end] : successors) {
      ProductionText p{head_, std::nullopt, {Range{begin, end}}, section_};
      p.python_body = body;
      p.python_branch = ++branch;
      p.python_branches = static_cast<int>(successors.size());
      draft_.productions.push_back(std::move(p));
    }
    if (branch == 0) {
      // Still compiled, so that what lsolid cannot run is refused; its
      // condition never holds.
      ProductionText p{
          head_, std::nullopt, {Range{body.end, body.end}}, section_};
      p.python_body = body;
      p.python_branch = -1;
      draft_.productions.push_back(std::move(p));
    }
  }

  void read_python(Range line, bool indented) {
    if (indented) refuse_python(line.begin, "an indented Python block");
    const std::string_view text = view(line);
    // Python's math and random functions are the expressions' own
    // (random numbers from lsolid's generator, not Python's).
    for (std::string_view module : {"import math as ", "import random as "}) {
      if (text.starts_with(module) &&
          is_identifier(text.substr(module.size()))) {
        draft_.python_modules.emplace_back(text.substr(module.size()));
        return;
      }
    }
    // lsolid draws from its own generator: a seed changes nothing here.
    if (text.starts_with("seed(") || text.starts_with("random.seed(")) return;
    if (text.starts_with("assert ")) {
      // `assert c` or `assert c, "message"`: c must hold (over constants).
      const auto parts = split_top(Range{line.begin + 7, line.end}, ',');
      draft_.assertions.push_back(trim(parts.front()));
      return;
    }
    // Printing is a side effect on the console: nothing to build.
    if ((text.starts_with("print(") || text.starts_with("print (")) &&
        text.ends_with(")")) {
      return;
    }
    if (text.starts_with("import ") || text.starts_with("from ")) {
      // An import defines names and runs nothing lsolid needs: what the
      // file uses of a module other than math and random (PlantGL's
      // Vector3, copy's deepcopy, sys.path) is refused where it is used.
      note_import(line);
      return;
    }
    if (read_function(line)) return;
    // L-Py's hooks, run as cpfg runs Start: and its kin.
    for (const auto& [name, kind] :
         {std::pair{"def Start(", BlockKind::Start},
          std::pair{"def StartEach(", BlockKind::StartEach},
          std::pair{"def EndEach(", BlockKind::EndEach},
          std::pair{"def End(", BlockKind::End}}) {
      if (!text.starts_with(name)) continue;
      // `def EndEach(lstring):` is passed the string, which lsolid does
      // not hand to Python: the hook is read when it does not use it.
      const std::size_t open = std::string_view(name).size();
      const std::size_t close = text.find(')', open);
      if (close == std::string_view::npos) break;
      const std::string parameter(
          view(trim(Range{line.begin + open, line.begin + close})));
      std::size_t colon = close + 1;
      while (colon < text.size() && (text[colon] == ' ' || text[colon] == '\t'))
        ++colon;
      if (colon >= text.size() || text[colon] != ':' ||
          (!parameter.empty() && !is_identifier(parameter))) {
        break;
      }
      hook_ = Hook{kind, parameter, line.begin, std::string(text)};
      body_ = Range{line.begin + colon + 1, line.end};
      return;
    }
    if (text.starts_with("context().turtle.") ||
        text.starts_with("execContext().turtle.")) {
      turtle_setting(line);
      return;
    }
    if (text.starts_with("extern(") && text.ends_with(")")) {
      for (const Range& piece :
           split_top(Range{line.begin + 7, line.end - 1}, ',')) {
        define(trim(piece));
      }
      return;
    }
    define(line);
  }

  // The names `import a.b as c`, `import a, b` and `from m import x, y as z`
  // bind, by module (Draft::python_imports); math and random are read.
  void note_import(Range line) {
    const std::string_view text = view(line);
    const bool from = text.starts_with("from ");
    std::string module;
    Range names = line;
    if (from) {
      const std::size_t at = find_in(line, " import ");
      if (at == std::string::npos) return;
      module = std::string(view(trim(Range{line.begin + 5, at})));
      names = trim(Range{at + 8, line.end});
    } else {
      names = trim(Range{line.begin + 7, line.end});
    }
    if (module == "math" || module == "random") return;
    for (const Range& piece : split_top(names, ',')) {
      std::string_view item = view(trim(piece));
      std::string_view bound = item;
      if (const std::size_t as = item.find(" as ");
          as != std::string_view::npos) {
        bound = item.substr(as + 4);
        item = item.substr(0, as);
      } else if (!from) {
        bound = item.substr(0, item.find('.'));
      }
      const std::string of = from ? module : std::string(item);
      if (of == "math" || of == "random" || bound == "*") continue;
      while (!bound.empty() && bound.front() == ' ') bound.remove_prefix(1);
      while (!bound.empty() && bound.back() == ' ') bound.remove_suffix(1);
      if (is_identifier(bound)) {
        draft_.python_imports.emplace(std::string(bound), of);
      }
    }
  }

  // A function body as L-Py's examples write them: a docstring, then
  // `return e`, or `if c: return a`, `elif …`, and `else: return b` (or a
  // last `return b`), each condition and value on one line.
  bool read_returns(Range body, PythonFunction& f) const {
    struct Line {
      std::size_t indent;
      Range code;
    };
    std::vector<Line> lines;
    std::size_t i = body.begin;
    while (i < body.end) {
      std::size_t end = text_.find('\n', i);
      if (end == std::string::npos || end > body.end) end = body.end;
      std::size_t first = i;
      while (first < end && (text_[first] == ' ' || text_[first] == '\t'))
        ++first;
      const Range code = trim(Range{first, end});  // comments are blanked
      if (!code.empty()) lines.push_back(Line{first - i, code});
      i = end + 1;
    }
    std::size_t k = 0;
    if (k < lines.size()) {
      const std::string_view t = view(lines[k].code);
      for (std::string_view quote : {"\"\"\"", "'''", "\"", "'"}) {
        if (!t.starts_with(quote)) continue;
        // A docstring: up to the line that closes it.
        while (k < lines.size()) {
          const std::string_view l = view(lines[k].code);
          const std::size_t from = k == 0 ? quote.size() : 0;
          ++k;
          if (l.find(quote, from) != std::string_view::npos) break;
        }
        break;
      }
    }
    // The value after `return` on this line, or on the next, deeper one.
    const auto value_of = [&](std::size_t& at,
                              Range rest) -> std::optional<Range> {
      if (rest.empty()) {
        if (++at >= lines.size()) return std::nullopt;
        rest = lines[at].code;
      }
      if (!view(rest).starts_with("return ")) return std::nullopt;
      ++at;
      return trim(Range{rest.begin + 7, rest.end});
    };
    while (k < lines.size()) {
      const Range code = lines[k].code;
      const std::string_view t = view(code);
      if (t.starts_with("return ")) {
        if (k + 1 != lines.size()) return false;
        f.begin = code.begin + 7;
        f.end = code.end;
        return true;
      }
      const bool is_if = f.branches.empty() && t.starts_with("if ");
      const bool is_elif = !f.branches.empty() && t.starts_with("elif ");
      if (is_if || is_elif) {
        const std::size_t colon = find_top(code, ":");
        if (colon == std::string::npos) return false;
        const Range condition =
            trim(Range{code.begin + (is_if ? 3 : 5), colon});
        const auto value = value_of(k, trim(Range{colon + 1, code.end}));
        if (!value || condition.empty()) return false;
        f.branches.push_back(PythonFunction::Branch{
            condition.begin, condition.end, value->begin, value->end});
        continue;
      }
      if (!f.branches.empty() && t.starts_with("else")) {
        const std::size_t colon = find_top(code, ":");
        if (colon == std::string::npos ||
            !trim(Range{code.begin + 4, colon}).empty()) {
          return false;
        }
        const auto value = value_of(k, trim(Range{colon + 1, code.end}));
        if (!value || k != lines.size()) return false;
        f.begin = value->begin;
        f.end = value->end;
        return true;
      }
      return false;
    }
    return false;  // no last return: Python would return None
  }

  // True when `name` stands as a word in `body` on a line other than a
  // `print(…)`, which lsolid skips.
  bool uses_outside_print(Range body, std::string_view name) const {
    std::size_t i = body.begin;
    while (i < body.end) {
      std::size_t end = text_.find('\n', i);
      if (end == std::string::npos || end > body.end) end = body.end;
      const Range line = trim(Range{i, end});
      i = end + 1;
      const std::string_view t = view(line);
      if (t.starts_with("print(") || t.starts_with("print (") ||
          t.starts_with("#")) {
        continue;
      }
      for (std::size_t k = t.find(name); k != std::string_view::npos;
           k = t.find(name, k + 1)) {
        const auto word_char = [](char c) {
          return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
        };
        const bool starts = k == 0 || !word_char(t[k - 1]);
        const bool ends =
            k + name.size() >= t.size() || !word_char(t[k + name.size()]);
        if (starts && ends) return true;
      }
    }
    return false;
  }

  // `def name(a, b):` and a body, kept if it is one `return` line.
  bool read_function(Range line) {
    const std::string_view text = view(line);
    if (!text.starts_with("def ")) return false;
    const std::size_t open = text.find('(');
    const std::size_t close = text.find(')');
    if (open == std::string_view::npos || close == std::string_view::npos ||
        close < open) {
      return false;
    }
    const std::string name(
        view(trim(Range{line.begin + 4, line.begin + open})));
    if (!is_identifier(name) || name == "Start" || name == "End" ||
        name == "StartEach" || name == "EndEach") {
      return false;
    }
    std::size_t colon = close + 1;
    while (colon < text.size() && (text[colon] == ' ' || text[colon] == '\t'))
      ++colon;
    if (colon >= text.size() || text[colon] != ':') return false;
    PendingFunction f{name, std::string(text), line.begin, {}};
    const Range list{line.begin + open + 1, line.begin + close};
    if (!trim(list).empty()) {
      for (const Range& p : split_top(list, ',')) {
        const std::string parameter(view(trim(p)));
        if (!is_identifier(parameter)) return false;  // defaults, *args
        f.function.parameters.push_back(parameter);
      }
    }
    function_ = std::move(f);
    body_ = Range{line.begin + colon + 1, line.end};
    return true;
  }

  // `name = expression`, a constant the rules may read; `a, b = 1, 2`
  // defines both.
  void define(Range line) {
    const std::size_t equals = find_equals(line);
    if (equals != std::string::npos) {
      const auto names = split_top(Range{line.begin, equals}, ',');
      const auto values = split_top(Range{equals + 1, line.end}, ',');
      if (names.size() > 1 && values.size() == 1 &&
          define_range(names, trim(values.front()))) {
        return;
      }
      if (names.size() > 1 && names.size() == values.size()) {
        for (std::size_t i = 0; i < names.size(); ++i) {
          const Range name = trim(names[i]);
          if (!is_identifier(view(name))) {
            refuse_python(line.begin, "'" + std::string(view(line)) + "'");
          }
          draft_.defines.emplace_back(name, trim(values[i]));
        }
        return;
      }
    }
    const Range name =
        equals == std::string::npos ? line : trim(Range{line.begin, equals});
    if (equals == std::string::npos || !is_identifier(view(name))) {
      refuse_python(line.begin, "'" + std::string(view(line)) + "'");
    }
    const Range value = trim(Range{equals + 1, line.end});
    if (!value.empty() &&
        (text_[value.begin] == '\'' || text_[value.begin] == '"')) {
      return;  // a string: metadata such as __authors__
    }
    if (view(value).starts_with("lambda ") ||
        view(value).starts_with("lambda:")) {
      define_lambda(line, name, value);
      return;
    }
    const bool tuple = value.end >= value.begin + 2 &&
                       text_[value.begin] == '(' &&
                       text_[value.end - 1] == ')' &&
                       find_top(Range{value.begin + 1, value.end - 1}, ",") !=
                           std::string::npos &&
                       find_top(value, ",") == std::string::npos;
    if (tuple || (value.end >= value.begin + 2 && text_[value.begin] == '[' &&
                  text_[value.end - 1] == ']')) {
      // A list; its elements are read as constants by the grammar builder
      // (a list of lists or of other things fails there, at its place).
      Draft::PythonList list{name, {}};
      const Range inside = trim(Range{value.begin + 1, value.end - 1});
      if (!inside.empty()) {
        for (const Range& e : split_top(inside, ',')) {
          if (!trim(e).empty()) list.elements.push_back(trim(e));
        }
      }
      draft_.python_lists.push_back(std::move(list));
      return;
    }
    draft_.defines.emplace_back(name, trim(Range{equals + 1, line.end}));
  }

  // `Forward, Backward, Growth = range(3)`, Python's enumeration idiom:
  // the names are the constants 0, 1, 2. False when the value is not a
  // `range` of a whole number.
  bool define_range(const std::vector<Range>& names, Range value) {
    const std::string_view v = view(value);
    if (!v.starts_with("range(") || v.back() != ')') return false;
    const std::string count(view(trim(Range{value.begin + 6, value.end - 1})));
    if (count.empty() || !std::all_of(count.begin(), count.end(), [](char c) {
          return std::isdigit(static_cast<unsigned char>(c)) != 0;
        })) {
      return false;
    }
    if (std::stoul(count) != names.size()) {
      std::string message = "range(";
      message += count;
      message += ") gives ";
      message += count;
      message += " values to ";
      message += std::to_string(names.size());
      message += " names";
      fail(value.begin, std::move(message));
    }
    for (std::size_t i = 0; i < names.size(); ++i) {
      const Range name = trim(names[i]);
      if (!is_identifier(view(name))) {
        refuse_python(name.begin, "'" + std::string(view(name)) + "'");
      }
      draft_.constants[std::string(view(name))] = static_cast<double>(i);
    }
    return true;
  }

  // `f = lambda a, b: expression`, a function of one return as `def`
  // gives (the L-Py tutorials' archimodels define their laws so).
  void define_lambda(Range line, Range name, Range value) {
    const Range rest{value.begin + 6, value.end};
    const std::size_t colon = find_top(rest, ":");
    if (colon == std::string::npos) {
      refuse_python(line.begin, "'" + std::string(view(line)) + "'");
    }
    PythonFunction f;
    const Range list = trim(Range{rest.begin, colon});
    if (!list.empty()) {
      for (const Range& p : split_top(list, ',')) {
        const std::string parameter(view(trim(p)));
        if (!is_identifier(parameter)) {
          refuse_python(line.begin, "'" + std::string(view(line)) + "'");
        }
        f.parameters.push_back(parameter);
      }
    }
    const Range body = trim(Range{colon + 1, value.end});
    if (body.empty()) {
      refuse_python(line.begin, "'" + std::string(view(line)) + "'");
    }
    f.begin = body.begin;
    f.end = body.end;
    draft_.python_functions[std::string(view(name))] = std::move(f);
  }

  // The editor's scalars, `scalars = [('n', 'Integer', 3, 1, 20), …]` (or
  // the older `('n', 3, 1, 20)`): constants, as L-Py sets them in the
  // context before the file's code runs; the file's own assignment of the
  // same name stays. Categories and other kinds are the editor's.
  void read_scalars(Range line) {
    const std::size_t open = view(line).find('[');
    for (const Range& item :
         split_top(Range{line.begin + open + 1, line.end - 1}, ',')) {
      const Range tuple = trim(item);
      if (tuple.empty() || text_[tuple.begin] != '(' ||
          text_[tuple.end - 1] != ')') {
        continue;
      }
      const auto fields = split_top(Range{tuple.begin + 1, tuple.end - 1}, ',');
      const auto quoted = [&](Range r) {
        r = trim(r);
        return r.end - r.begin >= 2 &&
               (text_[r.begin] == '\'' || text_[r.begin] == '"') &&
               text_[r.end - 1] == text_[r.begin];
      };
      if (fields.size() < 2 || !quoted(fields[0])) continue;
      const Range name_quoted = trim(fields[0]);
      const Range name{name_quoted.begin + 1, name_quoted.end - 1};
      std::size_t value_at = 1;
      if (quoted(fields[1])) {
        const std::string_view kind = view(trim(fields[1]));
        if (kind != "'Integer'" && kind != "'Float'" && kind != "'Bool'" &&
            kind != "\"Integer\"" && kind != "\"Float\"" &&
            kind != "\"Bool\"") {
          continue;
        }
        value_at = 2;
      }
      if (fields.size() <= value_at || !is_identifier(view(name))) continue;
      const bool defined = std::any_of(
          draft_.defines.begin(), draft_.defines.end(),
          [&](const auto& d) { return view(d.first) == view(name); });
      if (!defined) draft_.defines.emplace_back(name, trim(fields[value_at]));
    }
  }

  // context().turtle.setAngleIncrement(90) and its kin.
  void turtle_setting(Range line) {
    const std::string_view text = view(line);
    const std::string_view object = text.substr(
        0, text.find("turtle.") + std::string_view("turtle.").size());
    for (const auto& [method, key] :
         {std::pair{"setAngleIncrement(", Key::Angle},
          std::pair{"setDefaultStep(", Key::Step},
          std::pair{"setWidthIncrement(", Key::WidthIncrement}}) {
      const std::string prefix = std::string(object) + method;
      if (text.starts_with(prefix) && text.ends_with(")")) {
        const Range value{line.begin + prefix.size(), line.end - 1};
        setting(key, line, trim(value));
        return;
      }
    }
    refuse_python(line.begin, "this turtle call");
  }

  const ParseOptions& options_;
  Draft draft_;
  Mode mode_ = Mode::Python;
  Section section_ = Section::Productions;
  // The rule whose Python body is being read: its head and body so far.
  Range head_;
  std::optional<Range> body_;
  std::optional<std::size_t> axiom_at_;  ///< when the body is the axiom's
  struct Hook {
    BlockKind kind;
    std::string parameter;  ///< `lstring` of `def EndEach(lstring):`
    std::size_t at;
    std::string line;
  };
  std::optional<Hook> hook_;  ///< when the body is a hook's
  struct PendingFunction {
    std::string name;
    std::string line;  ///< the `def` line, for the refusal
    std::size_t at;
    PythonFunction function;
  };
  std::optional<PendingFunction> function_;  ///< when it is a function's
  std::vector<std::string> grammar_warnings_;
};

}  // namespace

Grammar read_lpy(std::shared_ptr<const SourceFile> source,
                 const ParseOptions& options) {
  return LpyReader(std::move(source), options).run();
}

}  // namespace lsys::dialects
