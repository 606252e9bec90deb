// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Laurens Lapré's Lparser, the DOS versions 4 and 5 (what each symbol does,
// and where that is documented: docs/dialects/lparser.md). Its files have
// lines starting with `#` are comments; three numbers, the recursion
// depth, the angle in degrees and the thickness as a percentage of each
// segment's length; the axiom; rules `X=successor`, the first for a
// character winning; `@` ends the file. Only the first word of a line
// counts, so a comment may follow it. Parameters belong to the text, not
// to the module: a rule for `f` rewrites `f(200)` too, and the `(200)`
// stays behind its successor (`f=z` makes `z(200)`). Lparser 5 also reads
// a keyword form, each setting named on its line (`recursion 10`, `angle
// 45`, `thickness 15`, `axiom FA`, `rule A = F[+A]A`), which its example
// files and their ports use.
#include <cmath>
#include <cstdlib>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dialects/front_ends.hpp"
#include "dialects/grammar_builder.hpp"
#include "lsys/expression.hpp"

namespace lsys::dialects {
namespace {

constexpr double kPi = 3.14159265358979323846;

// Lparser's turtle (Lapré's L_draw, as its descendants keep it). `F` and
// `Z` never add a polygon vertex, `f`, `z` and `.` do. The bare factors:
// 0.9 for length and angle, 0.7 for thickness, and their inverses. A bare
// `~` turns up to 6 (radians, as the code has it), `t` bends by 0.2.
const std::vector<SymbolCommand> kSymbols = {
    {"F", TurtleCommand::DrawNoVertex, std::nullopt},
    {"Z", TurtleCommand::DrawHalf, std::nullopt},
    {"f", TurtleCommand::Move, std::nullopt},
    {"z", TurtleCommand::MoveHalf, std::nullopt},
    {"g", TurtleCommand::MoveNoVertex, std::nullopt},
    {".", TurtleCommand::PolygonVertex, std::nullopt},
    {"+", TurtleCommand::TurnLeft, std::nullopt},
    {"-", TurtleCommand::TurnRight, std::nullopt},
    {"&", TurtleCommand::PitchDown, std::nullopt},
    {"^", TurtleCommand::PitchUp, std::nullopt},
    {"<", TurtleCommand::RollLeft, std::nullopt},
    {">", TurtleCommand::RollRight, std::nullopt},
    {"|", TurtleCommand::TurnAround, std::nullopt},
    {"%", TurtleCommand::RollRight, 180.0},
    {"$", TurtleCommand::RollToVerticalSwappingTurns, std::nullopt},
    {"~", TurtleCommand::RandomTurn, 6.0 * 180.0 / kPi},
    {"t", TurtleCommand::Gravity, std::nullopt},
    {"'", TurtleCommand::MultiplyStep, 0.9},
    {"\"", TurtleCommand::MultiplyStep, 1.0 / 0.9},
    {":", TurtleCommand::MultiplyAngle, 0.9},
    {";", TurtleCommand::MultiplyAngle, 1.0 / 0.9},
    {"!", TurtleCommand::MultiplyWidth, 0.7},
    {"?", TurtleCommand::MultiplyWidth, 1.0 / 0.7},
    {"c", TurtleCommand::ColorNext, std::nullopt},
    {"[", TurtleCommand::Push, std::nullopt},
    {"]", TurtleCommand::Pop, std::nullopt},
    {"{", TurtleCommand::PolygonBegin, std::nullopt},
    {"}", TurtleCommand::PolygonEnd, std::nullopt},
};

// Lparser's `F` is 100 units long and its colour starts at 2 (red in
// Lviewer's palette).
constexpr double kStep = 100.0;
constexpr int kColor = 2;

// Blanks `#` comment lines, everything after the line that starts with
// `@`, and (for the numeric form, not the keyword form, which reads whole
// lines) everything after a line's first word, keeping offsets.
std::string clean_text(const std::string& text, bool whole_lines) {
  std::string out = text;
  bool ended = false;
  std::size_t start = 0;
  while (start < out.size()) {
    std::size_t end = out.find('\n', start);
    if (end == std::string::npos) end = out.size();
    std::size_t i = start;
    while (i < end && (out[i] == ' ' || out[i] == '\t')) ++i;
    const bool comment = i < end && out[i] == '#';
    if (!ended && !comment && i < end && out[i] == '@') ended = true;
    if (ended || comment) {
      i = start;
    } else if (whole_lines) {
      i = end;
    } else {
      while (i < end && out[i] != ' ' && out[i] != '\t' && out[i] != '#' &&
             out[i] != '\r') {
        ++i;
      }
    }
    for (; i < end; ++i) out[i] = ' ';
    start = end + 1;
  }
  return out;
}

}  // namespace

bool is_lparser_keyword_line(std::string_view line) {
  if (!line.starts_with("recursion")) return false;
  line.remove_prefix(9);
  if (line.empty() || (line.front() != ' ' && line.front() != '\t'))
    return false;
  while (!line.empty() && (line.front() == ' ' || line.front() == '\t'))
    line.remove_prefix(1);
  return !line.empty() &&
         (std::isdigit(static_cast<unsigned char>(line.front())) != 0 ||
          line.front() == '.');
}

namespace {

bool keyword_form(const std::string& text) {
  std::size_t start = 0;
  while (start < text.size()) {
    std::size_t end = text.find('\n', start);
    if (end == std::string::npos) end = text.size();
    std::string_view line(text.data() + start, end - start);
    while (!line.empty() && (line.front() == ' ' || line.front() == '\t'))
      line.remove_prefix(1);
    if (!line.empty() && line.front() != '#' && line.front() != '\r') {
      return is_lparser_keyword_line(line);
    }
    start = end + 1;
  }
  return false;
}

class LparserReader : TextScan {
 public:
  LparserReader(std::shared_ptr<const SourceFile> source,
                const ParseOptions& options, bool keywords)
      : TextScan(source, clean_text(source->text(), keywords)),
        options_(options),
        keywords_(keywords) {}

