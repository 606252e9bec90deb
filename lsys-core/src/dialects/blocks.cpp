// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "dialects/blocks.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <string>
#include <vector>

#include "lsys/diagnostic.hpp"

namespace lsys::dialects {

void BlockReader::read_blocks() {
  for (const StatementBlock& block : draft_.blocks) {
    if (block.kind == BlockKind::Define) read_arrays(block.text);
  }
  for (const Draft::PythonList& list : draft_.python_lists) {
    read_python_list(list);
  }
  for (const StatementBlock& block : draft_.blocks) {
    if (block.kind == BlockKind::Define) continue;
    ExpressionScope scope = context_.statement_scope(
        ExpressionScope{.constants = &grammar_.constants,
                        .used_constants = &context_.used_constants},
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

template <typename Closing, typename Skip>
void BlockReader::read_array(Range name_range, std::size_t& i, std::size_t end,
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
      std::any_of(context_.arrays.begin(), context_.arrays.end(),
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
    const double d = context_.constant(Range{i, close});
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
        values.push_back(context_.constant(Range{from, k}));
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
  context_.arrays.push_back(std::move(array));
}

// cpfg's `define: { array a[2][3] = {1, 2, 3}, b[4]; … }` (lsys_input.y):
// each array a run of global variables, row by row, its dimensions and
// initial values constants. cpfg warns of too many or too few values
// and leaves the rest 0, as lsolid does.
void BlockReader::read_arrays(Range block) {
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

// L-Py's `color = [1, 3, 2]`: an array of one dimension whose indices
// are Python's (a negative one counts from the end).
void BlockReader::read_python_list(const Draft::PythonList& list) {
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
      fail(e.begin, "a list of lists or tuples: lsolid reads lists of numbers");
    }
    grammar_.initial_globals[array.first + k] = context_.constant(e);
  }
  context_.arrays.push_back(std::move(array));
}

}  // namespace lsys::dialects
