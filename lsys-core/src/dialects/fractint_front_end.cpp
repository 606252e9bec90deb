// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Fractint's `.l` files (Fractint 20.4's lsys.c and its help text, "L-Systems";
// docs/dialects/fractint.md): several `Name { … }` systems per file, `;`
// comments, every line lower-cased before it is read (so `F` and `f` are
// one module), `Angle n` for turns of 360/n degrees, `Axiom`, and rules
// `X=body` of one character, several rules of one character joined in
// file order. The order is not in the file: Fractint asks for it, 2 by
// default.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "dialects/front_ends.hpp"
#include "dialects/grammar_builder.hpp"

namespace lsys::dialects {
namespace {

// Fractint compares the first 18 characters of a name (ITEMNAMELEN).
constexpr std::size_t kNameLength = 18;
constexpr int kDefaultOrder = 2;

// Drawing commands, after lower-casing; any other character is a module
// that draws nothing (lsys.c's default branch).
const std::vector<SymbolCommand> kSymbols = {
    {"f", TurtleCommand::Draw, std::nullopt},
    {"d", TurtleCommand::Draw, std::nullopt},
    {"g", TurtleCommand::Move, std::nullopt},
    {"m", TurtleCommand::Move, std::nullopt},
    {"+", TurtleCommand::TurnLeft, std::nullopt},
    {"-", TurtleCommand::TurnRight, std::nullopt},
    {"\\", TurtleCommand::TurnLeft, std::nullopt},
    {"/", TurtleCommand::TurnRight, std::nullopt},
    {"|", TurtleCommand::TurnRightFixed, std::nullopt},
    {"!", TurtleCommand::SwapTurns, std::nullopt},
    {"@", TurtleCommand::MultiplyStep, std::nullopt},
    {"c", TurtleCommand::ColorNext, std::nullopt},
    {"<", TurtleCommand::ColorAdd, std::nullopt},
    {">", TurtleCommand::ColorAdd, std::nullopt},
    {"[", TurtleCommand::Push, std::nullopt},
    {"]", TurtleCommand::Pop, std::nullopt},
};

// The commands that cannot have a rule (lsys.c).
constexpr std::string_view kReserved = "+-/\\@|!c<>[]";

// Lower-cases ASCII letters and blanks `;` comments, keeping offsets.
std::string clean_text(const std::string& text) {
  std::string out = text;
  bool comment = false;
  for (char& c : out) {
    if (c == '\n') comment = false;
    if (c == ';') comment = true;
    if (comment) {
      c = ' ';
    } else if (static_cast<unsigned char>(c) < 0x80U) {
      c = lower(c);
    }
  }
  return out;
}

struct Entry {
  Range name;
  Range body;  // from after `{` to the start of the `}` line, or the end
};

class FractintReader : TextScan {
 public:
  FractintReader(std::shared_ptr<const SourceFile> source,
                 const ParseOptions& options)
      : TextScan(source, clean_text(source->text())), options_(options) {}

  Grammar run() {
    const Entry entry = choose(entries());
    read_body(entry);
    Draft draft = std::move(draft_);
    draft.syntax = Syntax{.contexts_and_conditions = false,
                          .probability_after_successor = false,
                          .parameter_lists = false,
                          .cut_and_wildcard = false};
    draft.symbols = kSymbols;
    draft.defaults.derivation_length = kDefaultOrder;
    draft.defaults.initial_color = 15;
    draft.inline_parameter = [this](std::string_view name, std::size_t at,
                                    Range r) {
      return number_after(name, at, r);
    };
    if (!draft.axiom) fail(entry.name.begin, "this system has no axiom");
    if (angle_steps_ == 0) {
      fail(entry.name.begin,
           "this system has no 'angle' (Fractint's turns "
           "are 360/n degrees for 'angle n')");
    }
    draft.defaults.angle_deg = 360.0 / angle_steps_;
    // `|` turns n/2 steps (integer division) the way `-` turns: 180° for
    // an even n, the largest turn under 180° for an odd one.
    for (SymbolCommand& symbol : draft.symbols) {
      if (symbol.name == "|") {
        symbol.default_parameter =
            (angle_steps_ / 2) * 360.0 / static_cast<double>(angle_steps_);
      }
    }
    reject_two_headings(draft);
    return build_grammar(*this, std::move(draft), options_);
  }

