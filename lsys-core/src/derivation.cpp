// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Parallel rewriting (ABOP §1.1) in two ways. Context-free grammars stream
// depth-first: the n-th string is the left-to-right walk of the derivation
// tree, so only one path of successors is held at a time (seed 004,
// "tree-based structure"). Context-sensitive grammars (ABOP §1.8, p. 32 for
// bracketed contexts) and grammars with cuts (`%`, ABOP p. 73) rewrite the
// whole string each step. Stochastic choices (ABOP §1.7) are keyed by the
// module's place in its string (lsys/random.hpp), so both ways agree.
#include "lsys/derivation.hpp"

#include <algorithm>
#include <string>

#include "lsys/diagnostic.hpp"
#include "lsys/random.hpp"
#include "queries.hpp"
#include "rule_index.hpp"
#include "size_model.hpp"

namespace lsys {

class Derivation::Impl {
 public:
  Impl(const Grammar& grammar, const DerivationOptions& options)
      : grammar_(grammar),
        options_(options),
        n_(options.derivation_length.value_or(
            grammar.settings.derivation_length)),
        seed_(options.seed.value_or(grammar.settings.seed)),
        productions_(grammar.productions, grammar.alphabet.size()),
        decompositions_(grammar.decompositions, grammar.alphabet.size()),
        costs_(grammar, false) {
    for (const Production& p : grammar.productions) {
      is_context_sensitive_ = is_context_sensitive_ || p.is_context_sensitive();
      if (p.probability) {
        is_stochastic_ = true;
        if (stochastic_symbol_.empty()) {
          stochastic_symbol_.resize(grammar.alphabet.size(), false);
        }
        stochastic_symbol_[p.predecessor.symbol] = true;
      }
    }
    // cpfg's variables and random numbers make each value depend on what
    // was rewritten before it: the string is rewritten in cpfg's order.
    // A query's answer depends on the whole string before it, drawn.
    has_queries_ = uses_queries(grammar);
    is_streaming_ = !is_context_sensitive_ && !has_cut(grammar) &&
                    !grammar.uses_variables && !has_queries_;
    variables_ = initial_variables(grammar);
    check_prediction();
    if (is_streaming_) {
      expanded_.assign(static_cast<std::size_t>(n_) + 1, 0);
      emitted_.assign(static_cast<std::size_t>(n_) + 1, 0);
      push(grammar_.axiom, {}, 0, 0);
    }
  }

  bool next(ModuleString& chunk, std::size_t chunk_size) {
    chunk.clear();
    if (is_streaming_) {
      stream(chunk, chunk_size);
    } else {
      if (!materialised_) materialise();
      const std::size_t end = std::min(string_.size(), served_ + chunk_size);
      for (; served_ < end; ++served_) chunk.push_back(string_, served_);
    }
    return !chunk.empty();
  }

  int derivation_length() const noexcept { return n_; }
  Variables* variables() noexcept { return &variables_; }
  bool is_streaming() const noexcept { return is_streaming_; }
  const std::optional<SizePrediction>& prediction() const noexcept {
    return prediction_;
  }

 private:
  struct Frame {
    const Successor* successor;
    const double* values;
    std::uint32_t position;
    std::uint32_t step;
    std::uint32_t depth;
  };

  [[noreturn]] void refuse(const std::string& what) const {
    throw limit_error(grammar_, options_, n_, what);
  }

  static constexpr const char* kWhole =
      "with contexts or cuts, the whole string is rewritten each step";

  std::string memory_text() const {
    return std::to_string(options_.max_memory_bytes >> 20U) + " MiB";
  }

  // Refuses before `out` grows past the memory limit with one more module
  // of `parameters` values, counting the other string and bracket matching.
  void check_room(const ModuleString& out, std::size_t parameters) {
    std::size_t held =
        out.memory_bytes_after_push(parameters) +
        (match_.capacity() + open_.capacity()) * sizeof(std::size_t);
    if (&out != &string_) held += string_.memory_bytes();
    // A module string indexes its values with 32 bits.
    constexpr std::size_t kMostValues = 0xFFFFFFFFU;
    if (held > options_.max_memory_bytes ||
        out.parameter_count() + parameters > kMostValues) {
      refuse_memory(step_, out.size());
    }
  }

