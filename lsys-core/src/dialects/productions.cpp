// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "dialects/productions.hpp"

#include <algorithm>
#include <cctype>
#include <optional>
#include <string>
#include <vector>

#include "lsys/diagnostic.hpp"

namespace lsys::dialects {

bool ProductionReader::is_label_word(Range r) const {
  const std::string_view word = view(r);
  return !word.empty() && std::all_of(word.begin(), word.end(), is_word_char);
}

// True if `r` compiles as an expression of numbers and constants only.
bool ProductionReader::is_constant_condition(Range r) const {
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
Range ProductionReader::strip_label(Range lhs) const {
  lhs = trim(lhs);
  if (draft_.syntax.numbered_labels) return strip_numbered_label(lhs);
  if (draft_.syntax.cpfg_statements) return lhs;  // cpfg has no labels
  const std::size_t colon = find_top(lhs, ":");
  if (colon == std::string::npos) return lhs;
  const Range label = trim(Range{lhs.begin, colon});
  const Range rest = trim(Range{colon + 1, lhs.end});
  if (is_field_label(label)) return rest;
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

// Houdini's L-system node names its fields `Rule 1` to `Rule 24` in its
// parameter pane, and a system pasted from there keeps those names before
// each production (`Rule 1: X = F[+X]F`): any case, blanks between.
bool ProductionReader::is_field_label(Range r) const {
  const std::optional<std::size_t> number =
      match_words(r.begin, r.end, "rule ");
  return number && *number < r.end &&
         std::all_of(text_.begin() + static_cast<std::ptrdiff_t>(*number),
                     text_.begin() + static_cast<std::ptrdiff_t>(r.end),
                     [](char c) {
                       return std::isdigit(static_cast<unsigned char>(c)) != 0;
                     });
}

// `p1:` or `P12:` before the production; nothing else is a label.
Range ProductionReader::strip_numbered_label(Range lhs) const {
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

// The `}` that closes the `{` at `open`, within r.
std::size_t ProductionReader::closing_brace(Range r, std::size_t open) const {
  int depth = 0;
  for (std::size_t i = open; i < r.end; ++i) {
    if (text_[i] == '{') ++depth;
    if (text_[i] == '}' && --depth == 0) return i;
  }
  fail(open, "unclosed '{'");
}

// cpfg: `{ before } condition { after }` around the condition.
void ProductionReader::split_blocks(Lhs& out) const {
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

ProductionReader::Lhs ProductionReader::split_lhs(Range lhs_with_label) const {
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
  if (const std::size_t lt = find_top(pattern, "<"); lt != std::string::npos) {
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

void ProductionReader::declare_names() {
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
        fail(lhs.predecessor.begin, "the predecessor must be a single module");
      }
    }
    grammar_.alphabet.intern(view(name));
  }
}

void ProductionReader::read_production(const ProductionText& text) {
  const Lhs lhs = split_lhs(text.lhs);
  Production p;
  std::vector<std::string> slots;
  PatternValues values;
  if (!lhs.left.empty()) {
    p.left_context = modules_.pattern(lhs.left, slots, values, false,
                                      "a left context cannot contain brackets");
  }
  const std::vector<PatternModule> predecessor = modules_.pattern(
      lhs.predecessor, slots, values, false, "brackets cannot be rewritten");
  if (predecessor.empty() ||
      (predecessor.size() > 1 && (!draft_.syntax.several_module_predecessors ||
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
    p.right_context = modules_.pattern(lhs.right, slots, values, true, "");
  }
  if (!values.empty()) {
    p.guard = Expression::slots_equal(source_, p.offset, values);
  }
  std::vector<std::string> locals;
  ExpressionScope scope = context_.statement_scope(
      ExpressionScope{.parameters = slots,
                      .constants = &grammar_.constants,
                      .used_constants = &context_.used_constants,
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
    // The body's productions but the last undo a run that does not select
    // them; the last keeps its run's draws and globals whether or not it
    // applies, as L-Py and lpfg keep those of a body that produces nothing.
    p.undo_unless_applied =
        text.python_branch > 0 && text.python_branch < text.python_branches;
    p.successor_from_body = text.python_builds;
    if (text.python_builds) modules_.read_successors_into(scope, p.successor);
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
            slots.size() + static_cast<std::size_t>(produced - locals.begin())),
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
    if (p.probability) fail(colon, "this production already has a probability");
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
  if (!p.successor_from_body) p.successor = modules_.modules(rhs, scope);
  p.local_count = static_cast<int>(locals.size());
  if (text.section != Section::Productions) {
    const char* what = text.section == Section::Decomposition ? "decomposition"
                                                              : "homomorphism";
    if (p.is_context_sensitive()) {
      fail(p.offset, std::string("a ") + what + " rule cannot have a context");
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

}  // namespace lsys::dialects
