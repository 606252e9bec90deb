// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// cpfg passes its `.l` and `.v` files through vlabcpp, a copy of GNU cccp,
// before reading them (cpfg's utility.c, PreprocessFile), so its models use
// the C preprocessor freely: macros with parameters (`#define br_ang(o,i)
// (100*func(1,i/(N-1)))`), macros whose body is a module string (`#define
// F_SPIKE ?(2,1.25)spikef$`), and `#ifdef` switches between variants. This
// is the part of cccp that such files use, written here because no Debian
// package offers a C preprocessor as a library that maps its output back to
// its input, which our diagnostics need.
#include "dialects/c_preprocessor.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <optional>
#include <set>
#include <string_view>
#include <utility>

#include "dialects/companion_files.hpp"
#include "dialects/text_scan.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/expression.hpp"

namespace lsys::dialects {
namespace {

bool is_ident_start(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool is_ident_char(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r'; }

std::string_view trim(std::string_view s) {
  while (!s.empty() && (is_space(s.front()) || s.front() == '\n'))
    s.remove_prefix(1);
  while (!s.empty() && (is_space(s.back()) || s.back() == '\n'))
    s.remove_suffix(1);
  return s;
}

struct Macro {
  std::optional<std::vector<std::string>> parameters;  // function-like
  std::string body;
};

// What one preprocessing does in all, its included files' too. A file of a
// kilobyte can ask for exponential work (macros that use each other twice,
// headers that include each other six times), so the work is bounded, not
// only the size of one expansion or the depth of includes.
struct Budget {
  std::size_t work = 0;      // bytes scanned and written while expanding
  std::size_t written = 0;   // bytes of text emitted, by every file
  std::size_t includes = 0;  // #include directives read
};

// Replaces comments by blanks, keeping line breaks and offsets; string
// literals (printf formats) are left alone.
std::string blank_comments(const SourceFile& source, bool line_comments) {
  std::string out = source.text();
  for (std::size_t i = 0; i < out.size(); ++i) {
    if (out[i] == '"') {
      for (++i; i < out.size() && out[i] != '"' && out[i] != '\n'; ++i) {
        if (out[i] == '\\') ++i;
      }
      continue;
    }
    if (out[i] != '/' || i + 1 == out.size()) continue;
    if (out[i + 1] == '/' && line_comments) {
      for (; i < out.size() && out[i] != '\n'; ++i) out[i] = ' ';
      continue;
    }
    if (out[i + 1] != '*') continue;
    i = blank_block_comment(source, out, i);
  }
  return out;
}

class Preprocessor {
 public:
  Preprocessor(const SourceFile& source, const PreprocessOptions& options)
      : source_(source),
        options_(options),
        clean_(blank_comments(source, options.line_comments)),
        macros_(own_macros_),
        constants_(own_constants_),
        expansions_(own_expansions_),
        budget_(own_budget_) {
    for (const std::string& d : options.defines) {
      overridden_.insert(d.substr(0, d.find('=')));
    }
    for (const auto& [name, body] : options.predefined) {
      macros_[name] = Macro{std::nullopt, body};
    }
  }

  // A file included by `parent`: C's macros are one table for the
  // translation unit, so the included file's `#define`s hold after it.
  Preprocessor(const SourceFile& source, Preprocessor& parent)
      : source_(source),
        options_(parent.options_),
        clean_(blank_comments(source, parent.options_.line_comments)),
        macros_(parent.macros_),
        constants_(parent.constants_),
        expansions_(parent.expansions_),
        budget_(parent.budget_),
        overridden_(parent.overridden_),
        include_depth_(parent.include_depth_ + 1) {}

  std::shared_ptr<const SourceFile> run() {
    std::size_t begin = 0;
    while (begin < clean_.size()) {
      const std::size_t end = logical_line_end(begin);
      line(begin, end);
      if (end < clean_.size()) emit_verbatim(end, end + 1);
      begin = end + 1;
    }
    if (!conditions_.empty()) {
      throw error_at(source_, conditions_.back().offset,
                     "'#if' without '#endif'");
    }
    return std::make_shared<const SourceFile>(
        source_.name(), source_.text(), std::move(out_), std::move(spans_));
  }

 private:
  struct Condition {
    bool active;  // this branch is being read
    bool taken;   // some branch of this #if was taken
    bool outer;   // the enclosing region is active
    std::size_t offset;
  };

  [[noreturn]] void fail(std::size_t offset, std::string message) const {
    throw error_at(source_, offset, std::move(message));
  }

  bool active() const {
    return conditions_.empty() || conditions_.back().active;
  }

  bool is_directive(std::size_t begin) const {
    std::size_t i = begin;
    while (i < clean_.size() && is_space(clean_[i])) ++i;
    if (i >= clean_.size() || clean_[i] != '#') return false;
    // `#(2)` and `#F` are cpfg's widen module, not directives.
    std::size_t j = i + 1;
    while (j < clean_.size() && is_space(clean_[j])) ++j;
    return j < clean_.size() &&
           std::islower(static_cast<unsigned char>(clean_[j])) != 0 &&
           is_directive_word(j);
  }

  bool is_directive_word(std::size_t at) const {
    std::size_t end = at;
    while (end < clean_.size() && is_ident_char(clean_[end])) ++end;
    const std::string_view word(clean_.data() + at, end - at);
    for (std::string_view known :
         {"define", "undef", "if", "ifdef", "ifndef", "elif", "else", "endif",
          "include", "error", "pragma", "line", "warning"}) {
      if (word == known) return true;
    }
    return false;
  }

  // The end (a line break or the text's end) of the statement that starts
  // at `begin`: `\` splices lines, and so does a tab after a break in cpfg.
  std::size_t logical_line_end(std::size_t begin) const {
    const bool directive = is_directive(begin);
    std::size_t i = begin;
    for (;;) {
      const std::size_t end = clean_.find('\n', i);
      if (end == std::string::npos) return clean_.size();
      std::size_t last = end;
      while (last > i && clean_[last - 1] == '\r') --last;
      if (last > i && clean_[last - 1] == '\\') {
        i = end + 1;
        continue;
      }
      const bool continues =
          end + 1 < clean_.size() &&
          ((options_.tab_continues && clean_[end + 1] == '\t') ||
           (options_.indent_continues &&
            (clean_[end + 1] == '\t' || clean_[end + 1] == ' ')));
      if (!directive && (options_.tab_continues || options_.indent_continues) &&
          ((continues && !is_directive(end + 1)) ||
           opens_statements(begin, end))) {
        i = end + 1;
        continue;
      }
      return end;
    }
  }

  // cpfg's statements `{ … }` span lines freely (its lexer reads no line
  // ends inside them): after a production's `:` before the arrow, or in a
  // `Start:` block and its kin. Braces elsewhere are polygons.
  bool opens_statements(std::size_t begin, std::size_t end) const {
    const std::string_view line(clean_.data() + begin, end - begin);
    std::size_t stop = line.find("->");  // and `-->`, which holds it
    if (stop == std::string_view::npos) stop = line.size();
    if (stop > 0 && line[stop - 1] == '-') --stop;
    const std::size_t colon = line.find(':');
    const std::size_t brace = line.find('{');
    if (colon == std::string_view::npos || brace == std::string_view::npos ||
        brace < colon || brace > stop) {
      return false;
    }
    int depth = 0;
    for (std::size_t k = brace; k < stop; ++k) {
      if (line[k] == '{') ++depth;
      if (line[k] == '}') --depth;
    }
    return depth > 0;
  }

  // Counts text about to be emitted at `at`, refusing it past the limit.
  void count_written(std::size_t at, std::size_t bytes) {
    budget_.written += bytes;
    if (budget_.written > kMaxSourceBytes) {
      fail(at,
           "the text with its macros and included files expanded comes "
           "to more than " +
               std::to_string(kMaxSourceBytes) +
               " bytes, the limit for a file");
    }
  }

  // Counts the work of expanding, refusing it past the limit.
  void count_work(std::size_t at, std::size_t bytes) {
    budget_.work += bytes;
    if (budget_.work > kMaxWork) {
      fail(at, "the macros take too much work to expand (more than " +
                   std::to_string(kMaxWork) +
                   " bytes scanned; macros that use each other many "
                   "times?)");
    }
  }

  // Copies bytes [begin, end) of the original; splices become blanks.
  void emit_verbatim(std::size_t begin, std::size_t end) {
    if (begin >= end) return;
    count_written(begin, end - begin);
    const std::size_t at = out_.size();
    for (std::size_t i = begin; i < end; ++i) {
      char c = clean_[i];
      if (i + 1 < end && c == '\\' &&
          (clean_[i + 1] == '\n' || clean_[i + 1] == '\r')) {
        c = ' ';
      } else if (c == '\n' && i + 1 != end) {
        c = ' ';
      }
      out_ += c;
    }
    if (!spans_.empty() && spans_.back().verbatim &&
        spans_.back().original_begin + spans_.back().length == begin &&
        spans_.back().text_begin + spans_.back().length == at) {
      spans_.back().length += end - begin;
    } else {
      spans_.push_back(SourceSpan{.text_begin = at,
                                  .original_begin = begin,
                                  .length = end - begin,
                                  .verbatim = true});
    }
  }

  void emit_expansion(std::size_t at, const std::string& text) {
    if (text.empty()) return;
    count_written(at, text.size());
    spans_.push_back(SourceSpan{.text_begin = out_.size(),
                                .original_begin = at,
                                .length = text.size(),
                                .verbatim = false});
    out_ += text;
  }

  void line(std::size_t begin, std::size_t end) {
    if (is_directive(begin)) {
      directive(begin, end);
      return;
    }
    if (!active()) return;
    const std::string_view text = std::string_view(clean_).substr(0, end);
    std::size_t copied = begin;
    for (auto use = next_use(text, begin, std::nullopt); use;
         use = next_use(text, use->after, std::nullopt)) {
      emit_verbatim(copied, use->begin);
      emit_expansion(use->begin, use->expansion);
      copied = use->after;
    }
    emit_verbatim(copied, end);
  }

  // A macro's use in a text, and what it expands to.
  struct Use {
    std::size_t begin;
    std::size_t after;
    std::string expansion;
  };

  // The first use at or after `from` of a macro not being expanded
  // already: strings and numbers are skipped (`1e5` holds no name), and a
  // macro with parameters is a use only where `(` follows. Errors are
  // placed at `at`, or at the use itself where the text is the source's.
  std::optional<Use> next_use(std::string_view text, std::size_t from,
                              std::optional<std::size_t> at) {
    std::size_t i = from;
    while (i < text.size()) {
      const char c = text[i];
      if (c == '"') {
        i = skip_string(text, i, text.size());
        continue;
      }
      if (std::isdigit(static_cast<unsigned char>(c)) != 0) {
        i = skip_number(text, i, text.size());
        continue;
      }
      if (!is_ident_start(c)) {
        ++i;
        continue;
      }
      std::size_t j = i;
      while (j < text.size() && is_ident_char(text[j])) ++j;
      const std::string name(text.substr(i, j - i));
      const auto it = macros_.find(name);
      if (it == macros_.end() || std::find(expanding_.begin(), expanding_.end(),
                                           name) != expanding_.end()) {
        i = j;
        continue;
      }
      const std::size_t where = at.value_or(i);
      count_work(where, kUseWork);
      if (!it->second.parameters) {
        // A macro without parameters expands the same wherever it stands
        // outside other macros: its expansion is kept until a #define or
        // #undef changes the table.
        const bool outermost = expanding_.empty();
        if (outermost) {
          const auto known = expansions_.find(name);
          if (known != expansions_.end()) return Use{i, j, known->second};
        }
        expanding_.push_back(name);
        std::string expansion = expand(it->second.body, where);
        expanding_.pop_back();
        if (outermost) expansions_[name] = expansion;
        return Use{i, j, std::move(expansion)};
      }
      std::size_t open = j;
      while (open < text.size() && (is_space(text[open]) || text[open] == '\n'))
        ++open;
      if (open >= text.size() || text[open] != '(') {
        i = j;
        continue;
      }
      std::vector<std::string> arguments;
      const std::size_t after =
          read_arguments(text, open, arguments, name, where);
      return Use{i, after, call(it->second, std::move(arguments), name, where)};
    }
    return std::nullopt;
  }

  static std::size_t skip_string(std::string_view text, std::size_t i,
                                 std::size_t end) {
    for (++i; i < end && text[i] != '"'; ++i) {
      if (text[i] == '\\') ++i;
    }
    return std::min(end, i + 1);
  }

  static std::size_t skip_number(std::string_view text, std::size_t i,
                                 std::size_t end) {
    ++i;
    while (i < end && (is_ident_char(text[i]) || text[i] == '.' ||
                       ((text[i] == '+' || text[i] == '-') &&
                        (text[i - 1] == 'e' || text[i - 1] == 'E')))) {
      ++i;
    }
    return i;
  }

  // Reads `( a, b )` from `open`; returns the offset after `)`.
  std::size_t read_arguments(std::string_view text, std::size_t open,
                             std::vector<std::string>& arguments,
                             const std::string& name, std::size_t at) const {
    int depth = 0;
    std::size_t start = open + 1;
    for (std::size_t k = open; k < text.size(); ++k) {
      const char c = text[k];
      if (c == '"') {
        k = skip_string(text, k, text.size()) - 1;
        continue;
      }
      if (c == '(') {
        ++depth;
      } else if (c == ')' && --depth == 0) {
        arguments.emplace_back(trim(text.substr(start, k - start)));
        return k + 1;
      } else if (c == ',' && depth == 1) {
        arguments.emplace_back(trim(text.substr(start, k - start)));
        start = k + 1;
      }
    }
    fail(at, "unclosed '(' in the call of macro '" + name + "'");
  }

  std::string call(const Macro& macro, std::vector<std::string> arguments,
                   const std::string& name, std::size_t at) {
    const std::size_t wanted = macro.parameters->size();
    if (wanted == 0 && arguments.size() == 1 && arguments.front().empty()) {
      arguments.clear();
    }
    if (arguments.size() != wanted) {
      std::string message = "macro '";
      message += name;
      message += "' takes ";
      message += std::to_string(wanted);
      message += wanted == 1 ? " argument" : " arguments";
      message += ", here ";
      message += std::to_string(arguments.size());
      fail(at, std::move(message));
    }
    // C expands an argument before substituting it; one that the body
    // does not use is never expanded (its expansion would be thrown
    // away), and one used several times is expanded once.
    std::vector<std::optional<std::string>> expanded(arguments.size());
    std::string substituted;
    const std::string& body = macro.body;
    for (std::size_t i = 0; i < body.size();) {
      if (!is_ident_start(body[i])) {
        substituted += body[i++];
        continue;
      }
      std::size_t j = i;
      while (j < body.size() && is_ident_char(body[j])) ++j;
      const std::string_view word(body.data() + i, j - i);
      const auto p =
          std::find(macro.parameters->begin(), macro.parameters->end(), word);
      if (p == macro.parameters->end()) {
        substituted += word;
      } else {
        const auto k = static_cast<std::size_t>(p - macro.parameters->begin());
        if (!expanded[k]) expanded[k] = expand(arguments[k], at);
        substituted += *expanded[k];
        if (substituted.size() > kMaxExpansion) {
          fail(at, "a macro expands to too much");
        }
      }
      i = j;
    }
    expanding_.push_back(name);
    std::string out = expand(substituted, at);
    expanding_.pop_back();
    return out;
  }

  // Expands the macros of a text that is not in the source (a body, an
  // argument); errors are placed at `at`, the use that led here.
  std::string expand(const std::string& text, std::size_t at) {
    if (++depth_ > kMaxDepth) fail(at, "macros expand too deeply");
    count_work(at, kUseWork + text.size());
    std::string out;
    std::size_t copied = 0;
    for (auto use = next_use(text, 0, at); use;
         use = next_use(text, use->after, at)) {
      out.append(text, copied, use->begin - copied);
      out += use->expansion;
      copied = use->after;
      count_work(at, use->expansion.size());
      if (out.size() > kMaxExpansion) fail(at, "a macro expands to too much");
    }
    out.append(text, copied);
    if (out.size() > kMaxExpansion) fail(at, "a macro expands to too much");
    --depth_;
    return out;
  }

  void directive(std::size_t begin, std::size_t end) {
    std::size_t i = clean_.find('#', begin) + 1;
    while (i < end && is_space(clean_[i])) ++i;
    const std::size_t word_begin = i;
    while (i < end && is_ident_char(clean_[i])) ++i;
    const std::string word = clean_.substr(word_begin, i - word_begin);
    std::string_view rest = std::string_view(clean_).substr(i, end - i);
    if (word == "if" || word == "ifdef" || word == "ifndef") {
      const bool outer = active();
      bool value = false;
      if (outer) {
        value = word == "if" ? evaluate_condition(rest, i)
                             : (is_defined(trim(rest)) == (word == "ifdef"));
      }
      conditions_.push_back(
          Condition{outer && value, outer && value, outer, begin});
      return;
    }
    if (word == "elif" || word == "else" || word == "endif") {
      if (conditions_.empty()) {
        fail(word_begin, "'#" + word + "' without '#if'");
      }
      Condition& c = conditions_.back();
      if (word == "endif") {
        conditions_.pop_back();
      } else if (word == "else") {
        c.active = c.outer && !c.taken;
        c.taken = true;
      } else {
        c.active = c.outer && !c.taken && evaluate_condition(rest, i);
        c.taken = c.taken || c.active;
      }
      return;
    }
    if (!active()) return;
    if (word == "define") {
      define(begin, end, i);
      return;
    }
    if (word == "undef") {
      macros_.erase(std::string(trim(rest)));
      expansions_.clear();
      return;
    }
    if (word == "pragma" || word == "line" || word == "warning") return;
    if (word == "error") {
      fail(begin, "#error " + std::string(trim(rest)));
    }
    if (word == "include") {
      include(begin, trim(rest));
      return;
    }
    fail(begin, "unknown directive '#" + word + "'");
  }

  // `#include "name"` reads the file beside this one, as vlabcpp finds a
  // model's own headers in the object's folder (Adel's `.h` parameter
  // files); its text is an expansion of the directive, so that what the
  // front end finds wrong in it is placed at the `#include`, and its own
  // directives are errors placed in it. `<name>` is a system header: only
  // those the notation names (lpfg's `lpfgall.h`) are known.
  void include(std::size_t begin, std::string_view what) {
    const bool quoted =
        what.size() > 2 && what.front() == '"' && what.back() == '"';
    const bool system =
        what.size() > 2 && what.front() == '<' && what.back() == '>';
    if (!quoted && !system) {
      fail(begin, "expected \"file\" or <file> after #include");
    }
    const std::string name(what.substr(1, what.size() - 2));
    for (const std::string& header : options_.ignored_headers) {
      if (name == header) return;
    }
    if (system) {
      std::string message = "#include <";
      message += name;
      message += ">: a header lsolid does not have";
      fail(begin, std::move(message));
    }
    if (include_depth_ >= kMostIncludeDepth) {
      fail(begin, "#include nested too deeply (a file that includes itself?)");
    }
    if (++budget_.includes > kMostIncludes) {
      fail(begin, "more than " + std::to_string(kMostIncludes) +
                      " #include directives read in all (files that "
                      "include each other many times?)");
    }
    if (options_.companions == nullptr) {
      fail(begin, "#include \"" + name + "\": this text has no folder");
    }
    const std::shared_ptr<const SourceFile> included = read_as_windows_1252(
        options_.companions->load(source_, begin, "#include", name));
    check_text(*included);
    std::shared_ptr<const SourceFile> text =
        Preprocessor(*included, *this).run();
    emit_expansion(begin, text->text());
  }

  void define(std::size_t begin, std::size_t end, std::size_t i) {
    expansions_.clear();
    while (i < end && is_space(clean_[i])) ++i;
    const std::size_t name_begin = i;
    while (i < end && is_ident_char(clean_[i])) ++i;
    if (i == name_begin || !is_ident_start(clean_[name_begin])) {
      fail(name_begin, "expected a name after #define");
    }
    const std::string name = clean_.substr(name_begin, i - name_begin);
    Macro macro;
    if (i < end && clean_[i] == '(') {
      std::vector<std::string> parameters;
      const std::size_t close = clean_.find(')', i);
      if (close == std::string::npos || close >= end) {
        fail(i, "unclosed '(' in #define");
      }
      std::string_view list =
          std::string_view(clean_).substr(i + 1, close - i - 1);
      while (!trim(list).empty()) {
        const std::size_t comma = list.find(',');
        const std::string_view p = trim(list.substr(0, comma));
        if (p.empty() || !is_ident_start(p.front()) ||
            !std::all_of(p.begin(), p.end(), is_ident_char)) {
          fail(i + 1, "expected the names of the macro's parameters");
        }
        parameters.emplace_back(p);
        if (comma == std::string_view::npos) break;
        list.remove_prefix(comma + 1);
      }
      macro.parameters = std::move(parameters);
      i = close + 1;
    }
    std::string body;
    for (char c : trim(std::string_view(clean_).substr(i, end - i))) {
      body += (c == '\n' || c == '\\') ? ' ' : c;
    }
    macro.body = std::string(trim(body));
    if (!macro.parameters && options_.keep_constants &&
        (overridden_.count(name) != 0 || is_constant_body(macro.body))) {
      // The grammar reads it as a constant; its line stays.
      macros_.erase(name);
      constants_[name] = macro.body;
      emit_verbatim(begin, end);
      return;
    }
    constants_.erase(name);
    macros_[name] = std::move(macro);
  }

  // A number, a constant, or `( … )` over numbers, constants and
  // arithmetic: its value as a constant equals its textual expansion.
  bool is_constant_body(std::string_view body) const {
    if (body.empty()) return false;
    const auto names_are_constants = [&](std::string_view s) {
      for (std::size_t i = 0; i < s.size();) {
        if (std::isdigit(static_cast<unsigned char>(s[i])) != 0 ||
            (s[i] == '.' && i + 1 < s.size() &&
             std::isdigit(static_cast<unsigned char>(s[i + 1])) != 0)) {
          i = skip_number(s, i, s.size());
          continue;
        }
        if (is_ident_start(s[i])) {
          std::size_t j = i;
          while (j < s.size() && is_ident_char(s[j])) ++j;
          if (constants_.count(std::string(s.substr(i, j - i))) == 0)
            return false;
          i = j;
          continue;
        }
        if (std::string_view("+-*/() \t.").find(s[i]) ==
            std::string_view::npos) {
          return false;
        }
        ++i;
      }
      return true;
    };
    std::string_view rest = body;
    if (rest.front() == '-' || rest.front() == '+') rest.remove_prefix(1);
    rest = trim(rest);
    if (rest.empty()) return false;
    if (rest.front() == '(') {
      int depth = 0;
      for (std::size_t k = 0; k < rest.size(); ++k) {
        if (rest[k] == '(') ++depth;
        if (rest[k] == ')' && --depth == 0 && k + 1 != rest.size())
          return false;
      }
      return depth == 0 && names_are_constants(rest);
    }
    const bool single =
        std::none_of(rest.begin(), rest.end(),
                     [](char c) {
                       return std::string_view("+-*/() \t").find(c) !=
                              std::string_view::npos;
                     }) ||
        (std::isdigit(static_cast<unsigned char>(rest.front())) != 0 &&
         skip_number(rest, 0, rest.size()) == rest.size());
    return single && names_are_constants(rest);
  }

  bool is_defined(std::string_view name) const {
    const std::string n(name);
    return macros_.count(n) != 0 || constants_.count(n) != 0;
  }

  bool evaluate_condition(std::string_view text, std::size_t at) {
    // `defined X` and `defined(X)` first, then macros; names left are 0.
    std::string resolved;
    for (std::size_t i = 0; i < text.size();) {
      if (text.substr(i).starts_with("defined") &&
          (i + 7 == text.size() || !is_ident_char(text[i + 7]))) {
        std::size_t j = i + 7;
        while (j < text.size() && is_space(text[j])) ++j;
        const bool paren = j < text.size() && text[j] == '(';
        if (paren) ++j;
        while (j < text.size() && is_space(text[j])) ++j;
        const std::size_t name_begin = j;
        while (j < text.size() && is_ident_char(text[j])) ++j;
        resolved +=
            is_defined(text.substr(name_begin, j - name_begin)) ? " 1 " : " 0 ";
        if (paren) {
          while (j < text.size() && text[j] != ')') ++j;
          ++j;
        }
        i = j;
        continue;
      }
      resolved += text[i++];
    }
    std::map<std::string, Macro> saved = macros_;
    for (const auto& [name, body] : constants_) {
      macros_[name] = Macro{std::nullopt, "(" + body + ")"};
    }
    expansions_.clear();
    std::string expanded = expand(resolved, at);
    macros_ = std::move(saved);
    expansions_.clear();
    std::string numeric;
    for (std::size_t i = 0; i < expanded.size();) {
      if (is_ident_start(expanded[i])) {
        std::size_t j = i;
        while (j < expanded.size() && is_ident_char(expanded[j])) ++j;
        const std::string_view word(expanded.data() + i, j - i);
        // Function calls stay; other names are 0, as in C.
        std::size_t k = j;
        while (k < expanded.size() && is_space(expanded[k])) ++k;
        numeric += (k < expanded.size() && expanded[k] == '(')
                       ? std::string(word)
                       : std::string("0");
        i = j;
        continue;
      }
      numeric += expanded[i++];
    }
    try {
      const auto condition =
          std::make_shared<const SourceFile>(source_.name(), numeric);
      const Expression e =
          parse_expression(condition, 0, numeric.size(), ExpressionScope{});
      if (!e.is_constant()) fail(at, "cannot evaluate this #if");
      return e.constant_value() != 0.0;
    } catch (const ParseError& error) {
      fail(at, "cannot evaluate this #if: " + error.diagnostic().message);
    }
  }

  static constexpr int kMaxDepth = 200;
  static constexpr int kMostIncludeDepth = 16;
  static constexpr std::size_t kMostIncludes = 1000;
  // Well under a second of expanding, four times the largest text a file
  // may come to.
  static constexpr std::size_t kMaxWork = std::size_t{64} << 20U;
  // A use or an expansion counts as this many bytes besides its text.
  static constexpr std::size_t kUseWork = 64;
  static constexpr std::size_t kMaxExpansion = std::size_t{1} << 20U;

  const SourceFile& source_;
  const PreprocessOptions& options_;
  std::string clean_;
  std::string out_;
  std::vector<SourceSpan> spans_;
  std::map<std::string, Macro> own_macros_;
  std::map<std::string, std::string> own_constants_;
  std::map<std::string, Macro>& macros_;
  std::map<std::string, std::string>& constants_;
  // The expansions of macros without parameters outside other macros.
  std::map<std::string, std::string> own_expansions_;
  std::map<std::string, std::string>& expansions_;
  Budget own_budget_;
  Budget& budget_;
  std::vector<std::string> expanding_;  // the macros being expanded
  std::set<std::string> overridden_;
  std::vector<Condition> conditions_;
  int depth_ = 0;
  int include_depth_ = 0;
};

}  // namespace

std::shared_ptr<const SourceFile> preprocess(const SourceFile& source,
                                             const PreprocessOptions& options) {
  return Preprocessor(source, options).run();
}

}  // namespace lsys::dialects
