// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The second pass every notation shares: once a front end has sorted a
// file's lines and collected the names of predecessors, module names are
// tokenised by longest match wherever they appear (ABOP fig. 1.26's
// `plant`, `internode`), expressions compiled, settings checked and each
// symbol given its turtle command.
#include "dialects/grammar_builder.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "lsys/diagnostic.hpp"

namespace lsys::dialects {

std::vector<DeclaredName> module_names(const TextScan& scan, Range names) {
  const std::string_view text = scan.view(Range{0, names.end});
  std::vector<DeclaredName> out;
  std::size_t i = names.begin;
  while (i < names.end) {
    while (i < names.end && (is_blank(text[i]) || text[i] == ',')) ++i;
    if (i >= names.end) break;
    std::size_t j = i;
    while (j < names.end && !is_blank(text[j]) && text[j] != ',' &&
           text[j] != '(') {
      ++j;
    }
    if (j == i) scan.fail(i, "expected a module name before '('");
    DeclaredName declared{Range{i, j}};
    while (j < names.end && is_blank(text[j])) ++j;
    if (j < names.end && text[j] == '(') {
      const std::size_t close = scan.find_in(Range{j, names.end}, ")");
      if (close == std::string::npos) scan.fail(j, "unclosed '('");
      const Range inside = scan.trim(Range{j + 1, close});
      if (!inside.empty()) {
        declared.parameter_count =
            static_cast<int>(scan.split_top(inside, ',').size());
      }
      j = close + 1;
    }
    out.push_back(declared);
    i = j;
  }
  return out;
}

namespace {

class GrammarBuilder : TextScan {
 public:
  GrammarBuilder(const TextScan& scan, Draft draft, const ParseOptions& options)
      : TextScan(scan), draft_(std::move(draft)), options_(options) {}