 private:
  // Every `Name {` of the file, with its body, which runs to the first
  // `}` (Fractint's scan_entries). A nameless block and one named `comment`
  // are comments (Fractint leaves them out of its list).
  std::vector<Entry> entries() const {
    std::vector<Entry> out;
    std::size_t start = 0;
    while (start < text_.size()) {
      std::size_t end = text_.find('\n', start);
      if (end == std::string::npos) end = text_.size();
      const Range line = trim(Range{start, end});
      start = end + 1;
      const std::size_t brace = find_in(line, "{");
      if (line.empty() || brace == std::string::npos) continue;
      std::size_t name_end = line.begin;
      while (name_end < line.end &&
             std::string_view(" \t([{").find(text_[name_end]) ==
                 std::string_view::npos) {
        ++name_end;
      }
      const Range name{line.begin, name_end};
      const bool comment = name.empty() || view(name) == "comment";
      const std::size_t close = text_.find('}', brace + 1);
      if (close == std::string::npos) {
        if (comment) break;
        fail(name.begin,
             "'" + original_name(name) + " {' has no closing '}' line");
      }
      if (!comment) {
        reject_inner_start(name, Range{brace + 1, close});
        out.push_back(Entry{name, Range{brace + 1, close}});
      }
      end = text_.find('\n', close);
      start = end == std::string::npos ? text_.size() : end + 1;
    }
    return out;
  }

  // A system that starts before the one above it has closed: that one
  // lacks its `}`.
  void reject_inner_start(Range name, Range body) const {
    for (const Range& raw : lines(body)) {
      const Range line = trim(raw);
      const std::size_t brace = find_in(line, "{");
      if (brace == std::string::npos || brace == line.begin) continue;
      // A `{` after a keyword or in a rule is a stray character (Rouse's
      // `Angle 6 {`), not a system's start.
      if (match_words(line.begin, line.end, "angle") ||
          match_words(line.begin, line.end, "axiom") ||
          find_in(Range{line.begin, brace}, "=") != std::string::npos) {
        continue;
      }
      fail(line.begin, "a system starts inside '" + original_name(name) +
                           " {' (line " +
                           std::to_string(source_->location(name.begin).line) +
                           "), which has no closing '}' line");
    }
  }

  std::string original_name(Range name) const {
    return source_->text().substr(name.begin, name.end - name.begin);
  }

  static std::string key(std::string_view name) {
    std::string k(name.substr(0, kNameLength));
    for (char& c : k) c = lower(c);
    return k;
  }

  Entry choose(const std::vector<Entry>& entries) const {
    if (entries.empty()) fail(0, "no system 'Name { … }' in this file");
    std::string names;
    for (const Entry& e : entries) {
      if (!names.empty()) names += ", ";
      names += original_name(e.name);
    }
    if (options_.system.empty()) {
      if (entries.size() == 1) return entries.front();
      fail(entries.front().name.begin,
           "this file holds " + std::to_string(entries.size()) +
               " systems; choose one with --system NAME: " + names);
    }
    for (const Entry& e : entries) {
      if (key(view(e.name)) == key(options_.system)) return e;
    }
    fail(entries.front().name.begin, "no system named '" + options_.system +
                                         "' in this file; it holds " + names);
  }

  // The token at `at`, as strtok cuts it: delimiters before it skipped.
  Range token(std::size_t at, std::size_t end,
              std::string_view delimiters) const {
    while (at < end && delimiters.find(text_[at]) != std::string_view::npos) {
      ++at;
    }
    std::size_t stop = at;
    while (stop < end && delimiters.find(text_[stop]) == std::string_view::npos)
      ++stop;
    return Range{at, stop};
  }

  void read_body(const Entry& entry) {
    for (const Range& line : lines(entry.body)) {
      if (!trim(line).empty()) read_line(trim(line));
    }
  }

  void read_line(Range line) {
    const Range first = token(line.begin, line.end, " \t=");
    const std::string_view word = view(first);
    const std::size_t next = first.end;
    if (word == "axiom") {
      // `axiom=FX` works (`=` ends the keyword), `axiom = FX` does not.
      const Range value =
          token(next < line.end && text_[next] == '=' ? next + 1 : next,
                line.end, " \t");
      if (value.empty()) fail(first.end, "expected the axiom after 'axiom'");
      if (draft_.axiom) fail(first.begin, "a second axiom");
      draft_.axiom = value;
      reject_extra(value.end, line.end);
      return;
    }
    if (word == "angle") {
      const Range value = token(next, line.end, " \t=");
      const std::string_view digits = view(value);
      int n = 0;
      if (digits.empty() || digits.size() > 3 ||
          !std::all_of(digits.begin(), digits.end(), [](char c) {
            return std::isdigit(static_cast<unsigned char>(c)) != 0;
          })) {
        fail(value.begin, "expected a whole number of steps after 'angle'");
      }
      n = std::stoi(std::string(digits));
      if (n < 3 || n > 50) {
        fail(value.begin,
             "Fractint's angle is a number of steps from 3 to 50 (turns of "
             "360/n degrees), here " +
                 std::to_string(n));
      }
      angle_steps_ = n;
      reject_extra(value.end, line.end);
      return;
    }
    if (word.empty() || code_point_length(word) != word.size()) {
      fail(first.begin,
           "expected 'axiom', 'angle', a rule such as 'F=F+F' "
           "or '}', not '" +
               std::string(word) + "'");
    }
    if (kReserved.find(word) != std::string_view::npos) {
      std::string message = "'";
      message += word;
      message += "' is a drawing command and cannot have a rule";
      fail(first.begin, message);
    }
    const Range body = token(next, line.end, " \t=");
    reject_extra(body.end, line.end);
    for (ProductionText& p : draft_.productions) {
      if (view(p.lhs) == word) {  // Fractint joins rules of one symbol
        p.rhs.push_back(body);
        return;
      }
    }
    draft_.productions.push_back(ProductionText{first, std::nullopt, {body}});
  }

