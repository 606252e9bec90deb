// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>

#include "dialects/build_context.hpp"

namespace lsys::dialects {

/// Reads the statement blocks a notation runs around the derivation
/// (cpfg's `Start:`, `StartEach:`, `EndEach:`, `End:` and L-Py's hooks),
/// cpfg's `define:` arrays and L-Py's lists of numbers, in file order,
/// before anything reads their variables: what they assign is global.
class BlockReader : protected TextScan {
 public:
  explicit BlockReader(BuildContext& context)
      : TextScan(context.scan),
        context_(context),
        draft_(context.draft),
        grammar_(context.grammar) {}

  /// Reads every block of the draft into the grammar.
  /// @throws ParseError at what cannot be read.
  void read_blocks();

 private:
  void read_arrays(Range block);
  template <typename Closing, typename Skip>
  void read_array(Range name_range, std::size_t& i, std::size_t end,
                  const Closing& closing, const Skip& skip);
  void read_python_list(const Draft::PythonList& list);
  char text_at(std::size_t i) const { return source_->text()[i]; }

  static constexpr double kMostArrayElements = 1e6;
  BuildContext& context_;
  Draft& draft_;
  Grammar& grammar_;
};

}  // namespace lsys::dialects