  [[noreturn]] void refuse_memory(int step, std::size_t modules) {
    string_ = ModuleString();
    match_ = {};
    refuse("needs more than the limit of " + memory_text() +
           " (--max-memory) in step " + std::to_string(step + 1) +
           (modules > 0 ? ", at " + std::to_string(modules) + " modules" : "") +
           "; " + kWhole);
  }

  // Refuses at once when the exact size, or a lower bound of it, is above a
  // limit; where the size is exact and within the limits, nothing needs
  // counting while deriving.
  void check_prediction() {
    if (grammar_.uses_variables) return;  // sizes depend on the variables
    prediction_ = exact_size(grammar_, n_);
    const std::optional<SizePrediction> bound =
        prediction_ ? prediction_ : size_lower_bound(grammar_, n_);
    if (!bound) return;
    const std::string at_least = prediction_ ? "" : "at least ";
    const auto max_modules = static_cast<double>(options_.max_modules);
    const auto max_segments = static_cast<double>(options_.max_segments);
    if (bound->segments > max_segments) {
      refuse("would draw " + at_least + count_text(bound->segments) +
             " segments, more than the limit of " + count_text(max_segments) +
             " (--max-segments)");
    }
    if (bound->modules > max_modules) {
      refuse("would derive a string of " + at_least +
             count_text(bound->modules) + " modules, more than the limit of " +
             count_text(max_modules) + " (--max-modules)");
    }
    // A string held whole takes at least 16 bytes a module.
    constexpr double kLeastBytesPerModule = 16.0;
    if (!is_streaming_ && bound->modules * kLeastBytesPerModule >
                              static_cast<double>(options_.max_memory_bytes)) {
      refuse("would hold a string of " + at_least + count_text(bound->modules) +
             " modules, more than the limit of " + memory_text() +
             " (--max-memory); " + kWhole);
    }
    if (prediction_) is_counting_ = false;
  }

  void count(SymbolId symbol) {
    if (++modules_ > options_.max_modules) {
      refuse("derives more than the limit of " +
             count_text(static_cast<double>(options_.max_modules)) +
             " modules (--max-modules)");
    }
    // A bound is no count: the interpreter counts what it draws instead.
    if (!costs_.is_exact()) return;
    if (segment_weight_.empty())
      segment_weight_.resize(grammar_.alphabet.size(), -1.0);
    double& weight = segment_weight_[symbol];
    if (weight < 0.0) weight = costs_.segments_any_arity(symbol);
    segments_ += weight;
    if (segments_ > static_cast<double>(options_.max_segments)) {
      refuse("draws more than the limit of " +
             count_text(static_cast<double>(options_.max_segments)) +
             " segments (--max-segments)");
    }
  }

  // Chooses the production for a module: the first applicable one, or a
  // weighted choice among the applicable ones when any is stochastic
  // (weights normalised over those that apply, as cpfg does).
  template <typename Applicable, typename Position>
  const Production* choose(SymbolId symbol, std::uint32_t step,
                           const Applicable& applicable,
                           const Position& position) {
    const auto rules = productions_.rules_for(symbol);
    if (!is_stochastic_ || !stochastic_symbol_[symbol]) {
      for (const Production* rule : rules) {
        if (applicable(*rule)) return rule;
      }
      return nullptr;
    }
    candidates_.clear();
    double total = 0.0;
    for (const Production* rule : rules) {
      if (!applicable(*rule)) continue;
      const double w = rule->probability
                           ? rule->probability->evaluate(slots_, &variables_)
                           : 1.0;
      if (w < 0.0) {
        throw error_at(*grammar_.source, rule->probability->offset(),
                       "a probability cannot be negative");
      }
      // Each candidate's bound values, so that the chosen one's are in
      // slots_ without matching it again (and without running its cpfg
      // statements twice).
      if (candidate_slots_.size() <= candidates_.size()) {
        candidate_slots_.emplace_back();
      }
      candidate_slots_[candidates_.size()].assign(slots_.begin(), slots_.end());
      candidates_.emplace_back(rule, w);
      total += w;
    }
    if (candidates_.empty()) return nullptr;
    if (total <= 0.0) {
      throw error_at(*grammar_.source, candidates_.front().first->offset,
                     "the probabilities of the applicable productions of '" +
                         grammar_.alphabet.name(symbol) + "' sum to zero");
    }
    const double u = stochastic_uniform(seed_, step, position()) * total;
    double sum = 0.0;
    for (std::size_t k = 0; k < candidates_.size(); ++k) {
      sum += candidates_[k].second;
      if (u < sum || k + 1 == candidates_.size()) {
        slots_.swap(candidate_slots_[k]);
        return candidates_[k].first;
      }
    }
    return nullptr;  // not reached: the last candidate is always taken
  }

