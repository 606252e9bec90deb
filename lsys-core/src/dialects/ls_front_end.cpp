// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// lsolid's own notation, `.ls`: the notations of ABOP's captions
// (Prusinkiewicz and Lindenmayer 1990), cpfg (`#define`, `derivation
// length:`, `-->`), L-Py's declarative part (`Axiom:`, `module`), Houdini
// (`premise:`) and the source documents of printables/, as
// docs/language.md describes. This pass sorts lines into settings,
// productions and the axiom; the grammar builder does the rest.
#include <algorithm>
#include <array>
#include <cctype>
#include <optional>
#include <string_view>
#include <utility>

#include "dialects/front_ends.hpp"
#include "dialects/grammar_builder.hpp"
#include "lsys/diagnostic.hpp"

namespace lsys::dialects {
namespace {

struct Spelling {
  std::string_view text;
  Key key;
};

// Every spelling of every setting; longest first so that `width increment`
// wins over `width`. A space matches any run of blanks.
constexpr std::array<Spelling, 46> kSpellings = [] {
  std::array<Spelling, 46> s{{
      {"axiom", Key::Axiom},
      {"\u03C9", Key::Axiom},
      {"premise", Key::Axiom},
      {"initial value", Key::Axiom},
      {"start", Key::Axiom},  // Jon Leech's lsys (finish_lsys)
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

// Modules of cpfg (and Houdini's `~`) that lsolid cannot build: refused
// where they stand rather than split into letters (`@O` is not `@`, `O`).
const std::vector<RefusedName> kRefused = {
    {"@o", "a disc"},
    {"@c", "a disc"},
    {"@M", "a move to a point"},
    {"@R", "setting the heading"},
    {"@L", "a label"},
    {"~", "a predefined surface in cpfg, a random turn in Houdini"},
};

// Replaces comments by blanks, keeping line breaks and byte offsets:
// `/* ... */` anywhere, and, when `hash_comments`, from a `#` that stands
// alone as a word (a blank or the line's start before it, a blank or the
// line's end after it) to the end of the line (`axiom: F   # three`), as
// L-Py and shells write them. A `#` that touches a module is cpfg's widen
// (`F#F`, `#(2)`), and one followed by a letter starts a directive.
std::string blank_comments(const SourceFile& source, bool hash_comments) {
  std::string out = source.text();
  const auto is_space = [](char c) {
    return c == ' ' || c == '\t' || c == '\n' || c == '\r';
  };
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (hash_comments && out[i] == '#' && (i == 0 || is_space(out[i - 1])) &&
        (i + 1 == out.size() || is_space(out[i + 1]))) {
      for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
      continue;
    }
    if (out[i] != '/' || i + 1 == out.size() || out[i + 1] != '*') continue;
    i = blank_block_comment(source, out, i);
  }
  return out;
}

class LsReader : TextScan {
 public:
  LsReader(std::shared_ptr<const SourceFile> source,
           const ParseOptions& options, Draft notation, LsVariant variant)
      : TextScan(source, blank_comments(*source, variant == LsVariant::Ls)),
        options_(options),
        draft_(std::move(notation)),
        variant_(variant) {}

  Grammar run() {
    sort_lines();
    if (variant_ == LsVariant::Lowclouds) finish_lowclouds();
    if (variant_ == LsVariant::Ls) finish_lsys();
    return build_grammar(*this, std::move(draft_), options_);
  }

 private:
  // Matches a setting spelling at the start of r, followed by `:` or `=`.
  // Returns the end of the key and the start of the value.
  struct KeyMatch {
    Key key;
    std::string extra;
    std::size_t key_end;
    std::size_t value_begin;
  };

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

  // Jon Leech's lsys (1989), which many ABOP transcriptions were written
  // for, gives the axiom as `START : F` and reads two macros as settings:
  // `#define maxgen 5` the derivation length and `#define delta 25.7` the
  // angle in degrees (its README). A file with a `START` axiom takes them
  // so unless it sets them itself; the macros stay constants too.
  void finish_lsys() {
    const auto axiom =
        std::find_if(draft_.settings.begin(), draft_.settings.end(),
                     [&](const SettingText& t) {
                       if (t.key != Key::Axiom) return false;
                       std::string key;
                       for (char c : view(t.key_range)) key += lower(c);
                       return trim_blanks(key) == "start";
                     });
    if (axiom == draft_.settings.end()) return;
    const auto has = [&](Key key) {
      return std::any_of(draft_.settings.begin(), draft_.settings.end(),
                         [&](const SettingText& t) { return t.key == key; });
    };
    const bool has_length = has(Key::DerivationLength);
    const bool has_angle = has(Key::Angle) || has(Key::AngleFactor);
    for (const auto& [name, value] : draft_.defines) {
      if (view(name) == "maxgen" && !has_length) {
        draft_.settings.push_back(
            SettingText{Key::DerivationLength, {}, name, value});
      } else if (view(name) == "delta" && !has_angle) {
        draft_.settings.push_back(SettingText{Key::Angle, {}, name, value});
      }
    }
  }

  static std::string_view trim_blanks(std::string_view s) {
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
      s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t'))
      s.remove_suffix(1);
    return s;
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
      draft_.settings.push_back(SettingText{match->key, match->extra,
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
      draft_.productions.push_back(
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
          draft_.declared_modules.count(std::string(name)) == 0 &&
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
          std::any_of(draft_.defines.begin(), draft_.defines.end(),
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
          draft_.declared_modules.count(name) != 0) {
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
        std::string message = "unknown setting '";
        message += name;
        message += "'";
        // A vlab object's control panel sits beside its L-system and
        // shares its `.l` ending (vlab's panel manual).
        if (name == "panel name" || name == "target") {
          message +=
              ": this is a vlab control panel, not an L-system; give the "
              "object's L-system file";
        }
        fail(word.begin, std::move(message));
      }
      return;
    }
    if (text_[i] != '=' || code_point_length(name) == name.size() ||
        draft_.declared_modules.count(std::string(name)) != 0) {
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
          after_axiom_ = false;
        }
        continue;
      }
      continues_axiom_ = indented && after_axiom_;
      after_axiom_ = false;
      after_production = sort_line(line, indented, after_production);
    }
  }

  // Returns true if the line was (part of) a production.
  bool sort_line(Range line, bool indented, bool after_production) {
    if (variant_ == LsVariant::Lowclouds && lowclouds_line(line)) return false;
    if (variant_ != LsVariant::Ls) {
      refuse_cpfg_only(line);
      if (cpfg_block(line)) return false;
    }
    if (match_words(line.begin, line.end, "endlsystem") == line.end ||
        match_words(line.begin, line.end, "warnings") == line.end ||
        match_words(line.begin, line.end, "no warnings") == line.end) {
      return false;
    }
    // A header alone starts a section; with content after its colon it
    // applies to that line only (`aliases: f=F`, `Production rules : A=fA`).
    Section section = section_;
    if (const auto header = match_header(line)) {
      // cpfg's `homomorphism: warnings` asks for messages about depth.
      if (header->second.empty() ||
          match_words(header->second.begin, header->second.end, "warnings") ==
              header->second.end ||
          match_words(header->second.begin, header->second.end,
                      "no warnings") == header->second.end) {
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
        draft_.alias_lines.push_back(line);
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
        draft_.module_lines.push_back(names);
        for (const DeclaredName& declared : module_names(*this, names)) {
          draft_.declared_modules.insert(std::string(view(declared.name)));
        }
        return false;
      }
    }
    if (const auto key = match_key(line);
        key && !is_one_letter_production(line, *key)) {
      has_axiom_setting_ = has_axiom_setting_ || key->key == Key::Axiom;
      after_axiom_ = key->key == Key::Axiom;
      add_settings(line);
      return false;
    }
    reject_unknown_setting(line);
    if (find_equals(line) != std::string::npos) return add_productions(line);
    if (indented && after_production) {
      draft_.productions.back().rhs.push_back(line);
      return true;
    }
    // A long axiom may go on over indented lines, as a successor does.
    if (continues_axiom_) {
      draft_.axiom_more.push_back(line);
      after_axiom_ = true;
      return false;
    }
    reject_missing_separator(line);
    if (!draft_.axiom && !has_axiom_setting_ && draft_.productions.empty()) {
      draft_.axiom = line;
      after_axiom_ = true;
      return false;
    }
    fail(line.begin,
         "missing arrow: a production needs '\u2192' or '->' between "
         "predecessor and successor");
  }

  void directive(Range line) {
    const auto [word, rest] = directive_parts(line);
    if (word == "define") {
      draft_.defines.push_back(define_directive(rest));
      return;
    }
    if (word == "ignore" || word == "consider") {
      Range value = rest;
      if (!value.empty() && text_[value.begin] == ':') {
        value = trim(Range{value.begin + 1, value.end});
      }
      draft_.settings.push_back(
          SettingText{word == "ignore" ? Key::Ignore : Key::Consider,
                      {},
                      Range{line.begin, line.begin + 1 + word.size()},
                      value});
      return;
    }
    if (word == "include") {
      // lpfg's files include its header, often after C's own.
      if (text_.find("lpfgall.h") != std::string_view::npos) {
        fail(line.begin,
             "this is an lpfg file, whose rules are C++: read it with "
             "--dialect lpfg");
      }
      fail(line.begin, "#include is not supported");
    }
    fail(line.begin, "unknown directive '#" + std::string(word) + "'");
  }

  // cpfg's `Start: { … }` and its kin: kept for the grammar builder.
  bool cpfg_block(Range line) {
    static constexpr std::array<std::pair<std::string_view, BlockKind>, 7>
        kBlocks{{
            {"define", BlockKind::Define},
            {"start each", BlockKind::StartEach},
            {"starteach", BlockKind::StartEach},
            {"start", BlockKind::Start},
            {"end each", BlockKind::EndEach},
            {"endeach", BlockKind::EndEach},
            {"end", BlockKind::End},
        }};
    for (const auto& [word, kind] : kBlocks) {
      const auto end = match_words(line.begin, line.end, word);
      if (!end) continue;
      std::size_t pos = *end;
      while (pos < line.end && is_blank(text_[pos])) ++pos;
      if (pos >= line.end || text_[pos] != ':') continue;
      const Range block = trim(Range{pos + 1, line.end});
      if (block.empty() || text_[block.begin] != '{') {
        fail(pos + 1, "expected '{' and statements after ':'");
      }
      draft_.blocks.push_back(StatementBlock{kind, block});
      return true;
    }
    return false;
  }

  // What cpfg files hold that lsolid does not run yet: refused at their
  // place, by name, rather than misread as settings or productions.
  void refuse_cpfg_only(Range line) const {
    if (match_words(line.begin, line.end, "ring lsystem") == line.end) {
      fail(line.begin,
           "a ring L-system (contexts that wrap around the string) is not "
           "supported");
    }
  }

  // L-system Explorer (its lsystem.js): before the axiom, `name = value`
  // lines set variables, several to a line separated by `;`, and
  // `stemsize: 0.2`, `dlength: 13` settings of its own; one `lsystem:`
  // label. True if the line was one of these.
  bool lowclouds_line(Range line) {
    if (const auto end = match_words(line.begin, line.end, "lsystem")) {
      std::size_t pos = *end;
      while (pos < line.end && is_blank(text_[pos])) ++pos;
      if (pos < line.end && text_[pos] == ':') {
        if (seen_lsystem_label_) {
          fail(line.begin,
               "a second 'lsystem:': sub-L-systems are not supported");
        }
        seen_lsystem_label_ = true;
        return true;
      }
    }
    const bool before_axiom = !draft_.axiom && !has_axiom_setting_;
    for (const auto& [word, key] :
         {std::pair{std::string_view("stemsize"), Key::Width},
          std::pair{std::string_view("dlength"), Key::DerivationLength},
          std::pair{std::string_view("length"), Key::DerivationLength}}) {
      const auto end = match_words(line.begin, line.end, word);
      if (!end) continue;
      std::size_t pos = *end;
      while (pos < line.end && is_blank(text_[pos])) ++pos;
      if (pos >= line.end || text_[pos] != ':') continue;
      draft_.settings.push_back(SettingText{
          key, {}, Range{line.begin, *end}, trim(Range{pos + 1, line.end})});
      return true;
    }
    std::size_t i = line.begin;
    while (i < line.end && is_word_char(text_[i])) ++i;
    std::size_t equals = i;
    while (equals < line.end && is_blank(text_[equals])) ++equals;
    const bool assignment = i > line.begin && equals < line.end &&
                            text_[equals] == '=' &&
                            text_.substr(equals, 2) != "==";
    if (!assignment || find_arrow(line, false)) return false;
    if (!before_axiom) {
      fail(line.begin,
           "a variable set after the axiom (L-system Explorer ignores it); "
           "set it before 'axiom:'");
    }
    for (const Range& piece : lowclouds_assignments(line)) {
      lowclouds_assignment(piece);
    }
    return true;
  }

  // `n=1; delta=22.5; stemsize=0.1`, and `n=6,delta=60` as makers write
  // it: cut at `;`, and at a `,` before another `name =`.
  std::vector<Range> lowclouds_assignments(Range line) const {
    std::vector<Range> pieces;
    int depth = 0;
    std::size_t start = line.begin;
    for (std::size_t i = line.begin; i < line.end; ++i) {
      const char c = text_[i];
      if (c == '(' || c == '[' || c == '{') ++depth;
      if (c == ')' || c == ']' || c == '}') --depth;
      if (depth != 0 || (c != ';' && c != ',')) continue;
      if (c == ',' &&
          !starts_with_name_and_separator(trim(Range{i + 1, line.end}))) {
        continue;
      }
      pieces.push_back(trim(Range{start, i}));
      start = i + 1;
    }
    pieces.push_back(trim(Range{start, line.end}));
    std::erase_if(pieces, [](const Range& r) { return r.empty(); });
    return pieces;
  }

  void lowclouds_assignment(Range piece) {
    const std::size_t equals = find_equals(piece);
    if (equals == std::string::npos) {
      fail(piece.begin, "expected 'name = value'");
    }
    const Range name = trim(Range{piece.begin, equals});
    const Range value = trim(Range{equals + 1, piece.end});
    const std::string_view word = view(name);
    if (!is_identifier(word)) fail(piece.begin, "expected 'name = value'");
    if (word == "view") return;  // the camera: nothing to print
    if (value.empty()) fail(equals, "expected a value after '='");
    const char first = text_[value.begin];
    if (first == '{' || first == '[' || first == '\'' || first == '"' ||
        match_words(value.begin, value.end, "function")) {
      fail(value.begin,
           "L-system Explorer's arrays, objects, strings and functions are "
           "not supported; a variable takes a number");
    }
    static constexpr std::array<std::pair<std::string_view, Key>, 3> kKeys{{
        {"delta", Key::Angle},
        {"stemsize", Key::Width},
        {"step", Key::Step},
    }};
    // The settings are variables as well, which expressions may read
    // (`+(delta/2)`).
    for (const auto& [setting, key] : kKeys) {
      if (word == setting) {
        draft_.settings.push_back(SettingText{key, {}, name, value});
      }
    }
    if (word == "n") {
      // `n` is the derivation length only where no `derivation length:`
      // gives one.
      lowclouds_n_ = SettingText{Key::DerivationLength, {}, name, value};
    }
    for (auto& [defined, defined_value] : draft_.defines) {
      if (view(defined) == word) {  // set again: the last value holds
        defined_value = value;
        return;
      }
    }
    draft_.defines.emplace_back(name, value);
    lowclouds_variables_.push_back(name);
  }

  void finish_lowclouds() {
    const bool has_length = std::any_of(
        draft_.settings.begin(), draft_.settings.end(),
        [](const SettingText& s) { return s.key == Key::DerivationLength; });
    if (!has_length && lowclouds_n_) draft_.settings.push_back(*lowclouds_n_);
    if (!has_length && !lowclouds_n_) {
      draft_.warnings.emplace_back(
          "no derivation length ('derivation length:', 'dlength:' or 'n = "
          "…'): 1, as L-system Explorer takes");
    }
    // A variable that a production's or a block's statements assign is a
    // global variable; the others are constants (`--define` sets them).
    std::vector<Range> statements;
    for (const ProductionText& p : draft_.productions) {
      statements.push_back(p.lhs);
    }
    for (const StatementBlock& b : draft_.blocks) statements.push_back(b.text);
    for (const Range& name : lowclouds_variables_) {
      const std::string_view word = view(name);
      const bool assigned =
          std::any_of(statements.begin(), statements.end(),
                      [&](Range r) { return assigns(r, word); });
      if (assigned) draft_.variables.insert(std::string(word));
    }
  }

  // True if `r` holds `word = …` (not `==`, `<=`, `>=`, `!=`).
  bool assigns(Range r, std::string_view word) const {
    for (std::size_t at = find_in(r, word); at != std::string::npos;
         at = find_in(Range{at + 1, r.end}, word)) {
      if (at > r.begin && is_word_char(text_[at - 1])) continue;
      std::size_t i = at + word.size();
      if (i < r.end && is_word_char(text_[i])) continue;
      while (i < r.end && is_blank(text_[i])) ++i;
      if (i < r.end && text_[i] == '=' && text_.substr(i, 2) != "==") {
        return true;
      }
    }
    return false;
  }

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

  const ParseOptions& options_;
  Draft draft_;
  LsVariant variant_;
  Section section_ = Section::Productions;
  bool seen_lsystem_label_ = false;
  std::optional<SettingText> lowclouds_n_;
  std::vector<Range> lowclouds_variables_;
  bool has_axiom_setting_ = false;
  bool after_axiom_ = false;      // the last line set or continued the axiom
  bool continues_axiom_ = false;  // this line is indented after it
};

}  // namespace

Grammar read_ls(std::shared_ptr<const SourceFile> source,
                const ParseOptions& options) {
  Draft notation;
  notation.refused = kRefused;
  return LsReader(std::move(source), options, std::move(notation),
                  LsVariant::Ls)
      .run();
}

Grammar read_ls_lines(std::shared_ptr<const SourceFile> source,
                      const ParseOptions& options, Draft notation,
                      LsVariant variant) {
  return LsReader(std::move(source), options, std::move(notation), variant)
      .run();
}

}  // namespace lsys::dialects