  void reject_extra(std::size_t at, std::size_t end) const {
    const Range rest = trim(Range{at, end});
    if (!rest.empty()) {
      fail(rest.begin,
           "extra text: a Fractint rule or axiom is one word, "
           "without blanks");
    }
  }

  // `\30`, `@.5`, `@IQ3` (1/√3), `C12`, `<2`: Fractint's getnumber, which
  // gives 0 where no positive number follows.
  std::optional<InlineParameter> number_after(std::string_view name,
                                              std::size_t at, Range r) const {
    if (name.size() != 1 ||
        std::string_view("\\/@c<>").find(name) == std::string_view::npos) {
      return std::nullopt;
    }
    bool root = false;
    bool inverse = false;
    std::size_t i = at;
    for (int k = 0; k < 2 && i < r.end; ++k) {
      if (text_[i] == 'q') {
        root = true;
      } else if (text_[i] == 'i') {
        inverse = true;
      } else {
        break;
      }
      ++i;
    }
    const std::size_t digits = i;
    while (i < r.end &&
           (std::isdigit(static_cast<unsigned char>(text_[i])) != 0 ||
            text_[i] == '.')) {
      ++i;
    }
    double value = 0.0;
    if (i > digits)
      value = std::atof(std::string(view(Range{digits, i})).c_str());
    if (value <= 0.0) {
      value = 0.0;
    } else {
      if (root) value = std::sqrt(value);
      if (inverse) value = 1.0 / value;
    }
    if (name == "c" || name == "<" || name == ">") value = std::trunc(value);
    if (name == ">") value = -value;
    return InlineParameter{i, value};
  }

  // Fractint keeps two headings: `+ - |` turn the one `F` and `G` follow,
  // `\ /` the one `D` and `M` follow. lsolid's turtle has one, which is
  // the same picture unless a system mixes the two families.
  void reject_two_headings(const Draft& draft) const {
    std::vector<Range> texts;
    if (draft.axiom) texts.push_back(*draft.axiom);
    for (const ProductionText& p : draft.productions) {
      texts.insert(texts.end(), p.rhs.begin(), p.rhs.end());
    }
    std::optional<std::size_t> index_turn;
    std::optional<std::size_t> degree_turn;
    std::optional<std::size_t> index_move;
    std::optional<std::size_t> degree_move;
    for (const Range& r : texts) {
      for (std::size_t i = r.begin; i < r.end; ++i) {
        const char c = text_[i];
        if (c == '+' || c == '-' || c == '|')
          index_turn = index_turn.value_or(i);
        if (c == '\\' || c == '/') degree_turn = degree_turn.value_or(i);
        if (c == 'f' || c == 'g') index_move = index_move.value_or(i);
        if (c == 'd' || c == 'm') degree_move = degree_move.value_or(i);
      }
    }
    if (index_turn && degree_move) {
      fail(*degree_move,
           "this system turns with '+', '-' or '|', which Fractint's 'D' and "
           "'M' do not follow (they keep a heading of their own); lsolid's "
           "turtle has one heading: not supported");
    }
    if (degree_turn && index_move) {
      fail(*index_move,
           "this system turns with '\\' or '/', which Fractint's 'F' and "
           "'G' do not follow (they keep a heading of their own); lsolid's "
           "turtle has one heading: not supported");
    }
  }

  const ParseOptions& options_;
  Draft draft_;
  int angle_steps_ = 0;
};

}  // namespace

Grammar read_fractint(std::shared_ptr<const SourceFile> source,
                      const ParseOptions& options) {
  return FractintReader(std::move(source), options).run();
}

}  // namespace lsys::dialects