  // --- Streaming ----------------------------------------------------------

  void push(const Successor& successor, std::span<const double> slots,
            std::uint32_t step, std::uint32_t depth) {
    const std::size_t level = frames_.size();
    const double* values = successor.constant_values().data();
    if (!successor.is_constant()) {
      if (buffers_.size() <= level) buffers_.resize(level + 1);
      successor.instantiate(slots, buffers_[level]);
      values = buffers_[level].data();
    }
    frames_.push_back(Frame{&successor, values, 0, step, depth});
  }

  std::uint64_t stream_position(std::uint32_t step) const {
    std::uint64_t position = expanded_[step];
    for (std::uint32_t i = 0; i <= step; ++i) position += emitted_[i];
    return position;
  }

  void stream(ModuleString& chunk, std::size_t chunk_size) {
    const auto max_depth =
        static_cast<std::uint32_t>(grammar_.settings.maximum_depth);
    const auto n = static_cast<std::uint32_t>(n_);
    const bool has_decompositions = !grammar_.decompositions.empty();
    while (!frames_.empty() && chunk.size() < chunk_size) {
      Frame& frame = frames_.back();
      if (frame.position == frame.successor->size()) {
        frames_.pop_back();
        continue;
      }
      const std::uint32_t i = frame.position++;
      const SymbolId symbol = frame.successor->symbols()[i];
      const auto& begins = frame.successor->parameter_begins();
      const std::span<const double> params(frame.values + begins[i],
                                           begins[i + 1] - begins[i]);
      const std::uint32_t step = frame.step;
      if (has_decompositions && frame.depth < max_depth &&
          decompositions_.has_rules(symbol)) {
        if (const Production* d =
                decompositions_.first_applicable(symbol, params)) {
          push(d->successor, params, step, frame.depth + 1);
          continue;
        }
      }
      if (step < n) {
        const Production* rule = productions_.only_rule(symbol);
        if (rule == nullptr || rule->predecessor.parameter_count !=
                                   static_cast<int>(params.size())) {
          rule = choose_streaming(symbol, params, step);
        }
        if (rule != nullptr) {
          if (is_stochastic_) ++expanded_[step];
          push(rule->successor, params, step + 1, 0);
          continue;
        }
      }
      if (is_stochastic_) ++emitted_[step];
      if (is_counting_) count(symbol);
      chunk.push_back(symbol, params, step);
    }
  }

  const Production* choose_streaming(SymbolId symbol,
                                     std::span<const double> params,
                                     std::uint32_t step) {
    if (!productions_.has_rules(symbol)) return nullptr;
    slots_.assign(params.begin(), params.end());
    return choose(
        symbol, step,
        [&](const Production& rule) {
          return rule.predecessor.parameter_count ==
                     static_cast<int>(params.size()) &&
                 condition_holds(rule, slots_);
        },
        [&] { return stream_position(step); });
  }

  // --- Rewriting the whole string -----------------------------------------

  bool is_ignored(SymbolId s) const {
    if (s == kBranchOpen || s == kBranchClose) return false;
    const auto& consider = grammar_.settings.consider;
    if (!consider.empty()) {
      return std::find(consider.begin(), consider.end(), s) == consider.end();
    }
    const auto& ignore = grammar_.settings.ignore;
    return std::find(ignore.begin(), ignore.end(), s) != ignore.end();
  }

