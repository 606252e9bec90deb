// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <optional>

#include "dialects/build_context.hpp"
#include "dialects/modules.hpp"

namespace lsys::dialects {

/// Reads the productions, decompositions and homomorphisms: each rule's
/// label, contexts, predecessor, condition, statements, probability and
/// successor.
class ProductionReader : protected TextScan {
 public:
  ProductionReader(BuildContext& context, ModuleReader& modules)
      : TextScan(context.scan),
        context_(context),
        draft_(context.draft),
        grammar_(context.grammar),
        modules_(modules) {}

  /// Interns each rule's predecessor as one name, so that the tokeniser
  /// finds names of several characters (`plant`) wherever they stand.
  void declare_names();
  /// Reads one rule into the grammar's productions, decompositions or
  /// homomorphisms.
  /// @throws ParseError at what cannot be read.
  void read_production(const ProductionText& text);

 private:
  // A rule's left-hand side, split.
  struct Lhs {
    Range left;
    Range predecessor;
    Range right;
    std::optional<Range> condition;
    std::optional<Range> before;  // cpfg: `{ … } condition { … }`
    std::optional<Range> after;
  };

  bool is_label_word(Range r) const;
  // Houdini's parameter pane's `Rule 1` (any case), before a production.
  bool is_field_label(Range r) const;
  bool is_constant_condition(Range r) const;
  Range strip_label(Range lhs) const;
  Range strip_numbered_label(Range lhs) const;
  std::size_t closing_brace(Range r, std::size_t open) const;
  void split_blocks(Lhs& out) const;
  Lhs split_lhs(Range lhs_with_label) const;

  BuildContext& context_;
  Draft& draft_;
  Grammar& grammar_;
  ModuleReader& modules_;
};

}  // namespace lsys::dialects
