// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "dialects/settings_reader.hpp"

#include <cmath>
#include <string>
#include <unordered_map>

#include "lsys/diagnostic.hpp"

namespace lsys::dialects {

double SettingsReader::positive(Range value, bool allow_zero) const {
  const double v = number(value);
  if (v < 0.0 || (!allow_zero && v == 0.0)) {
    fail(value.begin, std::string("expected a ") +
                          (allow_zero ? "non-negative" : "positive") +
                          " number");
  }
  return v;
}

std::int64_t SettingsReader::whole(Range value, double most) const {
  const double v = number(value);
  if (v < 0.0 || v != std::floor(v) || v > most) {
    fail(value.begin, "expected a whole number from 0 to " +
                          std::to_string(static_cast<std::int64_t>(most)));
  }
  return static_cast<std::int64_t>(v);
}

std::vector<SymbolId> SettingsReader::symbol_list(Range value) {
  std::vector<SymbolId> out;
  for (const RawModule& m : modules_.tokenize(value)) {
    if (!m.arguments.empty()) fail(m.offset, "expected module names only");
    out.push_back(m.symbol);
  }
  return out;
}

void SettingsReader::read_settings() {
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
      fail(setting.key_range.begin, "expected a value for '" + key_text + "'");
    }
    const Range v = setting.value;
    switch (setting.key) {
      case Key::Axiom:
        if (draft_.axiom) {
          fail(setting.key_range.begin,
               "duplicate axiom (the first is on line " +
                   std::to_string(source_->location(draft_.axiom->begin).line) +
                   ")");
        }
        draft_.axiom = v;
        break;
      case Key::DerivationLength:
        s.derivation_length = static_cast<int>(whole(v, kMaxDerivationLength));
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
        s.width_offset = v.begin;
        break;
      case Key::Radius:
        s.initial_width = 2.0 * positive(v, true);
        s.width_offset = v.begin;
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
        if (draft_.syntax.cpfg_statements && context_.constant(v) > 1000.0) {
          // cpfg stops at its depth as lsolid stops at 1000, the most its
          // recursion takes safely; models ask for 3000 but rarely use it.
          grammar_.warnings.push_back("maximum depth " + std::string(view(v)) +
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
    both(Key::Width, Key::Radius, "give either 'width' or 'radius', not both");
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

void SettingsReader::reject_letter_settings_of_modules() const {
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

glm::dvec3 SettingsReader::vector3(Range value) const {
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

}  // namespace lsys::dialects