  static bool same_module(const ModuleString& s, std::size_t i,
                          const PatternModule& p) {
    if (p.symbol == kAnyModule) {
      return s.symbol(i) != kBranchOpen && s.symbol(i) != kBranchClose;
    }
    return s.symbol(i) == p.symbol &&
           s.parameters(i).size() ==
               static_cast<std::size_t>(p.parameter_count);
  }

  // ABOP p. 32: the left context skips whole branches to the left and
  // climbs out of the branch the module is in.
  bool match_left(const ModuleString& s, std::size_t i,
                  const std::vector<PatternModule>& pattern) {
    matched_.resize(pattern.size());
    std::size_t j = i;
    for (std::size_t t = pattern.size(); t-- > 0;) {
      for (;;) {
        if (j == 0) return false;
        --j;
        const SymbolId sym = s.symbol(j);
        if (sym == kBranchClose) {
          j = match_[j];
        } else if (sym != kBranchOpen && !is_ignored(sym)) {
          break;
        }
      }
      if (!same_module(s, j, pattern[t])) return false;
      matched_[t] = j;
    }
    for (std::size_t t = 0; t < pattern.size(); ++t) {
      if (pattern[t].symbol == kAnyModule) continue;  // binds nothing
      const auto p = s.parameters(matched_[t]);
      slots_.insert(slots_.end(), p.begin(), p.end());
    }
    return true;
  }

  // ABOP p. 32: the right context may enter a branch where the pattern has
  // `[`; other branches are skipped; it never leaves the current branch
  // but after cpfg's `=`, which skips to the branch's end.
  bool match_right(const ModuleString& s, std::size_t i,
                   const std::vector<PatternModule>& pattern) {
    std::size_t j = i + 1;
    open_.clear();
    for (const PatternModule& p : pattern) {
      if (p.to_branch_end) {
        // cpfg's `=` (generate.c's skipright): on to the `]` that closes
        // the current branch, or the end of the string.
        while (j < s.size() && s.symbol(j) != kBranchClose) {
          j = s.symbol(j) == kBranchOpen ? match_[j] + 1 : j + 1;
        }
        continue;
      }
      if (p.symbol == kBranchClose) {
        if (open_.empty()) {
          // After `=`, leaving the branch the predecessor stands in.
          if (j >= s.size() || s.symbol(j) != kBranchClose) return false;
          ++j;
          continue;
        }
        j = match_[open_.back()] + 1;
        open_.pop_back();
        continue;
      }
      for (;;) {
        if (j >= s.size()) return false;
        const SymbolId sym = s.symbol(j);
        if (sym == kBranchOpen && p.symbol != kBranchOpen) {
          j = match_[j] + 1;
        } else if (sym == kBranchClose) {
          return false;
        } else if (is_ignored(sym)) {
          ++j;
        } else {
          break;
        }
      }
      if (!same_module(s, j, p)) return false;
      if (p.symbol == kBranchOpen) {
        open_.push_back(j);
      } else if (p.symbol != kAnyModule) {
        const auto params = s.parameters(j);
        slots_.insert(slots_.end(), params.begin(), params.end());
      }
      ++j;
    }
    return true;
  }

  bool applies(const ModuleString& s, std::size_t i, const Production& rule) {
    slots_.clear();
    if (!rule.left_context.empty() && !match_left(s, i, rule.left_context)) {
      return false;
    }
    if (s.symbol(i) != rule.predecessor.symbol ||
        s.parameters(i).size() !=
            static_cast<std::size_t>(rule.predecessor.parameter_count)) {
      return false;
    }
    const auto params = s.parameters(i);
    slots_.insert(slots_.end(), params.begin(), params.end());
    // cpfg's predecessor of several modules matches them as they stand
    // (generate.c compares the string module by module).
    std::size_t last = i;
    for (const PatternModule& m : rule.predecessor_rest) {
      if (++last >= s.size() || !same_module(s, last, m)) return false;
      const auto more = s.parameters(last);
      slots_.insert(slots_.end(), more.begin(), more.end());
    }
    if (!rule.right_context.empty() &&
        !match_right(s, last, rule.right_context)) {
      return false;
    }
    return statements_and_condition_hold(rule, slots_, &variables_);
  }