  Grammar run() {
    grammar_.source = source_;
    grammar_.settings = draft_.defaults;
    // Where `%` and `*` are ordinary modules, the ids of cut and wildcard
    // go to names no text can hold (check_text refuses control characters).
    const bool cut_and_wildcard = draft_.syntax.cut_and_wildcard;
    for (const char* name : {"[", "]", cut_and_wildcard ? "%" : "\x01%",
                             cut_and_wildcard ? "*" : "\x01*"}) {
      grammar_.alphabet.intern(name);
    }
    // Multi-character turtle modules must be known to the tokeniser.
    // cpfg's generalized-cylinder modules are whole names too, and draw
    // nothing more than lsolid's joined tubes.
    if (draft_.symbols.empty()) {
      for (const char* name :
           {"@v", "@Tp", "@Ts", "@O", "@Gs", "@Gc", "@Ge", "@Gt", "@Gr"}) {
        grammar_.alphabet.intern(name);
      }
    }
    for (const SymbolCommand& symbol : draft_.symbols) {
      grammar_.alphabet.intern(symbol.name);
    }
    for (const RefusedName& refused : draft_.refused) {
      refused_.emplace_back(grammar_.alphabet.intern(refused.name), &refused);
    }
    for (const RefusedName& left_out : draft_.left_out) {
      left_out_.emplace(grammar_.alphabet.intern(left_out.name),
                        LeftOut{&left_out});
    }
    grammar_.warnings = draft_.warnings;
    grammar_.constants = draft_.constants;
    evaluate_defines();  // labels are told from conditions over constants
    for (const Range& a : draft_.assertions) {
      if (constant(a) == 0.0) {
        fail(a.begin, "this assertion fails: " + std::string(view(a)));
      }
    }
    declare_names();
    read_aliases();
    read_module_declarations();
    read_settings();
    read_blocks();
    read_axiom();
    grammar_.productions.reserve(draft_.productions.size());
    for (const ProductionText& p : draft_.productions) read_production(p);
    reject_letter_settings_of_modules();
    build_commands();
    for (const auto& [symbol, left_out] : left_out_) {
      if (left_out.uses == 0) continue;
      std::string warning = "'";
      warning += left_out.name->name;
      warning += "' (";
      warning += left_out.name->what;
      warning += ") is left out: it draws nothing in a solid";
      grammar_.warnings.push_back(std::move(warning));
    }
    for (const auto& [name, at] : undefined_) {
      grammar_.warnings.push_back(
          "line " + std::to_string(source_->location(at).line) + ": '" + name +
          "' is not defined: taken as 0, as cpfg takes it");
    }
    note_variables();
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
  bool is_label_word(Range r) const {
    const std::string_view word = view(r);
    return !word.empty() && std::all_of(word.begin(), word.end(), is_word_char);
  }

  // True if `r` compiles as an expression of numbers and constants only.
  bool is_constant_condition(Range r) const {
    try {
      (void)parse_expression(source_, r.begin, r.end,
                             ExpressionScope{.constants = &grammar_.constants,
                                             .radians = draft_.syntax.radians,
                                             .mathjs = draft_.syntax.mathjs});
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
    if (draft_.syntax.numbered_labels) return strip_numbered_label(lhs);
    if (draft_.syntax.cpfg_statements) return lhs;  // cpfg has no labels
    const std::size_t colon = find_top(lhs, ":");
    if (colon == std::string::npos) return lhs;
    const Range label = trim(Range{lhs.begin, colon});
    const Range rest = trim(Range{colon + 1, lhs.end});
    if (!is_label_word(label)) return lhs;
    if (find_top(rest, ":") != std::string::npos) return rest;
    if (view(rest) == "*" || rest.empty()) return lhs;
    const std::string word(view(label));
    const bool may_be_predecessor = code_point_length(word) == word.size() ||
                                    draft_.declared_modules.count(word) != 0;
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

  // `p1:` or `P12:` before the production; nothing else is a label.
  Range strip_numbered_label(Range lhs) const {
    const std::size_t colon = find_top(lhs, ":");
    if (colon == std::string::npos) return lhs;
    const std::string_view label = view(trim(Range{lhs.begin, colon}));
    if (label.size() < 2 || (label[0] != 'p' && label[0] != 'P') ||
        !std::all_of(label.begin() + 1, label.end(), [](char c) {
          return std::isdigit(static_cast<unsigned char>(c)) != 0;
        })) {
      return lhs;
    }
    return trim(Range{colon + 1, lhs.end});
  }

  struct Lhs {
    Range left;
    Range predecessor;
    Range right;
    std::optional<Range> condition;
    std::optional<Range> before;  // cpfg: `{ … } condition { … }`
    std::optional<Range> after;
  };

  // The `}` that closes the `{` at `open`, within r.
  std::size_t closing_brace(Range r, std::size_t open) const {
    int depth = 0;
    for (std::size_t i = open; i < r.end; ++i) {
      if (text_[i] == '{') ++depth;
      if (text_[i] == '}' && --depth == 0) return i;
    }
    fail(open, "unclosed '{'");
  }

  // cpfg: `{ before } condition { after }` around the condition.
  void split_blocks(Lhs& out) const {
    Range c = *out.condition;
    if (text_[c.begin] == '{') {
      const std::size_t close = closing_brace(c, c.begin);
      out.before = Range{c.begin, close + 1};
      c = trim(Range{close + 1, c.end});
    }
    if (!c.empty() && text_[c.end - 1] == '}') {
      const std::size_t open = find_in(c, "{");
      if (open != std::string::npos && closing_brace(c, open) == c.end - 1) {
        out.after = Range{open, c.end};
        c = trim(Range{c.begin, open});
      }
    }
    if (c.empty()) {
      fail(out.before ? out.before->end : out.condition->begin,
           "expected a condition ('*' or an expression) beside the "
           "statements");
    }
    out.condition = c;
  }

  Lhs split_lhs(Range lhs_with_label) const {
    if (!draft_.syntax.contexts_and_conditions) {
      Lhs out;
      out.predecessor = trim(lhs_with_label);
      if (out.predecessor.empty()) {
        fail(lhs_with_label.begin, "missing predecessor before the arrow");
      }
      return out;
    }
    const Range lhs = strip_label(lhs_with_label);
    Lhs out;
    Range pattern = lhs;
    if (const std::size_t colon = find_top(lhs, ":");
        colon != std::string::npos) {
      pattern = trim(Range{lhs.begin, colon});
      out.condition = trim(Range{colon + 1, lhs.end});
      if (out.condition->empty()) fail(colon, "expected a condition after ':'");
      if (draft_.syntax.cpfg_statements) split_blocks(out);
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
    for (const Range& names : draft_.module_lines) {
      for (const DeclaredName& declared : module_names(*this, names)) {
        grammar_.alphabet.intern(view(declared.name));
      }
    }
    for (const ProductionText& p : draft_.productions) {
      // cpfg rewrites a predecessor of several letters, and lsolid does so
      // in productions; a homomorphism or decomposition rule's letters are
      // read as one name, as they rewrite the same where the letters only
      // stand together (docs/dialects/cpfg.md).
      if (draft_.syntax.single_character_modules &&
          p.section == Section::Productions) {
        continue;
      }
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
                                           .used_constants = &used_constants_,
                                           .radians = draft_.syntax.radians,
                                           .mathjs = draft_.syntax.mathjs});
      grammar_.constants[name] = value.constant_value();
      given.insert(name);
      given_defines_.push_back(name);
    }
    std::unordered_map<std::string, std::size_t> seen;
    for (const auto& [name_range, value] : draft_.defines) {
      const std::string name(view(name_range));
      if (const auto it = seen.find(name); it != seen.end()) {
        fail(name_range.begin,
             "duplicate definition of '" + name + "' (first defined on line " +
                 std::to_string(source_->location(it->second).line) + ")");
      }
      seen.emplace(name, name_range.begin);
      file_defines_.insert(name);
      if (given.count(name) != 0) continue;  // --define wins
      if (draft_.variables.count(name) != 0) {
        // lpfg's `int n;` starts at 0.
        grammar_.globals.push_back(name);
        grammar_.initial_globals.push_back(value.empty() ? 0.0
                                                         : constant(value));
        continue;
      }
      grammar_.constants[name] = constant(value);
    }
  }

  // The value of a constant: numbers and other constants only. A random
  // number (L-system Explorer's `x = random()`) is drawn while deriving,
  // never once for the whole file.
  double constant(Range r) const {
    ExpressionScope scope{.constants = &grammar_.constants,
                          .used_constants = &used_constants_,
                          .radians = draft_.syntax.radians,
                          .mathjs = draft_.syntax.mathjs,
                          .c_language = draft_.syntax.c_language};
    if (draft_.syntax.python) {
      scope.python = true;
      scope.python_modules = &draft_.python_modules;
      scope.python_functions = &draft_.python_functions;
      scope.python_imports = &draft_.python_imports;
    }
    const Expression e = parse_expression(source_, r.begin, r.end, scope);
    if (!e.is_constant()) {
      fail(r.begin,
           "a constant's value must be a number or arithmetic over numbers "
           "and constants, not a random number");
    }
    return e.constant_value();
  }

  void read_aliases() {
    for (const Range& line : draft_.alias_lines) {
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
        if (!notation_command(to) && to.size() > 1 && to.back() == ',') {
          to.remove_suffix(1);
        }
        const auto command = notation_command(to);
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
    for (const Range& names : draft_.module_lines) {
      for (const DeclaredName& declared : module_names(*this, names)) {
        if (declared.parameter_count == 0) continue;
        check_arity(*grammar_.alphabet.find(view(declared.name)),
                    declared.parameter_count, declared.name.begin);
      }
    }
  }

  // The command a name has in the notation, before aliases.
  std::optional<TurtleCommand> notation_command(std::string_view name) const {
    if (draft_.symbols.empty()) return builtin_command(name);
    for (const SymbolCommand& s : draft_.symbols) {
      if (s.name == name) return s.command;
    }
    return std::nullopt;
  }

  TurtleCommand command_of(SymbolId symbol) const {
    if (const auto it = aliases_.find(symbol); it != aliases_.end()) {
      return it->second;
    }
    return notation_command(grammar_.alphabet.name(symbol))
        .value_or(TurtleCommand::None);
  }

  void check_arity(SymbolId symbol, int count, std::size_t offset) {
    const std::string& name = grammar_.alphabet.name(symbol);
    const TurtleCommand command = command_of(symbol);
    if (command != TurtleCommand::None) {
      const int most = max_parameters(command);
      const int least = min_parameters(command);
      if ((count > most && !draft_.syntax.extra_turtle_parameters) ||
          count < least) {
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
    // Lparser's parameters are text behind a module, not part of it.
    if (!draft_.syntax.fixed_arity) return;
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
    std::optional<double> inline_value;  // Fractint's `\30`
  };

  // Calls `each` with every module of r in turn, so that a long axiom is
  // never held as tokens besides its successor.
  template <typename Each>
  void tokenize_each(Range r, const Each& each) {
    std::size_t i = r.begin;
    for (;;) {
      while (i < r.end && is_blank(text_[i])) ++i;
      if (i >= r.end) break;
      if ((text_[i] == '(' || text_[i] == ')') &&
          draft_.syntax.parameter_lists) {
        fail(i, std::string("unexpected '") + text_[i] +
                    "': parameters follow a module name, as in F(1)");
      }
      std::size_t length =
          grammar_.alphabet.match_length(text_.substr(i, r.end - i));
      if (draft_.syntax.identifier_modules &&
          (std::isalpha(static_cast<unsigned char>(text_[i])) != 0 ||
           text_[i] == '_')) {
        // lpfg: a module is a C identifier the notation or a `module`
        // line names, never split into letters.
        std::size_t e = i;
        while (e < r.end && is_word_char(text_[e])) ++e;
        const std::string_view word = text_.substr(i, e - i);
        if (!grammar_.alphabet.find(word)) {
          fail(i, "'" + std::string(word) +
                      "' is not a module: declare it with 'module " +
                      std::string(word) + "(…);'");
        }
        length = e - i;
      }
      RawModule m{grammar_.alphabet.intern(text_.substr(i, length)), i, {}};
      reject_refused(m.symbol, i);
      i += length;
      std::size_t j = i;
      while (j < r.end && is_blank(text_[j])) ++j;
      if (const auto it = left_out_.find(m.symbol); it != left_out_.end()) {
        // Its arguments may be Python's strings: skipped, quotes and all.
        ++it->second.uses;
        if (j < r.end && text_[j] == '(') i = skip_arguments(j, r.end) + 1;
        each(std::move(m));
        continue;
      }
      if (j < r.end && text_[j] == '(' && draft_.syntax.parameter_lists) {
        int depth = 0;
        std::size_t close = j;
        for (; close < r.end; ++close) {
          if (text_[close] == '(') ++depth;
          if (text_[close] == ')' && --depth == 0) break;
        }
        if (close >= r.end) fail(j, "unclosed '('");
        const bool none = draft_.syntax.identifier_modules &&
                          trim(Range{j + 1, close}).empty();  // `SB()`
        for (const Range& arg : none ? std::vector<Range>{}
                                     : split_top(Range{j + 1, close}, ',')) {
          if (trim(arg).empty()) fail(arg.begin, "expected an expression");
          m.arguments.push_back(arg);
        }
        i = close + 1;
      } else if (draft_.inline_parameter) {
        if (const auto p = draft_.inline_parameter(
                grammar_.alphabet.name(m.symbol), i, r)) {
          m.inline_value = p->value;
          i = p->end;
        }
      }
      each(std::move(m));
    }
  }

  // The `)` that closes the `(` at `open`, outside Python's strings.
  std::size_t skip_arguments(std::size_t open, std::size_t end) const {
    int depth = 0;
    char quote = 0;
    for (std::size_t k = open; k < end; ++k) {
      const char c = text_[k];
      if (quote != 0) {
        if (c == '\\') {
          ++k;
        } else if (c == quote) {
          quote = 0;
        }
      } else if (c == '\'' || c == '"') {
        quote = c;
      } else if (c == '(') {
        ++depth;
      } else if (c == ')' && --depth == 0) {
        return k;
      }
    }
    fail(open, "unclosed '('");
  }

  void reject_refused(SymbolId symbol, std::size_t offset) const {
    const std::string& name = grammar_.alphabet.name(symbol);
    for (const auto& [id, refused] : refused_) {
      // A one-character refused name that is a name's prefix refuses it
      // too: a predecessor `~f(t)` names cpfg's surface `~` with `f`.
      const bool prefix =
          refused->name.size() == 1 && !is_word_char(refused->name.front()) &&
          name.starts_with(refused->name) && !notation_command(name);
      if (id != symbol && !prefix) continue;
      std::string message = "'";
      message += refused->name;
      message += "' (";
      message += refused->what;
      message += ") is not supported by lsolid";
      fail(offset, std::move(message));
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
        check_arity(
            raw.symbol,
            static_cast<int>(raw.arguments.size()) + (raw.inline_value ? 1 : 0),
            raw.offset);
        std::vector<Expression> parameters;
        for (const Range& arg : raw.arguments) {
          parameters.push_back(
              parse_expression(source_, arg.begin, arg.end, scope));
        }
        if (raw.inline_value) {
          parameters.push_back(Expression::constant(*raw.inline_value));
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
        if (draft_.syntax.python && !is_identifier(formal)) {
          // L-Py's `A(0)` matches only the modules whose parameter is 0: a
          // hidden slot that the guard compares.
          const double value = constant(name);
          pattern_values_.emplace_back(static_cast<std::uint32_t>(slots.size()),
                                       value);
          std::string hidden = "#";
          hidden += std::to_string(slots.size());
          slots.push_back(std::move(hidden));
          continue;
        }
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
      out.back().to_branch_end =
          allow_brackets && draft_.syntax.skip_to_branch_end &&
          grammar_.alphabet.name(raw.symbol) == "=" && raw.arguments.empty();
    }
    // After cpfg's `=`, a `]` may leave the branch the predecessor is in:
    // only the rest is checked for balance.
    std::size_t first = 0;
    for (std::size_t i = 0; i + 1 < out.size(); ++i) {
      if (out[i].to_branch_end && out[i + 1].symbol == kBranchClose &&
          std::none_of(
              out.begin(), out.begin() + static_cast<long>(i),
              [](const PatternModule& m) { return m.symbol == kBranchOpen; })) {
        first = i + 2;
      }
    }
    check_brackets(
        out.size() - first,
        [&](std::size_t i) { return out[first + i].symbol; },
        [&](std::size_t i) { return out[first + i].offset; }, true);
    return out;
  }

  void read_production(const ProductionText& text) {
    const Lhs lhs = split_lhs(text.lhs);
    Production p;
    std::vector<std::string> slots;
    pattern_values_.clear();
    if (!lhs.left.empty()) {
      p.left_context = pattern(lhs.left, slots, false,
                               "a left context cannot contain brackets");
    }
    const std::vector<PatternModule> predecessor =
        pattern(lhs.predecessor, slots, false, "brackets cannot be rewritten");
    if (predecessor.empty() || (predecessor.size() > 1 &&
                                (!draft_.syntax.several_module_predecessors ||
                                 text.section != Section::Productions))) {
      fail(lhs.predecessor.begin, "the predecessor must be a single module");
    }
    for (const PatternModule& m : predecessor) {
      if (m.symbol == kAnyModule) {
        fail(m.offset, "'*' matches any module only in a context");
      }
    }
    p.predecessor = predecessor.front();
    p.predecessor_rest.assign(predecessor.begin() + 1, predecessor.end());
    p.offset = p.predecessor.offset;
    if (!lhs.right.empty()) {
      p.right_context = pattern(lhs.right, slots, true, "");
    }
    if (!pattern_values_.empty()) {
      p.guard = Expression::slots_equal(source_, p.offset, pattern_values_);
    }
    std::vector<std::string> locals;
    ExpressionScope scope =
        cpfg_scope(ExpressionScope{.parameters = slots,
                                   .constants = &grammar_.constants,
                                   .used_constants = &used_constants_,
                                   .radians = draft_.syntax.radians,
                                   .mathjs = draft_.syntax.mathjs},
                   &locals);
    if (lhs.before) {
      p.before =
          parse_statements(source_, lhs.before->begin, lhs.before->end, scope);
    }
    if (lhs.condition) {
      p.condition = parse_expression(source_, lhs.condition->begin,
                                     lhs.condition->end, scope);
    }
    if (lhs.after) {
      p.after =
          parse_statements(source_, lhs.after->begin, lhs.after->end, scope);
    }
    if (text.python_body) {
      p.undo_unless_applied = true;
      p.successor_from_body = text.python_builds;
      if (text.python_builds) read_successors_into(scope, p.successor);
      p.before = text.c_body
                     ? parse_statements(source_, text.python_body->begin,
                                        text.python_body->end, scope)
                     : parse_python_statements(source_, text.python_body->begin,
                                               text.python_body->end, scope);
      const auto produced =
          std::find(locals.begin(), locals.end(), kProducedLocal);
      p.condition = Expression::slot_equals(
          source_, text.python_body->begin,
          static_cast<std::uint32_t>(
              slots.size() +
              static_cast<std::size_t>(produced - locals.begin())),
          text.python_builds ? 1 : text.python_branch);
    }
    std::vector<Range> rhs = text.rhs;
    if (text.probability) {
      p.probability = parse_expression(source_, text.probability->begin,
                                       text.probability->end, scope);
    }
    // cpfg appends the probability: `F --> F[+F]F : 0.33`.
    if (const std::size_t colon = draft_.syntax.probability_after_successor
                                      ? find_top(rhs.back(), ":")
                                      : std::string::npos;
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
    if (!p.successor_from_body) p.successor = modules(rhs, scope);
    p.local_count = static_cast<int>(locals.size());
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

  // For a Python body that builds its successor: each `nproduce` or
  // `produce` statement's modules, read as a successor is, go into `all`
  // (Production::successor_from_body) and, as names and places of their
  // arguments, to the statements' compiler.
  void read_successors_into(ExpressionScope& scope, Successor& all) {
    scope.read_successor = [this, &scope, &all](std::size_t begin,
                                                std::size_t end) {
      ExpressionScope arguments = scope;
      arguments.read_successor = nullptr;
      std::vector<SuccessorModuleText> out;
      tokenize_each(Range{begin, end}, [&](RawModule&& raw) {
        check_arity(raw.symbol, static_cast<int>(raw.arguments.size()),
                    raw.offset);
        std::vector<Expression> parameters;
        SuccessorModuleText module{.symbol = raw.symbol, .offset = raw.offset};
        for (const Range& arg : raw.arguments) {
          parameters.push_back(
              parse_expression(source_, arg.begin, arg.end, arguments));
          module.arguments.emplace_back(arg.begin, arg.end);
        }
        all.push_back(raw.symbol, std::move(parameters), raw.offset);
        out.push_back(std::move(module));
      });
      return out;
    };
  }

  // cpfg's names and functions added to a scope.
  ExpressionScope cpfg_scope(ExpressionScope scope,
                             std::vector<std::string>* locals) {
    if (draft_.syntax.python) {
      // L-Py: a rule body's names are local unless a hook made them global.
      scope.python = true;
      scope.python_modules = &draft_.python_modules;
      scope.python_functions = &draft_.python_functions;
      scope.python_imports = &draft_.python_imports;
      scope.locals = locals;
      scope.globals = &grammar_.globals;
      scope.arrays = &arrays_;
      return scope;
    }
    if (!draft_.syntax.cpfg_statements) return scope;
    scope.locals = locals;
    scope.globals = &grammar_.globals;
    scope.arrays = &arrays_;
    scope.cpfg = true;
    scope.c_language = draft_.syntax.c_language;
    if (!scope.c_language && !draft_.syntax.mathjs) {
      scope.undefined = &undefined_;
    }
    if (scope.c_language) scope.python_functions = &draft_.python_functions;
    scope.functions = draft_.functions;
    return scope;
  }

  // `Start: { … }` and its kin, in file order, before anything reads
  // their variables: what they assign is global.
  void read_blocks() {
    for (const StatementBlock& block : draft_.blocks) {
      if (block.kind == BlockKind::Define) read_arrays(block.text);
    }
    for (const Draft::PythonList& list : draft_.python_lists) {
      read_python_list(list);
    }
    for (const StatementBlock& block : draft_.blocks) {
      if (block.kind == BlockKind::Define) continue;
      ExpressionScope scope =
          cpfg_scope(ExpressionScope{.constants = &grammar_.constants,
                                     .used_constants = &used_constants_},
                     nullptr);
      scope.assign_globals = true;
      std::optional<Expression>* slot = nullptr;
      switch (block.kind) {
        case BlockKind::Start:
          slot = &grammar_.start;
          break;
        case BlockKind::StartEach:
          slot = &grammar_.start_each;
          break;
        case BlockKind::EndEach:
          slot = &grammar_.end_each;
          break;
        case BlockKind::End:
          slot = &grammar_.end;
          break;
        case BlockKind::Define:
          continue;
      }
      if (slot->has_value()) {
        fail(block.text.begin, "a second block of this kind");
      }
      *slot = block.python ? parse_python_statements(source_, block.text.begin,
                                                     block.text.end, scope)
                           : parse_statements(source_, block.text.begin,
                                              block.text.end, scope);
    }
  }

  // cpfg's `define: { array a[2][3] = {1, 2, 3}, b[4]; … }` (lsys_input.y):
  // each array a run of global variables, row by row, its dimensions and
  // initial values constants. cpfg warns of too many or too few values
  // and leaves the rest 0, as lsolid does.
  void read_arrays(Range block) {
    const std::string& text = source_->text();
    std::size_t i = block.begin + 1;
    const std::size_t end = block.end - 1;  // the closing brace
    const auto skip = [&] {
      while (i < end && std::isspace(static_cast<unsigned char>(text[i]))) ++i;
    };
    const auto word = [&] {
      skip();
      const std::size_t at = i;
      while (i < end && (std::isalnum(static_cast<unsigned char>(text[i])) ||
                         text[i] == '_')) {
        ++i;
      }
      return Range{at, i};
    };
    // [from, the bracket that closes the one before from).
    const auto closing = [&](char open, char close) {
      int depth = 1;
      std::size_t k = i;
      for (; k < end; ++k) {
        if (text[k] == open) ++depth;
        if (text[k] == close && --depth == 0) return k;
      }
      fail(i - 1, std::string("expected '") + close + "'");
    };
    for (;;) {
      skip();
      if (i >= end) break;
      const Range keyword = word();
      if (view(keyword) == "external") {
        fail(keyword.begin, "cpfg's external arrays are not supported");
      }
      if (view(keyword) != "array") {
        fail(keyword.begin, "expected 'array' in a define: block");
      }
      for (;;) {
        read_array(word(), i, end, closing, skip);
        skip();
        if (i < end && text[i] == ',') {
          ++i;
          continue;
        }
        if (i < end && text[i] == ';') {
          ++i;
          break;
        }
        fail(i, "expected ',' or ';' after an array");
      }
    }
  }

  template <typename Closing, typename Skip>
  void read_array(Range name_range, std::size_t& i, std::size_t end,
                  const Closing& closing, const Skip& skip) {
    const std::string& text = source_->text();
    const std::string name(view(name_range));
    if (name.empty() ||
        std::isdigit(static_cast<unsigned char>(name.front())) != 0) {
      fail(name_range.begin, "expected an array's name");
    }
    const bool taken =
        std::find(grammar_.globals.begin(), grammar_.globals.end(), name) !=
            grammar_.globals.end() ||
        std::any_of(arrays_.begin(), arrays_.end(),
                    [&](const ArrayVariable& a) { return a.name == name; });
    if (taken) fail(name_range.begin, "'" + name + "' is defined twice");
    ArrayVariable array{
        .name = name,
        .first = static_cast<std::uint32_t>(grammar_.globals.size())};
    double total = 1.0;
    skip();
    while (i < end && text[i] == '[') {
      ++i;
      const std::size_t close = closing('[', ']');
      const double d = constant(Range{i, close});
      if (d != std::floor(d) || d < 1.0) {
        fail(i, "an array's dimension must be a whole number, at least 1");
      }
      total *= d;
      if (total > kMostArrayElements) {
        fail(i, "an array of more than a million elements");
      }
      array.dimensions.push_back(static_cast<std::uint32_t>(d));
      i = close + 1;
      skip();
    }
    if (array.dimensions.empty()) {
      fail(i, "expected '[' and the array's size after its name");
    }
    std::vector<double> values;
    if (i < end && text[i] == '=') {
      ++i;
      skip();
      if (i >= end || text[i] != '{') fail(i, "expected '{' and the values");
      ++i;
      const std::size_t close = closing('{', '}');
      std::size_t from = i;
      int depth = 0;
      for (std::size_t k = i; k <= close; ++k) {
        const char c = text[k];
        if (c == '(') ++depth;
        if (c == ')') --depth;
        if (k == close || (c == ',' && depth == 0)) {
          values.push_back(constant(Range{from, k}));
          from = k + 1;
        }
      }
      i = close + 1;
      const auto n = static_cast<std::size_t>(total);
      if (values.size() != n) {
        grammar_.warnings.push_back(
            "line " + std::to_string(source_->location(name_range.begin).line) +
            ": array '" + name + "' of " + std::to_string(n) +
            (n == 1 ? " element" : " elements") + " is given " +
            std::to_string(values.size()) +
            (values.size() < n ? " values: the rest are 0, as in cpfg"
                               : " values: the last are ignored, as in cpfg"));
      }
    }
    const auto n = static_cast<std::size_t>(total);
    for (std::size_t k = 0; k < n; ++k) {
      grammar_.globals.push_back(name + "[" + std::to_string(k) + "]");
    }
    grammar_.initial_globals.resize(grammar_.globals.size(), 0.0);
    std::copy_n(values.begin(), std::min(values.size(), n),
                grammar_.initial_globals.begin() + array.first);
    arrays_.push_back(std::move(array));
  }

  // L-Py's `color = [1, 3, 2]`: an array of one dimension whose indices
  // are Python's (a negative one counts from the end).
  void read_python_list(const Draft::PythonList& list) {
    const std::string name(view(list.name));
    if (list.elements.empty()) {
      fail(list.name.begin, "an empty list: lsolid reads lists of numbers");
    }
    ArrayVariable array{
        .name = name,
        .first = static_cast<std::uint32_t>(grammar_.globals.size()),
        .dimensions = {static_cast<std::uint32_t>(list.elements.size())},
        .python = true};
    for (std::size_t k = 0; k < list.elements.size(); ++k) {
      grammar_.globals.push_back(name + "[" + std::to_string(k) + "]");
    }
    grammar_.initial_globals.resize(grammar_.globals.size(), 0.0);
    for (std::size_t k = 0; k < list.elements.size(); ++k) {
      const Range e = list.elements[k];
      if (text_at(e.begin) == '[' || text_at(e.begin) == '(') {
        fail(e.begin,
             "a list of lists or tuples: lsolid reads lists of numbers");
      }
      grammar_.initial_globals[array.first + k] = constant(e);
    }
    arrays_.push_back(std::move(array));
  }

  char text_at(std::size_t i) const { return source_->text()[i]; }

  void note_variables() {
    bool uses = !grammar_.globals.empty() || grammar_.axiom_body ||
                grammar_.start || grammar_.start_each || grammar_.end_each ||
                grammar_.end || grammar_.axiom.uses_variables();
    for (const auto* list : {&grammar_.productions, &grammar_.decompositions,
                             &grammar_.homomorphisms}) {
      for (const Production& p : *list) {
        uses = uses || p.before || p.after || p.successor.uses_variables() ||
               (p.condition && p.condition->uses_variables()) ||
               (p.probability && p.probability->uses_variables());
      }
    }
    grammar_.uses_variables = uses;
  }

  void read_axiom() {
    if (draft_.axiom_python) {
      std::vector<std::string> locals;
      ExpressionScope scope =
          cpfg_scope(ExpressionScope{.constants = &grammar_.constants,
                                     .used_constants = &used_constants_,
                                     .radians = draft_.syntax.radians},
                     &locals);
      read_successors_into(scope, grammar_.axiom);
      grammar_.axiom_body = parse_python_statements(
          source_, draft_.axiom_python->begin, draft_.axiom_python->end, scope);
      grammar_.axiom_local_count = static_cast<int>(locals.size());
      grammar_.axiom_offset = draft_.axiom_python->begin;
      return;
    }
    if (!draft_.axiom) {
      fail(draft_.productions.empty()
               ? 0
               : trim(draft_.productions.front().lhs).begin,
           "no axiom: give one as 'axiom: F', '\u03C9: F' or a line of "
           "modules before the productions");
    }
    const ExpressionScope scope =
        cpfg_scope(ExpressionScope{.constants = &grammar_.constants,
                                   .used_constants = &used_constants_,
                                   .radians = draft_.syntax.radians,
                                   .mathjs = draft_.syntax.mathjs},
                   nullptr);
    std::vector<Range> ranges{*draft_.axiom};
    ranges.insert(ranges.end(), draft_.axiom_more.begin(),
                  draft_.axiom_more.end());
    grammar_.axiom = modules(ranges, scope);
    grammar_.axiom_offset = draft_.axiom->begin;
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
    for (const SettingText& setting : draft_.settings) {
      const std::string key_text(view(setting.key_range));
      if (setting.key == Key::Extra) {
        grammar_.extra_settings.push_back(
            ExtraSetting{setting.extra_key, std::string(view(setting.value)),
                         setting.value.begin});
        continue;
      }
      std::size_t separator = setting.key_range.end;
      while (separator < text_.size() && is_blank(text_[separator])) {
        ++separator;
      }
      if (separator < text_.size() && text_[separator] == '=' &&
          setting.key != Key::Axiom &&
          code_point_length(key_text) == key_text.size()) {
        letter_settings_.push_back(setting);
      }
      const int id = static_cast<int>(setting.key);
      if (const auto it = seen.find(id); it != seen.end()) {
        if (setting.key == Key::LsystemLabel) {
          // cpfg reads the next `Lsystem:` as a sub-L-system (often through
          // an `#include` of another `.l`), which `?` and `$` call.
          std::string message =
              "a second L-system (a sub-L-system; the first is on line ";
          message += std::to_string(source_->location(it->second).line);
          message += ") is not supported";
          fail(setting.key_range.begin, std::move(message));
        }
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
          if (draft_.axiom) {
            fail(setting.key_range.begin,
                 "duplicate axiom (the first is on line " +
                     std::to_string(
                         source_->location(draft_.axiom->begin).line) +
                     ")");
          }
          draft_.axiom = v;
          break;
        case Key::DerivationLength:
          s.derivation_length =
              static_cast<int>(whole(v, kMaxDerivationLength));
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
          s.seed = static_cast<std::uint64_t>(
              whole(v, static_cast<double>(kMaxWholeNumber)));
          s.seed_offset = v.begin;
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
          if (draft_.syntax.cpfg_statements && constant(v) > 1000.0) {
            // cpfg stops at its depth as lsolid stops at 1000, the most its
            // recursion takes safely; models ask for 3000 but rarely use it.
            grammar_.warnings.push_back("maximum depth " +
                                        std::string(view(v)) +
                                        " taken as 1000, lsolid's limit");
            s.maximum_depth = 1000;
            break;
          }
          s.maximum_depth = static_cast<int>(whole(v, 1000));
          break;
        case Key::HomomorphismDepth:
          s.homomorphism_depth = static_cast<int>(whole(v, 1000));
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
    grammar_.default_parameters.resize(grammar_.alphabet.size());
    if (draft_.syntax.extra_turtle_parameters) {
      grammar_.parameters_read.resize(grammar_.alphabet.size());
    }
    for (SymbolId s = 0; s < grammar_.alphabet.size(); ++s) {
      grammar_.commands[s] = command_of(s);
      if (draft_.syntax.extra_turtle_parameters &&
          grammar_.commands[s] != TurtleCommand::None) {
        grammar_.parameters_read[s] = max_parameters(grammar_.commands[s]);
      }
      if (aliases_.count(s) != 0) continue;
      for (const SymbolCommand& symbol : draft_.symbols) {
        if (symbol.name == grammar_.alphabet.name(s)) {
          grammar_.default_parameters[s] = symbol.default_parameter;
          if (symbol.parameters_read && draft_.syntax.extra_turtle_parameters) {
            grammar_.parameters_read[s] = symbol.parameters_read;
          }
        }
      }
    }
  }

  Draft draft_;
  const ParseOptions& options_;
  Grammar grammar_;
  std::vector<SettingText> letter_settings_;  // `n=2`: one letter and `=`
  struct LeftOut {
    const RefusedName* name;
    std::size_t uses = 0;
  };
  std::map<SymbolId, LeftOut> left_out_;
  std::vector<ArrayVariable> arrays_;  // cpfg's, in grammar_.globals
  // cpfg's names that nothing defined, taken as variables of 0.
  std::vector<std::pair<std::string, std::size_t>> undefined_;
  // The values an L-Py predecessor requires, by slot (pattern).
  std::vector<std::pair<std::uint32_t, double>> pattern_values_;
  static constexpr double kMostArrayElements = 1e6;
  std::unordered_map<SymbolId, TurtleCommand> aliases_;
  // The ids of the names the notation refuses, and why.
  std::vector<std::pair<SymbolId, const RefusedName*>> refused_;
  std::unordered_map<SymbolId, std::pair<int, std::size_t>> arity_;
  mutable std::set<std::string> used_constants_;  // filled while compiling
  std::vector<std::string> given_defines_;
  std::set<std::string> file_defines_;
};

}  // namespace

Grammar build_grammar(const TextScan& scan, Draft draft,
                      const ParseOptions& options) {
  return GrammarBuilder(scan, std::move(draft), options).run();
}

}  // namespace lsys::dialects
