// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Reads `.ls` files: the notations of ABOP's captions (Prusinkiewicz and
// Lindenmayer 1990), cpfg (`#define`, `derivation length:`, `-->`), L-Py
// (`Axiom:`, `module`), Houdini (`premise:`) and the source documents of
// printables/, as docs/language.md describes. Two passes: the first sorts
// lines into settings, productions and the axiom and collects the names of
// predecessors, so that the second can tokenise multi-character module names
// by longest match wherever they appear (ABOP fig. 1.26).
#include "lsys/parser.hpp"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <optional>
#include <set>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "lsys/diagnostic.hpp"

namespace lsys {
namespace {

struct Range {
  std::size_t begin = 0;
  std::size_t end = 0;
  [[nodiscard]] bool empty() const { return begin >= end; }
};

enum class Section { Productions, Decomposition, Homomorphism, Aliases };

enum class Key {
  Axiom,
  DerivationLength,
  Angle,
  AngleFactor,
  Step,
  Width,
  Radius,
  WidthIncrement,
  WidthFactor,
  WidthScale,
  WidthPerGeneration,
  RadiusPerGeneration,
  Color,
  Tropism,
  Elasticity,
  Seed,
  Roll,
  MaximumDepth,
  Ignore,
  Consider,
  LsystemLabel,
  Extra
};

struct Spelling {
  std::string_view text;
  Key key;
};

// Every spelling of every setting; longest first so that `width increment`
// wins over `width`. A space matches any run of blanks.
constexpr std::array<Spelling, 45> kSpellings = [] {
  std::array<Spelling, 45> s{{
      {"axiom", Key::Axiom},
      {"\u03C9", Key::Axiom},
      {"premise", Key::Axiom},
      {"initial value", Key::Axiom},
      {"n", Key::DerivationLength},
      {"derivation length", Key::DerivationLength},
      {"iterations", Key::DerivationLength},
      {"generations", Key::DerivationLength},
      {"\u03B4", Key::Angle},
      {"\u03C3", Key::Angle},
      {"delta", Key::Angle},
      {"angle", Key::Angle},
      {"angle increment", Key::Angle},
      {"angle factor", Key::AngleFactor},
      {"step", Key::Step},
      {"step size", Key::Step},
      {"branch length", Key::Step},
      {"branch length (height)", Key::Step},
      {"width", Key::Width},
      {"initial width", Key::Width},
      {"initial line width", Key::Width},
      {"radius", Key::Radius},
      {"branch radius", Key::Radius},
      {"width increment", Key::WidthIncrement},
      {"line width increment", Key::WidthIncrement},
      {"width factor", Key::WidthFactor},
      {"thickness scale", Key::WidthFactor},
      {"width scale", Key::WidthScale},
      {"width decrement per generation", Key::WidthPerGeneration},
      {"radius reduction per generation", Key::RadiusPerGeneration},
      {"branch radius reduction", Key::RadiusPerGeneration},
      {"color", Key::Color},
      {"colour", Key::Color},
      {"initial color", Key::Color},
      {"tropism", Key::Tropism},
      {"tropism direction", Key::Tropism},
      {"elasticity", Key::Elasticity},
      {"initial elasticity", Key::Elasticity},
      {"seed", Key::Seed},
      {"roll", Key::Roll},
      {"maximum depth", Key::MaximumDepth},
      {"ignore", Key::Ignore},
      {"consider", Key::Consider},
      {"lsystem", Key::LsystemLabel},
      {"initial colour", Key::Color},
  }};
  for (std::size_t i = 1; i < s.size(); ++i) {
    for (std::size_t j = i; j > 0 && s[j - 1].text.size() < s[j].text.size();
         --j) {
      std::swap(s[j - 1], s[j]);
    }
  }
  return s;
}();

struct Header {
  std::string_view text;
  Section section;
};

constexpr std::array<Header, 8> kHeaders{{
    {"production rules", Section::Productions},
    {"productions", Section::Productions},
    {"production", Section::Productions},
    {"homomorphism", Section::Homomorphism},
    {"interpretation", Section::Homomorphism},
    {"decomposition", Section::Decomposition},
    {"aliases", Section::Aliases},
    {"alias", Section::Aliases},
}};

bool is_blank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\n';
}

bool is_word_char(char c) {
  const auto u = static_cast<unsigned char>(c);
  return std::isalnum(u) != 0 || c == '_' || u >= 0x80U;
}

bool is_identifier(std::string_view s) {
  if (s.empty()) return false;
  const auto first = static_cast<unsigned char>(s.front());
  if (std::isdigit(first) != 0) return false;
  return std::all_of(s.begin(), s.end(), is_word_char);
}

char lower(char c) {
  return static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
}

// The text of a production before the successor.
struct ProductionText {
  Range lhs;
  std::optional<Range> probability;  // ABOP's -(p)→
  std::vector<Range> rhs;            // continuation lines append
  Section section = Section::Productions;
};

struct SettingText {
  Key key;
  std::string extra_key;
  Range key_range;
  Range value;
};

class Parser {
 public:
  Parser(std::shared_ptr<const SourceFile> source, const ParseOptions& options)
      : source_(std::move(source)),
        options_(options),
        clean_(blank_comments(source_->text())),
        text_(clean_) {}

  Grammar run() {
    grammar_.source = source_;
    for (const char* name : {"[", "]", "%", "*"})
      grammar_.alphabet.intern(name);
    // Multi-character turtle modules must be known to the tokeniser.
    for (const char* name : {"@v", "@Tp", "@Ts"})
      grammar_.alphabet.intern(name);
    sort_lines();
    evaluate_defines();  // labels are told from conditions over constants
    declare_names();
    read_aliases();
    read_module_declarations();
    read_settings();
    read_axiom();
    for (const ProductionText& p : productions_) read_production(p);
    reject_letter_settings_of_modules();
    build_commands();
    for (const std::string& name : given_defines_) {
      if (used_constants_.count(name) == 0 && !file_defines_.count(name)) {
        grammar_.warnings.push_back("--define " + name +
                                    ": the file neither defines nor uses '" +
                                    name + "'");
      }
    }
    return std::move(grammar_);
  }

 private:
  [[noreturn]] void fail(std::size_t offset, std::string message) const {
    throw error_at(*source_, offset, std::move(message));
  }

  // --- Pass 1: lines ------------------------------------------------------

  // Replaces comments by blanks, keeping line breaks and byte offsets:
  // `/* ... */` anywhere, and from a `#` that stands alone as a word (a
  // blank or the line's start before it, a blank or the line's end after
  // it) to the end of the line (`axiom: F   # three`), as L-Py and shells
  // write them. A `#` that touches a module is cpfg's widen (`F#F`,
  // `#(2)`), and one followed by a letter starts a directive.
  std::string blank_comments(const std::string& text) const {
    std::string out = text;
    const auto is_space = [](char c) {
      return c == ' ' || c == '\t' || c == '\n' || c == '\r';
    };
    for (std::size_t i = 0; i < out.size(); ++i) {
      if (out[i] == '#' && (i == 0 || is_space(out[i - 1])) &&
          (i + 1 == out.size() || is_space(out[i + 1]))) {
        for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
        continue;
      }
      if (out[i] != '/' || i + 1 == out.size() || out[i + 1] != '*') continue;
      const std::size_t close = out.find("*/", i + 2);
      if (close == std::string::npos) fail(i, "unterminated comment '/*'");
      for (std::size_t j = i; j < close + 2; ++j) {
        if (out[j] != '\n') out[j] = ' ';
      }
      i = close + 1;
    }
    return out;
  }