  void compute_matches(const ModuleString& s) {
    match_.assign(s.size(), 0);
    open_.clear();
    for (std::size_t i = 0; i < s.size(); ++i) {
      if (s.symbol(i) == kBranchOpen) open_.push_back(i);
      if (s.symbol(i) == kBranchClose && !open_.empty()) {
        match_[i] = open_.back();
        match_[open_.back()] = i;
        open_.pop_back();
      }
    }
  }

  void append_decomposed(ModuleString& out, SymbolId symbol,
                         std::span<const double> params, std::uint32_t step,
                         int depth) {
    if (depth < grammar_.settings.maximum_depth &&
        decompositions_.has_rules(symbol)) {
      std::vector<double> slots;
      if (const Production* d = decompositions_.first_applicable(
              symbol, params, &variables_, &slots)) {
        if (d->successor_from_body) {
          append_emitted(out,
                         take_emitted(variables_, *grammar_.source, d->offset),
                         step, depth + 1);
          return;
        }
        std::vector<double> values;
        d->successor.instantiate(
            d->has_statements() ? std::span<const double>(slots) : params,
            values, &variables_);
        const auto& begins = d->successor.parameter_begins();
        for (std::size_t k = 0; k < d->successor.size(); ++k) {
          append_decomposed(out, d->successor.symbols()[k],
                            std::span<const double>(values).subspan(
                                begins[k], begins[k + 1] - begins[k]),
                            step, depth + 1);
        }
        return;
      }
    }
    check_room(out, params.size());
    out.push_back(symbol, params, step);
  }

  void append_emitted(ModuleString& out, const EmittedModules& modules,
                      std::uint32_t step, int depth) {
    for (std::size_t k = 0; k < modules.symbols.size(); ++k) {
      append_decomposed(out, modules.symbols[k],
                        std::span<const double>(modules.values)
                            .subspan(modules.begins[k],
                                     modules.begins[k + 1] - modules.begins[k]),
                        step, depth);
    }
  }

  void append_successor(ModuleString& out, const Successor& successor,
                        std::span<const double> slots, std::uint32_t step) {
    std::vector<double> values;
    successor.instantiate(slots, values, &variables_);
    const auto& begins = successor.parameter_begins();
    for (std::size_t k = 0; k < successor.size(); ++k) {
      append_decomposed(out, successor.symbols()[k],
                        std::span<const double>(values).subspan(
                            begins[k], begins[k + 1] - begins[k]),
                        step, 0);
    }
  }

  // ABOP p. 73: `%` removes itself and the rest of its branch. In place,
  // so that cutting needs no second copy of the string.
  static void cut(ModuleString& s) {
    if (!s.contains(kCut)) return;
    std::vector<bool> keep(s.size(), true);
    bool cutting = false;
    int depth = 0;
    for (std::size_t i = 0; i < s.size(); ++i) {
      const SymbolId sym = s.symbol(i);
      if (!cutting) {
        if (sym == kCut) {
          cutting = true;
          depth = 0;
          keep[i] = false;
        }
        continue;
      }
      if (sym == kBranchOpen) ++depth;
      if (sym == kBranchClose && depth-- == 0) {
        cutting = false;
        continue;
      }
      keep[i] = false;
    }
    s.retain(keep);
  }

  void materialise() {
    materialised_ = true;
    // Memory is checked as the strings grow; running out anyway (a smaller
    // machine than the limit assumes) is reported as the same limit.
    ModuleString next;
    try {
      materialise_steps(next);
    } catch (const std::bad_alloc&) {
      next = ModuleString();
      refuse_memory(step_, 0);
    }
  }

  void run(const std::optional<Expression>& block) {
    if (block) block->execute({}, &variables_);
  }