  Grammar run() {
    if (keywords_) return run_keywords();
    std::vector<Range> words;
    for (const Range& line : lines(Range{0, text_.size()})) {
      const Range word = trim(line);
      if (!word.empty()) words.push_back(word);
    }
    const char* const header[] = {"the recursion depth", "the angle",
                                  "the thickness (a percentage of length)"};
    if (words.size() < 3) {
      fail(text_.size(), std::string("expected ") + header[words.size()] +
                             " on a line of its own: an Lparser file "
                             "starts with three numbers");
    }
    Draft draft;
    set_notation(draft);
    Settings& s = draft.defaults;
    set_depth(s, words[0]);
    s.angle_deg = number(words[1], header[1]);
    set_thickness(s, words[2]);
    if (words.size() < 4) {
      fail(words[2].end, "expected the axiom after the three numbers");
    }
    draft.axiom = words[3];
    for (std::size_t k = 4; k < words.size(); ++k) {
      const Range rule = words[k];
      if (rule.end - rule.begin < 2 || text_[rule.begin + 1] != '=') {
        fail(rule.begin,
             "expected a rule such as 'F=FF' (one character, '=', the "
             "successor, no blanks) or '@' to end the file");
      }
      draft.productions.push_back(
          ProductionText{Range{rule.begin, rule.begin + 1},
                         std::nullopt,
                         {Range{rule.begin + 2, rule.end}}});
    }
    Grammar grammar = build_grammar(*this, std::move(draft), options_);
    pass_parameters_on(grammar);
    return grammar;
  }

 private:
  static bool is_blank_char(char c) {
    return c == ' ' || c == '\t' || c == '\r';
  }

  Range trimmed(Range r) const {
    while (r.begin < r.end && is_blank_char(text_[r.begin])) ++r.begin;
    while (r.end > r.begin && is_blank_char(text_[r.end - 1])) --r.end;
    return r;
  }

  void set_depth(Settings& s, Range word) const {
    const double depth = number(word, "the recursion depth");
    if (depth < 0 || depth > kMaxDerivationLength ||
        depth != std::floor(depth)) {
      fail(word.begin,
           depth != std::floor(depth)
               ? "a fractional recursion depth (Lparser's growing mode) is "
                 "not supported: give a whole number"
               : "expected a whole number from 0 to " +
                     std::to_string(kMaxDerivationLength));
    }
    s.derivation_length = static_cast<int>(depth);
    s.derivation_length_offset = word.begin;
  }

  void set_thickness(Settings& s, Range word) const {
    const double thickness =
        number(word, "the thickness (a percentage of length)");
    if (thickness < 0) fail(word.begin, "expected a non-negative number");
    s.initial_width = thickness / 100.0;
    s.width_offset = word.begin;
  }

  static void set_notation(Draft& draft) {
    Settings& s = draft.defaults;
    s.widths_relative_to_length = true;
    s.step = kStep;
    s.initial_color = kColor;
    draft.syntax = Syntax{.contexts_and_conditions = false,
                          .probability_after_successor = false,
                          .parameter_lists = true,
                          .cut_and_wildcard = false,
                          .fixed_arity = false};
    draft.symbols = kSymbols;
  }