  Range trim(Range r) const {
    while (r.begin < r.end && is_blank(text_[r.begin])) ++r.begin;
    while (r.end > r.begin && is_blank(text_[r.end - 1])) --r.end;
    return r;
  }

  std::string_view view(Range r) const {
    return text_.substr(r.begin, r.end - r.begin);
  }

  // Finds `what` in r (and nowhere after it: a search to the end of the
  // text for each of many lines would be quadratic); npos if absent.
  std::size_t find_in(Range r, std::string_view what) const {
    const std::size_t at = view(r).find(what);
    return at == std::string_view::npos ? std::string::npos : r.begin + at;
  }

  // Finds `token` at paren depth 0 in r; npos if absent.
  std::size_t find_top(Range r, std::string_view token,
                       std::size_t from = std::string::npos) const {
    int depth = 0;
    for (std::size_t i = from == std::string::npos ? r.begin : from; i < r.end;
         ++i) {
      const char c = text_[i];
      if (c == '(') ++depth;
      if (c == ')') --depth;
      if (depth == 0 && text_.substr(i, token.size()) == token &&
          i + token.size() <= r.end) {
        return i;
      }
    }
    return std::string::npos;
  }

  std::vector<Range> split_top(Range r, char separator) const {
    std::vector<Range> pieces;
    int depth = 0;
    std::size_t start = r.begin;
    for (std::size_t i = r.begin; i < r.end; ++i) {
      if (text_[i] == '(') ++depth;
      if (text_[i] == ')') --depth;
      if (depth == 0 && text_[i] == separator) {
        pieces.push_back(Range{start, i});
        start = i + 1;
      }
    }
    pieces.push_back(Range{start, r.end});
    return pieces;
  }

  struct Arrow {
    Range lhs;
    std::optional<Range> probability;
    Range rhs;
  };

  // Finds the arrow of a production: →, ⟶, -->, ->, ::= anywhere at paren
  // depth 0, or else a lone `=` when `allow_equals`.
  std::optional<Arrow> find_arrow(Range r, bool allow_equals) const {
    int depth = 0;
    for (std::size_t i = r.begin; i < r.end; ++i) {
      const char c = text_[i];
      if (c == '(') ++depth;
      if (c == ')') --depth;
      if (depth != 0) continue;
      const std::string_view rest = text_.substr(i, r.end - i);
      std::size_t length = 0;
      for (std::string_view arrow : {"\u2192", "\u27F6", "-->", "->", "::="}) {
        if (rest.starts_with(arrow)) {
          length = arrow.size();
          break;
        }
      }
      if (length > 0) return make_arrow(r, i, i + length);
    }
    if (!allow_equals) return std::nullopt;
    if (const std::size_t e = find_equals(r); e != std::string::npos) {
      return make_arrow(r, e, e + 1);
    }
    return std::nullopt;
  }

  std::size_t find_equals(Range r) const {
    int depth = 0;
    for (std::size_t i = r.begin; i < r.end; ++i) {
      const char c = text_[i];
      if (c == '(') ++depth;
      if (c == ')') --depth;
      if (depth != 0 || c != '=') continue;
      const char before = i > r.begin ? text_[i - 1] : ' ';
      const char after = i + 1 < r.end ? text_[i + 1] : ' ';
      if (std::string_view("<>!=:").find(before) != std::string_view::npos ||
          after == '=') {
        continue;
      }
      return i;
    }
    return std::string::npos;
  }

  // ABOP writes stochastic productions as `F -(.33)→ F[+F]F`.
  Arrow make_arrow(Range r, std::size_t begin, std::size_t end) const {
    Arrow arrow{Range{r.begin, begin}, std::nullopt, Range{end, r.end}};
    std::size_t q = begin;
    while (q > r.begin && is_blank(text_[q - 1])) --q;
    if (q == r.begin || text_[q - 1] != ')') return arrow;
    int depth = 0;
    std::size_t open = q - 1;
    for (;; --open) {
      if (text_[open] == ')') ++depth;
      if (text_[open] == '(') --depth;
      if (depth == 0 || open == r.begin) break;
    }
    if (depth != 0 || open == r.begin || text_[open - 1] != '-') return arrow;
    const Range before = trim(Range{r.begin, open - 1});
    if (before.empty()) return arrow;  // `-(a) → …` rewrites the module `-`
    arrow.lhs = Range{r.begin, open - 1};
    arrow.probability = Range{open + 1, q - 1};
    return arrow;
  }

  // Matches a setting spelling at the start of r, followed by `:` or `=`.
  // Returns the end of the key and the start of the value.
  struct KeyMatch {
    Key key;
    std::string extra;
    std::size_t key_end;
    std::size_t value_begin;
  };

  std::optional<std::size_t> match_words(std::size_t pos, std::size_t end,
                                         std::string_view spelling) const {
    for (std::size_t k = 0; k < spelling.size(); ++k) {
      if (spelling[k] == ' ') {
        if (pos >= end || !is_blank(text_[pos])) return std::nullopt;
        while (pos < end && is_blank(text_[pos])) ++pos;
        continue;
      }
      if (pos >= end || lower(text_[pos]) != spelling[k]) return std::nullopt;
      ++pos;
    }
    if (pos < end && is_word_char(text_[pos]) &&
        is_word_char(spelling.back())) {
      return std::nullopt;
    }
    return pos;
  }

  std::optional<KeyMatch> match_key(Range r) const {
    const auto separator = [&](std::size_t pos) -> std::optional<std::size_t> {
      while (pos < r.end && is_blank(text_[pos])) ++pos;
      if (pos >= r.end) return std::nullopt;
      if (text_[pos] == ':' && text_.substr(pos, 3) != "::=") return pos + 1;
      if (text_[pos] == '=' && (pos + 1 >= r.end || text_[pos + 1] != '=')) {
        return pos + 1;
      }
      return std::nullopt;
    };
    for (const std::string& extra : options_.extra_settings) {
      std::string spelling;
      for (char c : extra) spelling += lower(c);
      if (const auto end = match_words(r.begin, r.end, spelling)) {
        if (const auto value = separator(*end)) {
          return KeyMatch{Key::Extra, extra, *end, *value};
        }
      }
    }
    for (const Spelling& s : kSpellings) {
      if (const auto end = match_words(r.begin, r.end, s.text)) {
        if (const auto value = separator(*end)) {
          return KeyMatch{s.key, {}, *end, *value};
        }
      }
    }
    return std::nullopt;
  }

  // `name:` or `name =` (a setting's start, known or not).
  bool starts_with_name_and_separator(Range r) const {
    std::size_t i = r.begin;
    while (i < r.end && (is_word_char(text_[i]) || text_[i] == ' ')) ++i;
    if (i == r.begin || i >= r.end) return false;
    if (std::isdigit(static_cast<unsigned char>(text_[r.begin])) != 0)
      return false;
    return (text_[i] == ':' && text_.substr(i, 3) != "::=") ||
           (text_[i] == '=' && text_.substr(i, 2) != "==");
  }

