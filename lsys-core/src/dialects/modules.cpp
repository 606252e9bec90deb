// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Module names are tokenised by longest match wherever they appear (ABOP
// fig. 1.26's `plant`, `internode`), never split where the notation knows
// a longer name.
#include "dialects/modules.hpp"

#include <algorithm>
#include <cctype>

namespace lsys::dialects {
namespace {

// Brackets must balance; `symbol_at(i)` and `offset_at(i)` give module i.
template <typename SymbolAt, typename OffsetAt>
void check_brackets(const TextScan& scan, std::size_t count,
                    const SymbolAt& symbol_at, const OffsetAt& offset_at,
                    bool allow_unclosed) {
  std::vector<std::size_t> open;
  for (std::size_t i = 0; i < count; ++i) {
    if (symbol_at(i) == kBranchOpen) open.push_back(offset_at(i));
    if (symbol_at(i) == kBranchClose) {
      if (open.empty()) {
        scan.fail(offset_at(i), "unbalanced ']': no '[' before it");
      }
      open.pop_back();
    }
  }
  if (!open.empty() && !allow_unclosed) {
    scan.fail(open.back(), "unclosed '[': no ']' after it");
  }
}

}  // namespace

template <typename Each>
void ModuleReader::tokenize_each(Range r, const Each& each) {
  std::size_t i = r.begin;
  for (;;) {
    while (i < r.end && is_blank(text_[i])) ++i;
    if (i >= r.end) break;
    if ((text_[i] == '(' || text_[i] == ')') && draft_.syntax.parameter_lists) {
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
        // (Appended piecewise: GCC 12 warns falsely of overlapping copies
        // in a chain of operator+ here.)
        std::string message = "'";
        message.append(word)
            .append("' is not a module: declare it with 'module ")
            .append(word)
            .append("(…);'");
        fail(i, message);
      }
      length = e - i;
    }
    RawModule m{grammar_.alphabet.intern(text_.substr(i, length)), i, {}};
    symbols_.reject_refused(m.symbol, i);
    i += length;
    std::size_t j = i;
    while (j < r.end && is_blank(text_[j])) ++j;
    if (symbols_.use_if_left_out(m.symbol)) {
      // Its arguments may be Python's strings: skipped, quotes and all.
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
      // `SB()` (lpfg), `F()` (L-Py, a Python call): no parameters.
      const bool none =
          (draft_.syntax.identifier_modules || draft_.syntax.python) &&
          trim(Range{j + 1, close}).empty();
      for (const Range& arg :
           none ? std::vector<Range>{} : split_top(Range{j + 1, close}, ',')) {
        if (trim(arg).empty()) fail(arg.begin, "expected an expression");
        m.arguments.push_back(arg);
      }
      i = close + 1;
    } else if (draft_.inline_parameter) {
      if (const auto p =
              draft_.inline_parameter(grammar_.alphabet.name(m.symbol), i, r)) {
        m.inline_value = p->value;
        i = p->end;
      }
    }
    each(std::move(m));
  }
}

std::size_t ModuleReader::skip_arguments(std::size_t open,
                                         std::size_t end) const {
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

std::vector<RawModule> ModuleReader::tokenize(Range r) {
  std::vector<RawModule> out;
  tokenize_each(r, [&](RawModule&& m) { out.push_back(std::move(m)); });
  return out;
}

Successor ModuleReader::modules(const std::vector<Range>& ranges,
                                const ExpressionScope& scope) {
  Successor out;
  // A module takes at least one byte: reserving that many is never too
  // little, and spares the copies of growing a long axiom.
  std::size_t bytes = 0;
  for (const Range& r : ranges) bytes += r.end - r.begin;
  out.reserve(bytes);
  for (const Range& r : ranges) {
    tokenize_each(r, [&](RawModule&& raw) {
      symbols_.check_arity(
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
      *this, out.size(), [&](std::size_t i) { return out.symbols()[i]; },
      [&](std::size_t i) { return out.offset(i); }, false);
  return out;
}

std::vector<PatternModule> ModuleReader::pattern(
    Range r, std::vector<std::string>& slots, PatternValues& values,
    bool allow_brackets, const char* bracket_error) {
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
      symbols_.check_arity(raw.symbol, static_cast<int>(raw.arguments.size()),
                           raw.offset);
    }
    for (const Range& arg : raw.arguments) {
      const Range name = trim(arg);
      const std::string formal(view(name));
      if (draft_.syntax.python && !is_identifier(formal)) {
        // L-Py's `A(0)` matches only the modules whose parameter is 0: a
        // hidden slot that the guard compares.
        const double value = context_.constant(name);
        values.emplace_back(static_cast<std::uint32_t>(slots.size()), value);
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
        fail(name.begin, "duplicate definition of parameter '" + formal + "'");
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
      *this, out.size() - first,
      [&](std::size_t i) { return out[first + i].symbol; },
      [&](std::size_t i) { return out[first + i].offset; }, true);
  return out;
}

void ModuleReader::read_successors_into(ExpressionScope& scope,
                                        Successor& all) {
  scope.read_successor = [this, &scope, &all](std::size_t begin,
                                              std::size_t end) {
    ExpressionScope arguments = scope;
    arguments.read_successor = nullptr;
    std::vector<SuccessorModuleText> out;
    tokenize_each(Range{begin, end}, [&](RawModule&& raw) {
      symbols_.check_arity(raw.symbol, static_cast<int>(raw.arguments.size()),
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

}  // namespace lsys::dialects