  void materialise_steps(ModuleString& next) {
    run(grammar_.start);
    if (grammar_.axiom_body) {
      std::vector<double> locals(
          static_cast<std::size_t>(grammar_.axiom_local_count), 0.0);
      grammar_.axiom_body->execute(locals, &variables_);
      append_emitted(
          string_,
          take_emitted(variables_, *grammar_.source, grammar_.axiom_offset), 0,
          0);
    } else {
      append_successor(string_, grammar_.axiom, {}, 0);
    }
    cut(string_);
    for (step_ = 0; step_ < n_; ++step_) {
      const int step = step_;
      variables_.iteration = step;
      // cpfg answers the queries before StartEach (generate.c's Derive).
      if (has_queries_) answer_queries(grammar_, string_, &variables_);
      run(grammar_.start_each);
      if (is_context_sensitive_) {
        if (string_.memory_bytes() + next.memory_bytes() +
                string_.size() * sizeof(std::size_t) >
            options_.max_memory_bytes) {
          refuse_memory(step, string_.size());
        }
        compute_matches(string_);
      }
      next.clear();
      const auto k = static_cast<std::uint32_t>(step);
      for (std::size_t i = 0; i < string_.size(); ++i) {
        const SymbolId symbol = string_.symbol(i);
        const Production* rule = nullptr;
        if (productions_.has_rules(symbol)) {
          rule = choose(
              symbol, k,
              [&](const Production& r) { return applies(string_, i, r); },
              [&] { return static_cast<std::uint64_t>(i); });
        }
        if (rule != nullptr && rule->successor_from_body) {
          append_emitted(
              next, take_emitted(variables_, *grammar_.source, rule->offset),
              k + 1, 0);
          i += rule->predecessor_rest.size();
        } else if (rule != nullptr) {
          append_successor(next, rule->successor, slots_, k + 1);
          i += rule->predecessor_rest.size();
        } else {
          check_room(next, string_.parameters(i).size());
          next.push_back(string_, i);
        }
        if (next.size() > options_.max_modules) {
          refuse("derives more than the limit of " +
                 count_text(static_cast<double>(options_.max_modules)) +
                 " modules (--max-modules)");
        }
      }
      cut(next);
      std::swap(string_, next);
      run(grammar_.end_each);
    }
    run(grammar_.end);
    if (is_counting_) {
      for (std::size_t i = 0; i < string_.size(); ++i) count(string_.symbol(i));
    }
  }

  const Grammar& grammar_;
  DerivationOptions options_;
  int n_;
  std::uint64_t seed_;
  RuleIndex productions_;
  RuleIndex decompositions_;
  InterpretationCosts costs_;
  std::optional<SizePrediction> prediction_;
  bool is_context_sensitive_ = false;
  bool is_stochastic_ = false;
  bool is_streaming_ = true;
  bool has_queries_ = false;
  bool is_counting_ = true;
  std::vector<bool> stochastic_symbol_;

  std::vector<Frame> frames_;
  std::vector<std::vector<double>> buffers_;
  std::vector<std::uint64_t> expanded_;
  std::vector<std::uint64_t> emitted_;

  bool materialised_ = false;
  int step_ = 0;  // of the whole-string derivation, for messages
  ModuleString string_;
  std::size_t served_ = 0;
  std::vector<std::size_t> match_;
  std::vector<std::size_t> open_;
  std::vector<std::size_t> matched_;

  std::vector<double> slots_;
  Variables variables_;
  std::vector<std::pair<const Production*, double>> candidates_;
  std::vector<std::vector<double>> candidate_slots_;
  std::uint64_t modules_ = 0;
  double segments_ = 0.0;
  std::vector<double> segment_weight_;
};

Derivation::Derivation(const Grammar& grammar, const DerivationOptions& options)
    : impl_(std::make_unique<Impl>(grammar, options)) {}

Derivation::~Derivation() = default;

bool Derivation::next(ModuleString& chunk, std::size_t chunk_size) {
  return impl_->next(chunk, chunk_size);
}

int Derivation::derivation_length() const noexcept {
  return impl_->derivation_length();
}

bool Derivation::is_streaming() const noexcept { return impl_->is_streaming(); }

Variables* Derivation::variables() noexcept { return impl_->variables(); }

const std::optional<SizePrediction>& Derivation::prediction() const noexcept {
  return impl_->prediction();
}

ModuleString derive(const Grammar& grammar, const DerivationOptions& options) {
  Derivation derivation(grammar, options);
  ModuleString all;
  ModuleString chunk;
  while (derivation.next(chunk)) {
    for (std::size_t i = 0; i < chunk.size(); ++i) all.push_back(chunk, i);
  }
  return all;
}

}  // namespace lsys