  void add_settings(Range line) {
    // `n=2, δ=90°`: split at commas that are followed by another setting.
    std::vector<std::size_t> cuts;
    int depth = 0;
    for (std::size_t i = line.begin; i < line.end; ++i) {
      if (text_[i] == '(') ++depth;
      if (text_[i] == ')') --depth;
      if (depth == 0 && text_[i] == ',' &&
          starts_with_name_and_separator(trim(Range{i + 1, line.end}))) {
        cuts.push_back(i);
      }
    }
    cuts.push_back(line.end);
    std::size_t start = line.begin;
    for (std::size_t cut : cuts) {
      const Range piece = trim(Range{start, cut});
      const auto match = match_key(piece);
      if (!match) {
        std::size_t end = piece.begin;
        while (end < piece.end &&
               (is_word_char(text_[end]) || text_[end] == ' '))
          ++end;
        fail(piece.begin, "unknown setting '" +
                              std::string(view(trim(Range{piece.begin, end}))) +
                              "'");
      }
      Range value{match->value_begin, piece.end};
      // `n=2 // two`: numbers never contain `//`; modules (the axiom, lists)
      // may, as rolls.
      if (match->key != Key::Axiom && match->key != Key::Ignore &&
          match->key != Key::Consider) {
        const std::size_t comment = find_in(value, "//");
        if (comment != std::string::npos) value.end = comment;
      }
      settings_.push_back(SettingText{match->key, match->extra,
                                      Range{piece.begin, match->key_end},
                                      trim(value)});
      start = cut + 1;
    }
  }

  bool add_productions(Range line) {
    // Several productions may share a line, separated by commas, when each
    // piece has an arrow (seed 001: `A = f[^Bl]>>[^Bl]>>A, B = f[-Bl]B`).
    const std::vector<Range> pieces = split_top(line, ',');
    std::vector<Arrow> arrows;
    if (pieces.size() > 1) {
      for (const Range& piece : pieces) {
        auto arrow = find_arrow(trim(piece), true);
        if (!arrow) break;
        arrows.push_back(*arrow);
      }
    }
    if (arrows.size() != pieces.size() || pieces.size() == 1) {
      arrows.clear();
      auto arrow = find_arrow(line, true);
      if (!arrow) return false;
      arrows.push_back(*arrow);
    }
    for (const Arrow& arrow : arrows) {
      productions_.push_back(
          ProductionText{arrow.lhs, arrow.probability, {arrow.rhs}, section_});
    }
    return true;
  }