  // Lparser 5's keyword form: `recursion`, `angle`, `thickness`, `axiom`,
  // `rule X = successor`; `min_thickness`, `shape` and `switch_yz` choose
  // how Lparser writes its output file, and are left out.
  Grammar run_keywords() {
    Draft draft;
    set_notation(draft);
    Settings& s = draft.defaults;
    for (const Range& l : lines(Range{0, text_.size()})) {
      const Range line = trimmed(l);
      if (line.empty()) continue;
      std::size_t i = line.begin;
      while (i < line.end && !is_blank_char(text_[i])) ++i;
      const std::string word(view(Range{line.begin, i}));
      const Range rest = trimmed(Range{i, line.end});
      if (word != "rule" && word != "axiom" && rest.empty()) {
        fail(line.end, "expected a value after '" + word + "'");
      }
      if (word == "recursion") {
        set_depth(s, rest);
      } else if (word == "angle") {
        s.angle_deg = number(rest, "the angle");
      } else if (word == "thickness") {
        set_thickness(s, rest);
      } else if (word == "min_thickness" || word == "shape" ||
                 word == "switch_yz") {
        draft.warnings.push_back("Lparser's '" + word +
                                 "' (how it writes its output) is left out");
      } else if (word == "axiom") {
        if (draft.axiom) fail(line.begin, "a second axiom");
        if (rest.empty()) fail(line.end, "expected the axiom after 'axiom'");
        draft.axiom = rest;
      } else if (word == "rule") {
        const std::size_t equals = find_in(rest, "=");
        const Range predecessor = equals == std::string::npos
                                      ? rest
                                      : trimmed(Range{rest.begin, equals});
        if (equals == std::string::npos ||
            predecessor.end - predecessor.begin != 1) {
          fail(rest.begin,
               "expected a rule such as 'rule F = FF' (one character, '=', "
               "the successor)");
        }
        draft.productions.push_back(ProductionText{
            predecessor, std::nullopt, {trimmed(Range{equals + 1, rest.end})}});
      } else {
        fail(line.begin,
             "unknown Lparser keyword '" + word +
                 "': expected recursion, angle, thickness, axiom or rule");
      }
    }
    if (!draft.axiom) fail(text_.size(), "no axiom: give one as 'axiom F'");
    Grammar grammar = build_grammar(*this, std::move(draft), options_);
    pass_parameters_on(grammar);
    return grammar;
  }

  double number(Range word, const char* what) const {
    const std::string text(view(word));
    char* end = nullptr;
    const double value = std::strtod(text.c_str(), &end);
    if (end == text.c_str() || *end != '\0' || !std::isfinite(value)) {
      fail(word.begin,
           std::string("expected ") + what + ", a number on a line of its own");
    }
    return value;
  }

  // In Lparser a module's `(x)` is text behind it, which a rule for the
  // module leaves behind its successor: `f=z` turns `f(200)` into
  // `z(200)`, and the last module of the successor reads it if it can.
  // So each rule of a module without parameters gets a twin for the
  // module with one, whose successor hands it to its last module where
  // that module has none of its own.
  void pass_parameters_on(Grammar& grammar) const {
    const auto slot_source = std::make_shared<const SourceFile>("x", "x");
    const Expression slot = parse_expression(
        slot_source, 0, 1, ExpressionScope{.parameters = {"x"}});
    std::vector<Production> twins;
    for (const Production& p : grammar.productions) {
      if (p.predecessor.parameter_count != 0) continue;
      Production twin = p;
      twin.predecessor.parameter_count = 1;
      Successor successor;
      const std::size_t n = p.successor.size();
      for (std::size_t i = 0; i < n; ++i) {
        const SymbolId symbol = p.successor.symbols()[i];
        const auto parameters = p.successor.parameters(i);
        std::vector<Expression> values(parameters.begin(), parameters.end());
        const TurtleCommand command = grammar.commands[symbol];
        if (i + 1 == n && values.empty() && max_parameters(command) >= 1) {
          values.push_back(slot);
        }
        successor.push_back(symbol, std::move(values), p.successor.offset(i));
      }
      twin.successor = std::move(successor);
      twins.push_back(std::move(twin));
    }
    for (Production& twin : twins) {
      grammar.productions.push_back(std::move(twin));
    }
  }

  const ParseOptions& options_;
  bool keywords_;
};

}  // namespace

Grammar read_lparser(std::shared_ptr<const SourceFile> source,
                     const ParseOptions& options) {
  const bool keywords = keyword_form(source->text());
  return LparserReader(std::move(source), options, keywords).run();
}

}  // namespace lsys::dialects
