// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstdint>
#include <glm/vec3.hpp>
#include <vector>

#include "dialects/build_context.hpp"
#include "dialects/modules.hpp"

namespace lsys::dialects {

/// Reads the settings a front end found (`n`, `angle`, `width`, `seed`,
/// `ignore` …) into the grammar's Settings, each checked once: a value out
/// of range, a setting given twice or two that contradict are refused at
/// their place.
class SettingsReader : protected TextScan {
 public:
  SettingsReader(BuildContext& context, ModuleReader& modules)
      : TextScan(context.scan),
        context_(context),
        draft_(context.draft),
        grammar_(context.grammar),
        modules_(modules) {}

  /// Reads every setting of the draft (an axiom given as a setting goes to
  /// the draft's axiom).
  /// @throws ParseError at a bad value or a setting given twice.
  void read_settings();
  /// `N=2` where the file also has a module N reads both as the setting n
  /// and as Fractint's production N → 2: refused as ambiguous, once every
  /// module is known.
  /// @throws ParseError at the setting.
  void reject_letter_settings_of_modules() const;

 private:
  double number(Range value) const { return context_.constant(value); }
  double positive(Range value, bool allow_zero) const;
  std::int64_t whole(Range value, double most) const;
  std::vector<SymbolId> symbol_list(Range value);
  glm::dvec3 vector3(Range value) const;

  BuildContext& context_;
  Draft& draft_;
  Grammar& grammar_;
  ModuleReader& modules_;
  std::vector<SettingText> letter_settings_;  // `n=2`: one letter and `=`
};

}  // namespace lsys::dialects