  // True for text that can only be a value: digits, operators, parentheses
  // and a degree sign (`90`, `0.5*2`, `22.5°`), not modules.
  bool is_value_text(Range r) const {
    const std::string_view v = view(trim(r));
    return !v.empty() && std::all_of(v.begin(), v.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) != 0 ||
             std::string_view(".-+*/^() eE\xC2\xB0").find(c) !=
                 std::string_view::npos;
    }) && std::any_of(v.begin(), v.end(), [](char c) {
      return std::isdigit(static_cast<unsigned char>(c)) != 0;
    });
  }

  // `anlge=90, n=2`: a line of `name = value` pieces where a piece names a
  // known setting, or gives a number to a multi-letter word, is a settings
  // line, and its unknown names are errors (not Houdini `=` productions).
  void reject_misspelt_settings(Range line) const {
    bool is_settings_line = false;
    std::vector<Range> unknown;
    for (const Range& raw : split_top(line, ',')) {
      const Range piece = trim(raw);
      if (match_key(piece)) {
        is_settings_line = true;
        continue;
      }
      const std::size_t equals = find_equals(piece);
      if (equals == std::string::npos) return;
      const Range word = trim(Range{piece.begin, equals});
      const std::string_view name = view(word);
      if (name.empty() || !std::all_of(name.begin(), name.end(), [](char c) {
            return is_word_char(c) || c == ' ';
          })) {
        return;
      }
      if (code_point_length(name) < name.size() &&
          declared_modules_.count(std::string(name)) == 0 &&
          is_value_text(Range{equals + 1, piece.end})) {
        is_settings_line = true;
      }
      unknown.push_back(word);
    }
    if (is_settings_line && !unknown.empty()) {
      fail(unknown.front().begin,
           "unknown setting '" + std::string(view(unknown.front())) + "'");
    }
  }

  // True if every name in `r` is a constant (`#define` so far, or
  // `--define`) and the rest is numbers and arithmetic.
  bool looks_like_value(Range r) const {
    if (is_value_text(r)) return true;
    bool has_name = false;
    for (std::size_t i = r.begin; i < r.end;) {
      const char c = text_[i];
      if (!is_word_char(c) || std::isdigit(static_cast<unsigned char>(c))) {
        if (!is_blank(c) && !std::isdigit(static_cast<unsigned char>(c)) &&
            std::string_view(".+-*/^()").find(c) == std::string_view::npos) {
          return false;
        }
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < r.end && is_word_char(text_[j])) ++j;
      const std::string_view word = text_.substr(i, j - i);
      const bool is_constant =
          std::any_of(defines_.begin(), defines_.end(),
                      [&](const auto& d) { return view(d.first) == word; }) ||
          std::any_of(options_.defines.begin(), options_.defines.end(),
                      [&](const std::string& d) {
                        return std::string_view(d).substr(0, d.find('=')) ==
                               word;
                      });
      if (!is_constant) return false;
      has_name = true;
      i = j;
    }
    return has_name;
  }

  // Fractint writes productions with `=`: `N=O` rewrites N. A one-letter
  // setting name (`n`, `N`, `δ`) before `=` and something other than a
  // value (a number, or arithmetic over numbers and constants) is such a
  // production; before a value it is a setting, and read_settings refuses
  // it when the file also uses the letter as a module.
  bool is_one_letter_production(Range line, const KeyMatch& key) const {
    if (key.key == Key::Axiom || key.key == Key::Extra) return false;
    const std::string_view name = view(trim(Range{line.begin, key.key_end}));
    if (code_point_length(name) != name.size() ||
        text_[key.value_begin - 1] != '=') {
      return false;
    }
    Range value{key.value_begin, split_top(line, ',').front().end};
    if (const std::size_t comment = find_in(value, "//");
        comment != std::string::npos) {
      value.end = comment;  // `n=2 // two steps`
    }
    return !looks_like_value(trim(value));
  }

  // `axiom X`, `n 5`, Fractint's `Angle 6`: a setting's name and a value
  // without `:` or `=` would otherwise become modules (`axiomX`).
  void reject_missing_separator(Range line) const {
    for (const Spelling& s : kSpellings) {
      const auto end = match_words(line.begin, line.end, s.text);
      if (!end || *end >= line.end || !is_blank(text_[*end])) continue;
      const Range value = trim(Range{*end, line.end});
      const std::string name(view(Range{line.begin, *end}));
      // A single letter is a setting only before a number (`n 5`, not the
      // modules `n F`); a declared name is a module.
      if ((code_point_length(name) == name.size() && !is_value_text(value)) ||
          declared_modules_.count(name) != 0) {
        continue;
      }
      const std::string v(view(value));
      std::string hint = "write '" + name + ": " + v + "'";
      if (s.key == Key::Angle) {
        hint += " for " + v + " degrees, or 'angle factor: " + v +
                "' for Fractint's 360/" + v + " degrees";
      }
      fail(*end, "missing ':' after '" + name + "': " + hint);
    }
  }

  // A word before `:`, or a multi-letter word before `= number`, reads as a
  // setting; an ABOP label such as `p1:` does not.
  void reject_unknown_setting(Range line) const {
    reject_misspelt_settings(line);
    std::size_t i = line.begin;
    while (i < line.end && (is_word_char(text_[i]) || text_[i] == ' ')) ++i;
    const Range word = trim(Range{line.begin, i});
    if (word.empty() || i >= line.end) return;
    const std::string_view name = view(word);
    if (std::isdigit(static_cast<unsigned char>(name.front())) != 0 ||
        has_abop_label(line)) {
      return;
    }
    if (find_equals(line) == std::string::npos) {
      if (text_[i] == ':' && text_.substr(i, 3) != "::=") {
        fail(word.begin, "unknown setting '" + std::string(name) + "'");
      }
      return;
    }
    if (text_[i] != '=' || code_point_length(name) == name.size() ||
        declared_modules_.count(std::string(name)) != 0) {
      return;
    }
    const std::string_view value = view(trim(Range{i + 1, line.end}));
    const bool numeric =
        !value.empty() && std::all_of(value.begin(), value.end(), [](char c) {
          return std::isdigit(static_cast<unsigned char>(c)) != 0 ||
                 std::string_view(".-+eE \xC2\xB0").find(c) !=
                     std::string_view::npos;
        });
    if (numeric)
      fail(word.begin, "unknown setting '" + std::string(name) + "'");
  }

  std::optional<std::pair<Section, Range>> match_header(Range line) const {
    for (const Header& h : kHeaders) {
      const auto end = match_words(line.begin, line.end, h.text);
      if (!end) continue;
      std::size_t pos = *end;
      while (pos < line.end && is_blank(text_[pos])) ++pos;
      if (pos == line.end) return std::pair{h.section, Range{pos, pos}};
      if (text_[pos] == ':' && text_.substr(pos, 3) != "::=") {
        return std::pair{h.section, trim(Range{pos + 1, line.end})};
      }
    }
    return std::nullopt;
  }

  void sort_lines() {
    bool after_production = false;
    std::size_t start = 0;
    while (start < text_.size()) {
      std::size_t end = text_.find('\n', start);
      if (end == std::string::npos) end = text_.size();
      const Range raw{start, end};
      start = end + 1;
      const Range line = trim(raw);
      if (line.empty()) continue;
      const bool indented = line.begin > raw.begin;
      const std::string_view t = view(line);
      if (t.starts_with("//")) continue;
      if (t.starts_with("#")) {
        if (t.size() > 1 &&
            std::isalpha(static_cast<unsigned char>(t[1])) != 0) {
          directive(line);
          after_production = false;
        }
        continue;
      }
      after_production = sort_line(line, indented, after_production);
    }
  }

  // Returns true if the line was (part of) a production.
  bool sort_line(Range line, bool indented, bool after_production) {
    if (match_words(line.begin, line.end, "endlsystem") == line.end ||
        match_words(line.begin, line.end, "warnings") == line.end ||
        match_words(line.begin, line.end, "no warnings") == line.end) {
      return false;
    }
    // A header alone starts a section; with content after its colon it
    // applies to that line only (`aliases: f=F`, `Production rules : A=fA`).
    Section section = section_;
    if (const auto header = match_header(line)) {
      if (header->second.empty()) {
        section_ = header->first;
        return false;
      }
      section = header->first;
      line = header->second;
    }
    const Section previous = std::exchange(section_, section);
    const bool result = sort_content(line, indented, after_production);
    section_ = previous;
    return result;
  }

  bool sort_content(Range line, bool indented, bool after_production) {
    if (section_ == Section::Aliases) {
      if (const auto key = match_key(line);
          key && !is_one_letter_production(line, *key)) {
        add_settings(line);
      } else {
        alias_lines_.push_back(line);
      }
      return false;
    }
    if (find_arrow(line, false)) return add_productions(line);
    for (std::string_view keyword : {"modules", "module"}) {
      if (const auto end = match_words(line.begin, line.end, keyword);
          end && *end < line.end &&
          (is_blank(text_[*end]) || text_[*end] == ':')) {
        std::size_t pos = *end;
        if (text_[pos] == ':') ++pos;
        const Range names = trim(Range{pos, line.end});
        module_lines_.push_back(names);
        for (const DeclaredName& declared : module_names(names)) {
          declared_modules_.insert(std::string(view(declared.name)));
        }
        return false;
      }
    }
    if (const auto key = match_key(line);
        key && !is_one_letter_production(line, *key)) {
      has_axiom_setting_ = has_axiom_setting_ || key->key == Key::Axiom;
      add_settings(line);
      return false;
    }
    reject_unknown_setting(line);
    if (find_equals(line) != std::string::npos) return add_productions(line);
    if (indented && after_production) {
      productions_.back().rhs.push_back(line);
      return true;
    }
    reject_missing_separator(line);
    if (!axiom_ && !has_axiom_setting_ && productions_.empty()) {
      axiom_ = line;
      return false;
    }
    fail(line.begin,
         "missing arrow: a production needs '\u2192' or '->' between "
         "predecessor and successor");
  }

  void directive(Range line) {
    std::size_t i = line.begin + 1;
    while (i < line.end && std::isalpha(static_cast<unsigned char>(text_[i]))) {
      ++i;
    }
    const std::string_view word =
        text_.substr(line.begin + 1, i - line.begin - 1);
    const Range rest = trim(Range{i, line.end});
    if (word == "define") {
      std::size_t j = rest.begin;
      while (j < rest.end && is_word_char(text_[j])) ++j;
      const Range name{rest.begin, j};
      if (name.empty() || !is_identifier(view(name))) {
        fail(rest.begin, "expected a name after #define");
      }
      const Range value = trim(Range{j, rest.end});
      if (value.empty()) fail(j, "expected a value after the name");
      defines_.emplace_back(name, value);
      return;
    }
    if (word == "ignore" || word == "consider") {
      Range value = rest;
      if (!value.empty() && text_[value.begin] == ':') {
        value = trim(Range{value.begin + 1, value.end});
      }
      settings_.push_back(
          SettingText{word == "ignore" ? Key::Ignore : Key::Consider,
                      {},
                      Range{line.begin, i},
                      value});
      return;
    }
    if (word == "include") fail(line.begin, "#include is not supported");
    fail(line.begin, "unknown directive '#" + std::string(word) + "'");
  }

  struct DeclaredName {
    Range name;
    int parameter_count = 0;  // of `bud(x)`; 0 without a list
  };

  // The names of a `module` line: `plant, internode seg, bud(x)`.
  std::vector<DeclaredName> module_names(Range names) const {
    std::vector<DeclaredName> out;
    std::size_t i = names.begin;
    while (i < names.end) {
      while (i < names.end && (is_blank(text_[i]) || text_[i] == ',')) ++i;
      if (i >= names.end) break;
      std::size_t j = i;
      while (j < names.end && !is_blank(text_[j]) && text_[j] != ',' &&
             text_[j] != '(') {
        ++j;
      }
      DeclaredName declared{Range{i, j}};
      while (j < names.end && is_blank(text_[j])) ++j;
      if (j < names.end && text_[j] == '(') {
        const std::size_t close = find_in(Range{j, names.end}, ")");
        if (close == std::string::npos) {
          fail(j, "unclosed '('");
        }
        const Range inside = trim(Range{j + 1, close});
        if (!inside.empty()) {
          declared.parameter_count =
              static_cast<int>(split_top(inside, ',').size());
        }
        j = close + 1;
      }
      out.push_back(declared);
      i = j;
    }
    return out;
  }

  // --- Pass 2 -------------------------------------------------------------

  // True when a line starts with an ABOP label such as `p1:` or `p_2 :`
  // (while sorting lines, before names and constants are known).
  bool has_abop_label(Range line) const {
    std::size_t i = line.begin;
    if (i >= line.end || lower(text_[i]) != 'p') return false;
    ++i;
    if (i < line.end && text_[i] == '_') ++i;
    const std::size_t digits = i;
    while (i < line.end && std::isdigit(static_cast<unsigned char>(text_[i]))) {
      ++i;
    }
    if (i == digits) return false;
    while (i < line.end && is_blank(text_[i])) ++i;
    return i < line.end && text_[i] == ':';
  }

  bool is_label_word(Range r) const {
    const std::string_view word = view(r);
    return !word.empty() && std::all_of(word.begin(), word.end(), is_word_char);
  }

  // True if `r` compiles as an expression of numbers and constants only.
  bool is_constant_condition(Range r) const {
    try {
      (void)parse_expression(source_, r.begin, r.end,
                             ExpressionScope{.constants = &grammar_.constants});
      return true;
    } catch (const ParseError&) {
      return false;
    }
  }

  // Strips a label, `name:` before the production: `p1:`, `P1:`, `r:`.
  // With two colons the first ends a label (`p1: A(x) : x>1 → …`); with
  // one, a word before it is a label unless it could be a predecessor
  // whose condition follows: `A : * → B` has the condition "always", and
  // `r : t > 1 → B` is refused as ambiguous when `t > 1` is a condition
  // over constants. A word of several characters that no `module` line
  // declares cannot be one predecessor, so it is always a label.
  Range strip_label(Range lhs) const {
    lhs = trim(lhs);
    const std::size_t colon = find_top(lhs, ":");
    if (colon == std::string::npos) return lhs;
    const Range label = trim(Range{lhs.begin, colon});
    const Range rest = trim(Range{colon + 1, lhs.end});
    if (!is_label_word(label)) return lhs;
    if (find_top(rest, ":") != std::string::npos) return rest;
    if (view(rest) == "*" || rest.empty()) return lhs;
    const std::string word(view(label));
    const bool may_be_predecessor = code_point_length(word) == word.size() ||
                                    declared_modules_.count(word) != 0;
    if (may_be_predecessor && is_constant_condition(rest)) {
      fail(label.begin,
           "ambiguous ':': '" + word +
               "' may be a label or a predecessor with the condition '" +
               std::string(view(rest)) +
               "'; write 'p1: " + std::string(view(rest)) +
               " \u2192 \u2026' for a label, 'p1: " + word + " : " +
               std::string(view(rest)) + " \u2192 \u2026' for a condition");
    }
    return rest;
  }

  struct Lhs {
    Range left;
    Range predecessor;
    Range right;
    std::optional<Range> condition;
  };

  Lhs split_lhs(Range lhs_with_label) const {
    const Range lhs = strip_label(lhs_with_label);
    Lhs out;
    Range pattern = lhs;
    if (const std::size_t colon = find_top(lhs, ":");
        colon != std::string::npos) {
      pattern = trim(Range{lhs.begin, colon});
      out.condition = trim(Range{colon + 1, lhs.end});
      if (out.condition->empty()) fail(colon, "expected a condition after ':'");
      if (view(*out.condition) == "*") out.condition.reset();
    }
    out.predecessor = pattern;
    if (const std::size_t lt = find_top(pattern, "<");
        lt != std::string::npos) {
      out.left = trim(Range{pattern.begin, lt});
      if (out.left.empty()) fail(lt, "expected a left context before '<'");
      out.predecessor = trim(Range{lt + 1, pattern.end});
    }
    if (const std::size_t gt = find_top(out.predecessor, ">");
        gt != std::string::npos) {
      out.right = trim(Range{gt + 1, out.predecessor.end});
      if (out.right.empty()) fail(gt, "expected a right context after '>'");
      out.predecessor = trim(Range{out.predecessor.begin, gt});
    }
    if (out.predecessor.empty()) {
      fail(lhs.begin, "missing predecessor before the arrow");
    }
    // cpfg's grammar maps a context that is only `*` to no context at all
    // (`* < A > * --> AF` rewrites every A); a `*` among other modules is
    // ABOP's wildcard, one module of any name.
    if (view(out.left) == "*") out.left = Range{};
    if (view(out.right) == "*") out.right = Range{};
    return out;
  }

  // The module name of a predecessor, before any parameter list.
  void declare_names() {
    for (const Range& names : module_lines_) {
      for (const DeclaredName& declared : module_names(names)) {
        grammar_.alphabet.intern(view(declared.name));
      }
    }
    for (const ProductionText& p : productions_) {
      const Lhs lhs = split_lhs(p.lhs);
      std::size_t end = find_in(lhs.predecessor, "(");
      if (end == std::string::npos) end = lhs.predecessor.end;
      const Range name = trim(Range{lhs.predecessor.begin, end});
      if (name.empty()) fail(lhs.predecessor.begin, "missing predecessor");
      for (std::size_t i = name.begin; i < name.end; ++i) {
        if (is_blank(text_[i])) {
          fail(lhs.predecessor.begin,
               "the predecessor must be a single module");
        }
      }
      grammar_.alphabet.intern(view(name));
    }
  }

  void evaluate_defines() {
    std::unordered_set<std::string> given;
    for (const std::string& define : options_.defines) {
      auto source = std::make_shared<const SourceFile>("--define", define);
      check_text(*source);
      const std::size_t equals = define.find('=');
      const std::string name =
          define.substr(0, std::min(equals, define.size()));
      if (equals == std::string::npos || !is_identifier(name)) {
        throw error_at(*source, 0, "expected NAME=VALUE");
      }
      const Expression value =
          parse_expression(source, equals + 1, define.size(),
                           ExpressionScope{.constants = &grammar_.constants,
                                           .used_constants = &used_constants_});
      grammar_.constants[name] = value.constant_value();
      given.insert(name);
      given_defines_.push_back(name);
    }
    std::unordered_map<std::string, std::size_t> seen;
    for (const auto& [name_range, value] : defines_) {
      const std::string name(view(name_range));
      if (const auto it = seen.find(name); it != seen.end()) {
        fail(name_range.begin,
             "duplicate definition of '" + name + "' (first defined on line " +
                 std::to_string(source_->location(it->second).line) + ")");
      }
      seen.emplace(name, name_range.begin);
      file_defines_.insert(name);
      if (given.count(name) != 0) continue;  // --define wins
      grammar_.constants[name] = constant(value);
    }
  }

  double constant(Range r) const {
    return parse_expression(source_, r.begin, r.end,
                            ExpressionScope{.constants = &grammar_.constants,
                                            .used_constants = &used_constants_})
        .constant_value();
  }

  void read_aliases() {
    for (const Range& line : alias_lines_) {
      std::size_t i = line.begin;
      while (i < line.end) {
        while (i < line.end && is_blank(text_[i])) ++i;
        if (i >= line.end) break;
        const std::size_t from_begin = i;
        while (i < line.end && !is_blank(text_[i]) && text_[i] != '=' &&
               text_.substr(i, 3) != "\u2192" && text_.substr(i, 2) != "->") {
          ++i;
        }
        const Range from{from_begin, i};
        while (i < line.end && is_blank(text_[i])) ++i;
        if (text_.substr(i, 1) == "=") {
          i += 1;
        } else if (text_.substr(i, 2) == "->") {
          i += 2;
        } else if (text_.substr(i, 3) == "\u2192") {
          i += 3;
        } else {
          fail(i, "expected '=' in an alias such as 'f=F'");
        }
        if (from.empty()) fail(from_begin, "expected a module before '='");
        while (i < line.end && is_blank(text_[i])) ++i;
        const std::size_t to_begin = i;
        while (i < line.end && !is_blank(text_[i])) ++i;
        std::string_view to = text_.substr(to_begin, i - to_begin);
        if (!builtin_command(to) && to.size() > 1 && to.back() == ',') {
          to.remove_suffix(1);
        }
        const auto command = builtin_command(to);
        if (to.empty()) fail(to_begin, "expected a turtle symbol after '='");
        if (!command) {
          fail(to_begin, "unknown turtle symbol '" + std::string(to) + "'");
        }
        if (*command == TurtleCommand::Push || *command == TurtleCommand::Pop ||
            *command == TurtleCommand::Cut) {
          fail(to_begin, "'" + std::string(to) + "' cannot be an alias target");
        }
        const SymbolId symbol = grammar_.alphabet.intern(view(from));
        if (symbol <= kCut) {
          fail(from_begin,
               "'" + std::string(view(from)) + "' cannot be aliased");
        }
        if (aliases_.count(symbol) != 0) {
          fail(from_begin,
               "duplicate alias for '" + std::string(view(from)) + "'");
        }
        aliases_.emplace(symbol, *command);
      }
    }
  }

  // `module bud(x)` fixes bud's parameter count; `module leaf` only
  // declares the name.
  void read_module_declarations() {
    for (const Range& names : module_lines_) {
      for (const DeclaredName& declared : module_names(names)) {
        if (declared.parameter_count == 0) continue;
        check_arity(*grammar_.alphabet.find(view(declared.name)),
                    declared.parameter_count, declared.name.begin);
      }
    }
  }

  TurtleCommand command_of(SymbolId symbol) const {
    if (const auto it = aliases_.find(symbol); it != aliases_.end()) {
      return it->second;
    }
    return builtin_command(grammar_.alphabet.name(symbol))
        .value_or(TurtleCommand::None);
  }

  void check_arity(SymbolId symbol, int count, std::size_t offset) {
    const std::string& name = grammar_.alphabet.name(symbol);
    const TurtleCommand command = command_of(symbol);
    if (command != TurtleCommand::None) {
      const int most = max_parameters(command);
      const int least = min_parameters(command);
      if (count > most || count < least) {
        std::string expected =
            least == most
                ? std::to_string(most)
                : (least == 0
                       ? "at most " + std::to_string(most)
                       : std::to_string(least) + " to " + std::to_string(most));
        fail(offset, "wrong parameter count: '" + name + "' takes " + expected +
                         (most == 1 ? " parameter" : " parameters") +
                         ", here " + std::to_string(count));
      }
      return;
    }
    const auto [it, inserted] =
        arity_.emplace(symbol, std::pair{count, offset});
    if (inserted || it->second.first == count) return;
    const int expected = it->second.first;
    fail(offset, "wrong parameter count: '" + name + "' takes " +
                     std::to_string(expected) +
                     (expected == 1 ? " parameter" : " parameters") +
                     " (as on line " +
                     std::to_string(source_->location(it->second.second).line) +
                     "), here " + std::to_string(count));
  }

  struct RawModule {
    SymbolId symbol;
    std::size_t offset;
    std::vector<Range> arguments;
  };

  // Calls `each` with every module of r in turn, so that a long axiom is
  // never held as tokens besides its successor.
  template <typename Each>
  void tokenize_each(Range r, const Each& each) {
    std::size_t i = r.begin;
    for (;;) {
      while (i < r.end && is_blank(text_[i])) ++i;
      if (i >= r.end) break;
      if (text_[i] == '(' || text_[i] == ')') {
        fail(i, std::string("unexpected '") + text_[i] +
                    "': parameters follow a module name, as in F(1)");
      }
      const std::size_t length =
          grammar_.alphabet.match_length(text_.substr(i, r.end - i));
      RawModule m{grammar_.alphabet.intern(text_.substr(i, length)), i, {}};
      i += length;
      std::size_t j = i;
      while (j < r.end && is_blank(text_[j])) ++j;
      if (j < r.end && text_[j] == '(') {
        int depth = 0;
        std::size_t close = j;
        for (; close < r.end; ++close) {
          if (text_[close] == '(') ++depth;
          if (text_[close] == ')' && --depth == 0) break;
        }
        if (close >= r.end) fail(j, "unclosed '('");
        for (const Range& arg : split_top(Range{j + 1, close}, ',')) {
          if (trim(arg).empty()) fail(arg.begin, "expected an expression");
          m.arguments.push_back(arg);
        }
        i = close + 1;
      }
      each(std::move(m));
    }
  }

  std::vector<RawModule> tokenize(Range r) {
    std::vector<RawModule> out;
    tokenize_each(r, [&](RawModule&& m) { out.push_back(std::move(m)); });
    return out;
  }

  // Brackets must balance; `symbol_at(i)` and `offset_at(i)` give module i.
  template <typename SymbolAt, typename OffsetAt>
  void check_brackets(std::size_t count, const SymbolAt& symbol_at,
                      const OffsetAt& offset_at, bool allow_unclosed) const {
    std::vector<std::size_t> open;
    for (std::size_t i = 0; i < count; ++i) {
      if (symbol_at(i) == kBranchOpen) open.push_back(offset_at(i));
      if (symbol_at(i) == kBranchClose) {
        if (open.empty()) {
          fail(offset_at(i), "unbalanced ']': no '[' before it");
        }
        open.pop_back();
      }
    }
    if (!open.empty() && !allow_unclosed) {
      fail(open.back(), "unclosed '[': no ']' after it");
    }
  }

  Successor modules(const std::vector<Range>& ranges,
                    const ExpressionScope& scope) {
    Successor out;
    // A module takes at least one byte: reserving that many is never too
    // little, and spares the copies of growing a long axiom.
    std::size_t bytes = 0;
    for (const Range& r : ranges) bytes += r.end - r.begin;
    out.reserve(bytes);
    for (const Range& r : ranges) {
      tokenize_each(r, [&](RawModule&& raw) {
        check_arity(raw.symbol, static_cast<int>(raw.arguments.size()),
                    raw.offset);
        std::vector<Expression> parameters;
        for (const Range& arg : raw.arguments) {
          parameters.push_back(
              parse_expression(source_, arg.begin, arg.end, scope));
        }
        out.push_back(raw.symbol, std::move(parameters), raw.offset);
      });
    }
    out.shrink_to_fit();
    check_brackets(
        out.size(), [&](std::size_t i) { return out.symbols()[i]; },
        [&](std::size_t i) { return out.offset(i); }, false);
    return out;
  }

  std::vector<PatternModule> pattern(Range r, std::vector<std::string>& slots,
                                     bool allow_brackets,
                                     const char* bracket_error) {
    std::vector<PatternModule> out;
    for (const RawModule& raw : tokenize(r)) {
      const bool bracket =
          raw.symbol == kBranchOpen || raw.symbol == kBranchClose;
      if (bracket && !allow_brackets) {
        fail(raw.offset, bracket_error);
      }
      if (raw.symbol == kAnyModule && !raw.arguments.empty()) {
        fail(raw.offset,
             "'*' in a context matches any module and takes no parameters");
      }
      if (raw.symbol != kAnyModule) {
        check_arity(raw.symbol, static_cast<int>(raw.arguments.size()),
                    raw.offset);
      }
      for (const Range& arg : raw.arguments) {
        const Range name = trim(arg);
        const std::string formal(view(name));
        if (!is_identifier(formal)) {
          fail(name.begin,
               "a parameter of a predecessor or context must be "
               "a name, not '" +
                   formal + "'");
        }
        if (std::find(slots.begin(), slots.end(), formal) != slots.end()) {
          fail(name.begin,
               "duplicate definition of parameter '" + formal + "'");
        }
        slots.push_back(formal);
      }
      out.push_back(PatternModule{
          raw.symbol, static_cast<int>(raw.arguments.size()), raw.offset});
    }
    check_brackets(
        out.size(), [&](std::size_t i) { return out[i].symbol; },
        [&](std::size_t i) { return out[i].offset; }, true);
    return out;
  }

  void read_production(const ProductionText& text) {
    const Lhs lhs = split_lhs(text.lhs);
    Production p;
    std::vector<std::string> slots;
    if (!lhs.left.empty()) {
      p.left_context = pattern(lhs.left, slots, false,
                               "a left context cannot contain brackets");
    }
    const std::vector<PatternModule> predecessor =
        pattern(lhs.predecessor, slots, false, "brackets cannot be rewritten");
    if (predecessor.size() != 1) {
      fail(lhs.predecessor.begin, "the predecessor must be a single module");
    }
    p.predecessor = predecessor.front();
    p.offset = p.predecessor.offset;
    if (!lhs.right.empty()) {
      p.right_context = pattern(lhs.right, slots, true, "");
    }
    const ExpressionScope scope{.parameters = slots,
                                .constants = &grammar_.constants,
                                .used_constants = &used_constants_};
    if (lhs.condition) {
      p.condition = parse_expression(source_, lhs.condition->begin,
                                     lhs.condition->end, scope);
    }
    std::vector<Range> rhs = text.rhs;
    if (text.probability) {
      p.probability = parse_expression(source_, text.probability->begin,
                                       text.probability->end, scope);
    }
    // cpfg appends the probability: `F --> F[+F]F : 0.33`.
    if (const std::size_t colon = find_top(rhs.back(), ":");
        colon != std::string::npos) {
      if (p.probability)
        fail(colon, "this production already has a probability");
      const Range probability = trim(Range{colon + 1, rhs.back().end});
      if (probability.empty()) fail(colon, "expected a probability after ':'");
      p.probability =
          parse_expression(source_, probability.begin, probability.end, scope);
      rhs.back().end = colon;
    }
    if (p.probability && p.probability->is_constant() &&
        p.probability->constant_value() < 0.0) {
      fail(p.probability->offset(), "a probability cannot be negative");
    }
    std::string joined;
    for (const Range& r : rhs) joined += view(trim(r));
    if (joined == "*" || joined == "\u03B5") rhs.clear();
    p.successor = modules(rhs, scope);
    if (text.section != Section::Productions) {
      const char* what = text.section == Section::Decomposition
                             ? "decomposition"
                             : "homomorphism";
      if (p.is_context_sensitive()) {
        fail(p.offset,
             std::string("a ") + what + " rule cannot have a context");
      }
      if (p.probability) {
        fail(p.probability->offset(),
             std::string("a ") + what + " rule cannot be stochastic");
      }
    }
    switch (text.section) {
      case Section::Decomposition:
        grammar_.decompositions.push_back(std::move(p));
        break;
      case Section::Homomorphism:
        grammar_.homomorphisms.push_back(std::move(p));
        break;
      default:
        grammar_.productions.push_back(std::move(p));
    }
  }

  void read_axiom() {
    if (!axiom_) {
      fail(productions_.empty() ? 0 : trim(productions_.front().lhs).begin,
           "no axiom: give one as 'axiom: F', '\u03C9: F' or a line of "
           "modules before the productions");
    }
    const ExpressionScope scope{.constants = &grammar_.constants,
                                .used_constants = &used_constants_};
    grammar_.axiom = modules({*axiom_}, scope);
    grammar_.axiom_offset = axiom_->begin;
  }

  double number(Range value) const { return constant(value); }

  double positive(Range value, bool allow_zero) const {
    const double v = number(value);
    if (v < 0.0 || (!allow_zero && v == 0.0)) {
      fail(value.begin, std::string("expected a ") +
                            (allow_zero ? "non-negative" : "positive") +
                            " number");
    }
    return v;
  }

  std::int64_t whole(Range value, double most) const {
    const double v = number(value);
    if (v < 0.0 || v != std::floor(v) || v > most) {
      fail(value.begin, "expected a whole number from 0 to " +
                            std::to_string(static_cast<std::int64_t>(most)));
    }
    return static_cast<std::int64_t>(v);
  }

  std::vector<SymbolId> symbol_list(Range value) {
    std::vector<SymbolId> out;
    for (const RawModule& m : tokenize(value)) {
      if (!m.arguments.empty()) fail(m.offset, "expected module names only");
      out.push_back(m.symbol);
    }
    return out;
  }

  void read_settings() {
    std::unordered_map<int, std::size_t> seen;
    Settings& s = grammar_.settings;
    bool has_increment = false;
    bool has_factor = false;
    for (const SettingText& setting : settings_) {
      const std::string key_text(view(setting.key_range));
      if (setting.key == Key::Extra) {
        grammar_.extra_settings.push_back(
            ExtraSetting{setting.extra_key, std::string(view(setting.value)),
                         setting.value.begin});
        continue;
      }
      std::size_t separator = setting.key_range.end;
      while (is_blank(text_[separator])) ++separator;
      if (text_[separator] == '=' && setting.key != Key::Axiom &&
          code_point_length(key_text) == key_text.size()) {
        letter_settings_.push_back(setting);
      }
      const int id = static_cast<int>(setting.key);
      if (const auto it = seen.find(id); it != seen.end()) {
        fail(setting.key_range.begin,
             "duplicate setting '" + key_text + "' (first set on line " +
                 std::to_string(source_->location(it->second).line) + ")");
      }
      seen.emplace(id, setting.key_range.begin);
      if (setting.value.empty() && setting.key != Key::Ignore &&
          setting.key != Key::Consider) {
        fail(setting.key_range.begin,
             "expected a value for '" + key_text + "'");
      }
      const Range v = setting.value;
      switch (setting.key) {
        case Key::Axiom:
          if (axiom_) {
            fail(setting.key_range.begin,
                 "duplicate axiom (the first is on line " +
                     std::to_string(source_->location(axiom_->begin).line) +
                     ")");
          }
          axiom_ = v;
          break;
        case Key::DerivationLength:
          s.derivation_length = static_cast<int>(whole(v, 10000));
          s.derivation_length_offset = setting.key_range.begin;
          break;
        case Key::Angle:
          s.angle_deg = number(v);
          break;
        case Key::AngleFactor:
          s.angle_deg = 360.0 / positive(v, false);
          break;
        case Key::Step:
          s.step = number(v);
          s.step_offset = v.begin;
          break;
        case Key::Width:
          s.initial_width = positive(v, true);
          break;
        case Key::Radius:
          s.initial_width = 2.0 * positive(v, true);
          break;
        case Key::WidthIncrement:
          s.width_increment = number(v);
          has_increment = true;
          break;
        case Key::WidthFactor:
          s.width_factor = positive(v, true);
          has_factor = true;
          break;
        case Key::WidthScale:
          s.width_scale = positive(v, false);
          break;
        case Key::WidthPerGeneration:
          s.width_decrement_per_generation = number(v);
          break;
        case Key::RadiusPerGeneration:
          s.width_decrement_per_generation = 2.0 * number(v);
          break;
        case Key::Color:
          s.initial_color = static_cast<int>(whole(v, kMaxColorIndex));
          break;
        case Key::Tropism:
          s.tropism = vector3(v);
          break;
        case Key::Elasticity:
          s.elasticity = number(v);
          break;
        case Key::Seed:
          s.seed = static_cast<std::uint64_t>(whole(v, 9007199254740992.0));
          break;
        case Key::Roll: {
          std::string word;
          for (char c : view(v)) word += lower(c);
          if (word == "lpfg" || word == "lpy" || word == "l-py") {
            s.roll = RollConvention::Lpfg;
          } else if (word == "cpfg") {
            s.roll = RollConvention::Cpfg;
          } else {
            fail(v.begin, "expected 'lpfg' or 'cpfg'");
          }
          break;
        }
        case Key::MaximumDepth:
          s.maximum_depth = static_cast<int>(whole(v, 1000));
          break;
        case Key::Ignore:
          s.ignore = symbol_list(v);
          break;
        case Key::Consider:
          s.consider = symbol_list(v);
          break;
        case Key::LsystemLabel:
        case Key::Extra:
          break;
      }
      const auto both = [&](Key a, Key b, const char* what) {
        if (seen.count(static_cast<int>(a)) != 0 &&
            seen.count(static_cast<int>(b)) != 0) {
          fail(setting.key_range.begin, what);
        }
      };
      both(Key::Angle, Key::AngleFactor,
           "give either 'angle' or 'angle factor', not both");
      both(Key::Width, Key::Radius,
           "give either 'width' or 'radius', not both");
      both(Key::WidthPerGeneration, Key::RadiusPerGeneration,
           "give either 'width decrement per generation' or 'radius "
           "reduction per generation', not both");
      if (has_increment && has_factor) {
        fail(setting.key_range.begin,
             "give either 'width increment' or 'width factor', not both");
      }
      if (!s.ignore.empty() && !s.consider.empty()) {
        fail(setting.key_range.begin,
             "give either 'ignore' or 'consider', not both");
      }
    }
  }

  // `N=2` where the file also has a module N reads both as the setting n
  // and as Fractint's production N → 2.
  void reject_letter_settings_of_modules() const {
    for (const SettingText& setting : letter_settings_) {
      const std::string letter(view(setting.key_range));
      if (!grammar_.alphabet.find(letter)) continue;
      const std::string value(view(setting.value));
      fail(setting.key_range.begin,
           "ambiguous '" + letter + "=" + value + "': it may set '" + letter +
               "' or rewrite the module '" + letter +
               "' that this file uses; write '" + letter + ": " + value +
               "' for the setting, '" + letter + " \u2192 " + value +
               "' for a production");
    }
  }

  glm::dvec3 vector3(Range value) const {
    Range r = value;
    if (view(r).starts_with("(") && view(r).ends_with(")")) {
      r = trim(Range{r.begin + 1, r.end - 1});
    }
    std::vector<Range> parts = split_top(r, ',');
    if (parts.size() == 1) {
      parts.clear();
      std::size_t i = r.begin;
      while (i < r.end) {
        while (i < r.end && is_blank(text_[i])) ++i;
        const std::size_t start = i;
        while (i < r.end && !is_blank(text_[i])) ++i;
        if (i > start) parts.push_back(Range{start, i});
      }
    }
    if (parts.size() != 3) fail(value.begin, "expected three numbers x, y, z");
    return {number(trim(parts[0])), number(trim(parts[1])),
            number(trim(parts[2]))};
  }

  void build_commands() {
    grammar_.commands.resize(grammar_.alphabet.size());
    for (SymbolId s = 0; s < grammar_.alphabet.size(); ++s) {
      grammar_.commands[s] = command_of(s);
    }
  }

  std::shared_ptr<const SourceFile> source_;
  const ParseOptions& options_;
  std::string clean_;
  std::string_view text_;
  Grammar grammar_;

  Section section_ = Section::Productions;
  std::vector<ProductionText> productions_;
  std::vector<SettingText> settings_;
  std::vector<SettingText> letter_settings_;  // `n=2`: one letter and `=`
  std::vector<std::pair<Range, Range>> defines_;
  std::vector<Range> module_lines_;
  std::vector<Range> alias_lines_;
  std::optional<Range> axiom_;
  bool has_axiom_setting_ = false;
  std::unordered_set<std::string> declared_modules_;
  std::unordered_map<SymbolId, TurtleCommand> aliases_;
  std::unordered_map<SymbolId, std::pair<int, std::size_t>> arity_;
  mutable std::set<std::string> used_constants_;  // filled while compiling
  std::vector<std::string> given_defines_;
  std::set<std::string> file_defines_;
};

}  // namespace

Grammar parse_grammar(std::shared_ptr<const SourceFile> source,
                      const ParseOptions& options) {
  // Successors keep 32-bit source places; files are far smaller
  // (kMaxSourceBytes), texts given in memory must be too.
  if (source->text().size() > 0xFFFFFFFFU) {
    throw ParseError(Diagnostic{.file = source->name(),
                                .message = "the text is longer than 4 GiB"});
  }
  check_text(*source);
  return Parser(std::move(source), options).run();
}

Grammar parse_grammar_text(std::string_view text, const ParseOptions& options,
                           std::string name) {
  return parse_grammar(
      std::make_shared<const SourceFile>(std::move(name), std::string(text)),
      options);
}

}  // namespace lsys
