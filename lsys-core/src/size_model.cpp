// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Growth of L-systems by counting modules (ABOP §1.2, growth functions): the
// number of each kind of module after step k+1 is v(k)·M, where row a of M
// counts the modules that one module of kind a becomes. Exact for D0L-like
// systems; with conditions, probabilities or contexts, the entrywise
// smallest alternative gives a lower bound that still refuses hopeless
// derivations at once.
#include "size_model.hpp"

#include <algorithm>
#include <array>
#include <charconv>

namespace lsys {
namespace {

bool is_drawing(TurtleCommand c) {
  return c == TurtleCommand::Draw || c == TurtleCommand::DrawNoVertex ||
         c == TurtleCommand::DrawHalf;
}

bool is_deterministic(const Grammar& g) {
  for (const auto* rules : {&g.productions, &g.decompositions}) {
    for (const Production& p : *rules) {
      if (p.is_conditional() || p.probability || p.is_context_sensitive()) {
        return false;
      }
    }
  }
  for (const Production& p : g.homomorphisms) {
    if (p.is_conditional()) return false;
  }
  return true;
}

using Counts = std::vector<double>;

void add(Counts& to, const Counts& from, double times = 1.0) {
  if (to.size() < from.size()) to.resize(from.size(), 0.0);
  for (std::size_t i = 0; i < from.size(); ++i) {
    to[i] = std::min(kHugeCount, to[i] + times * from[i]);
  }
}

// The entrywise minimum; missing entries are zero.
Counts entrywise_min(const Counts& a, const Counts& b) {
  Counts out(std::min(a.size(), b.size()));
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = std::min(a[i], b[i]);
  return out;
}

class CountMatrix {
 public:
  CountMatrix(const Grammar& g, bool is_lower_bound)
      : grammar_(g),
        productions_(g.productions, g.alphabet.size()),
        decompositions_(g.decompositions, g.alphabet.size()),
        costs_(g, is_lower_bound),
        is_lower_bound_(is_lower_bound) {}

  SizePrediction predict(int n) {
    Counts v;
    const Successor& axiom = grammar_.axiom;
    for (std::size_t i = 0; i < axiom.size(); ++i) {
      add(v, decomposed(kind(axiom, i), 0));
    }
    // Computing a row may add kinds, so rows are filled on demand.
    std::vector<Counts> rows;
    for (int step = 0; step < n; ++step) {
      Counts next;
      for (std::size_t k = 0; k < v.size(); ++k) {
        if (v[k] == 0.0) continue;
        while (rows.size() <= k) rows.push_back(row(rows.size()));
        add(next, rows[k], v[k]);
      }
      v = std::move(next);
    }
    SizePrediction p{.is_exact = !is_lower_bound_};
    for (std::size_t k = 0; k < v.size(); ++k) {
      const InterpretationCost c =
          costs_.cost(kinds_[k].first, kinds_[k].second);
      p.modules = std::min(kHugeCount, p.modules + v[k]);
      p.segments = std::min(kHugeCount, p.segments + v[k] * c.segments);
      p.interpreted_modules =
          std::min(kHugeCount, p.interpreted_modules + v[k] * c.modules);
    }
    return p;
  }

 private:
  std::size_t kind(SymbolId symbol, int arity) {
    const auto key = std::pair{symbol, arity};
    const auto it = index_.find(key);
    if (it != index_.end()) return it->second;
    kinds_.push_back(key);
    index_.emplace(key, kinds_.size() - 1);
    return kinds_.size() - 1;
  }
  std::size_t kind(const Successor& successor, std::size_t i) {
    return kind(successor.symbols()[i],
                static_cast<int>(successor.parameters(i).size()));
  }

  Counts identity(std::size_t k) const {
    Counts out(k + 1, 0.0);
    out[k] = 1.0;
    return out;
  }

  // What one module of kind k becomes under `rules` (each successor module
  // mapped by `each`): exactly the first rule in exact mode, the entrywise
  // least alternative (or itself, where no rule needs to apply) otherwise.
  template <typename Each>
  Counts rewrite(const RuleIndex& rules, std::size_t k, const Each& each) {
    bool may_stay = true;
    std::optional<Counts> least;
    for (const Production* rule : rules.rules_for(kinds_[k].first)) {
      if (rule->predecessor.parameter_count != kinds_[k].second) continue;
      Counts result;
      for (std::size_t i = 0; i < rule->successor.size(); ++i) {
        add(result, each(kind(rule->successor, i)));
      }
      if (!is_lower_bound_) return result;  // deterministic: the first rule
      least = least ? entrywise_min(*least, result) : result;
      if (!rule->is_conditional() && !rule->is_context_sensitive())
        may_stay = false;
    }
    if (!least) return identity(k);
    return may_stay ? entrywise_min(*least, identity(k)) : *least;
  }

  Counts decomposed(std::size_t k, int depth) {
    if (depth >= grammar_.settings.maximum_depth ||
        !decompositions_.has_rules(kinds_[k].first)) {
      return identity(k);
    }
    const auto key = std::pair{k, depth};
    if (const auto it = decomposed_.find(key); it != decomposed_.end()) {
      return it->second;
    }
    Counts out = rewrite(decompositions_, k, [&](std::size_t child) {
      return decomposed(child, depth + 1);
    });
    decomposed_.emplace(key, out);
    return out;
  }

  Counts row(std::size_t k) {
    if (!productions_.has_rules(kinds_[k].first)) return identity(k);
    return rewrite(productions_, k,
                   [&](std::size_t child) { return decomposed(child, 0); });
  }

  const Grammar& grammar_;
  RuleIndex productions_;
  RuleIndex decompositions_;
  InterpretationCosts costs_;
  bool is_lower_bound_;
  std::vector<std::pair<SymbolId, int>> kinds_;
  std::map<std::pair<SymbolId, int>, std::size_t> index_;
  std::map<std::pair<std::size_t, int>, Counts> decomposed_;
};

}  // namespace

bool has_cut(const Grammar& g) {
  const auto successor_has_cut = [](const Successor& s) {
    return std::find(s.symbols().begin(), s.symbols().end(), kCut) !=
           s.symbols().end();
  };
  if (successor_has_cut(g.axiom)) return true;
  for (const auto* rules : {&g.productions, &g.decompositions}) {
    for (const Production& p : *rules) {
      if (successor_has_cut(p.successor)) return true;
    }
  }
  return false;
}

InterpretationCosts::InterpretationCosts(const Grammar& grammar,
                                         bool is_lower_bound)
    : grammar_(grammar),
      homomorphisms_(grammar.homomorphisms, grammar.alphabet.size()),
      is_lower_bound_(is_lower_bound) {
  std::map<SymbolId, int> arity;
  for (const Production& p : grammar.homomorphisms) {
    const auto [it, first] =
        arity.emplace(p.predecessor.symbol, p.predecessor.parameter_count);
    if (p.is_conditional() || p.probability ||
        (!first && it->second != p.predecessor.parameter_count)) {
      is_exact_ = false;
    }
  }
}

InterpretationCost InterpretationCosts::cost(SymbolId symbol, int arity,
                                             int depth) {
  const auto key = std::tuple{symbol, arity, depth};
  if (const auto it = memo_.find(key); it != memo_.end()) return it->second;
  const InterpretationCost itself{
      is_drawing(grammar_.commands[symbol]) ? 1.0 : 0.0, 1.0};
  std::optional<InterpretationCost> result;
  bool may_stay = true;
  if (depth < grammar_.settings.homomorphism_depth.value_or(
                  grammar_.settings.maximum_depth)) {
    for (const Production* rule : homomorphisms_.rules_for(symbol)) {
      if (rule->predecessor.parameter_count != arity) continue;
      InterpretationCost sum;
      const Successor& successor = rule->successor;
      for (std::size_t i = 0; i < successor.size(); ++i) {
        const InterpretationCost c =
            cost(successor.symbols()[i],
                 static_cast<int>(successor.parameters(i).size()), depth + 1);
        sum.segments = std::min(kHugeCount, sum.segments + c.segments);
        sum.modules = std::min(kHugeCount, sum.modules + c.modules);
      }
      if (!result) {
        result = sum;
      } else if (is_lower_bound_) {
        result->segments = std::min(result->segments, sum.segments);
        result->modules = std::min(result->modules, sum.modules);
      } else {
        result->segments = std::max(result->segments, sum.segments);
        result->modules = std::max(result->modules, sum.modules);
      }
      if (!rule->is_conditional()) {
        may_stay = false;
        break;  // later rules never apply
      }
    }
  }
  InterpretationCost out = result.value_or(itself);
  if (result && may_stay) {
    const auto pick = [&](double a, double b) {
      return is_lower_bound_ ? std::min(a, b) : std::max(a, b);
    };
    out = {pick(out.segments, itself.segments),
           pick(out.modules, itself.modules)};
  }
  memo_[key] = out;
  return out;
}

double InterpretationCosts::segments_any_arity(SymbolId symbol) {
  double best = cost(symbol, 0).segments;
  for (const Production* rule : homomorphisms_.rules_for(symbol)) {
    best = std::max(best,
                    cost(symbol, rule->predecessor.parameter_count).segments);
  }
  return best;
}

std::optional<SizePrediction> exact_size(const Grammar& grammar, int n) {
  if (!is_deterministic(grammar) || has_cut(grammar)) return std::nullopt;
  return CountMatrix(grammar, false).predict(n);
}

std::optional<SizePrediction> size_lower_bound(const Grammar& grammar, int n) {
  if (has_cut(grammar)) return std::nullopt;
  // A predecessor of several modules takes its followers with it, which a
  // count per module cannot bound.
  if (std::any_of(
          grammar.productions.begin(), grammar.productions.end(),
          [](const Production& p) { return !p.predecessor_rest.empty(); })) {
    return std::nullopt;
  }
  return CountMatrix(grammar, true).predict(n);
}

std::string count_text(double value) {
  if (value >= kHugeCount) return "more than 1e+300";
  if (value < 1e15) return std::to_string(static_cast<std::uint64_t>(value));
  std::array<char, 32> buffer{};
  const auto r = std::to_chars(buffer.data(), buffer.data() + buffer.size(),
                               value, std::chars_format::scientific, 2);
  return std::string(buffer.data(), r.ptr);
}

ParseError limit_error(const Grammar& grammar, const DerivationOptions& options,
                       int n, const std::string& what) {
  std::size_t offset = grammar.axiom_offset;
  if (!options.derivation_length && grammar.settings.derivation_length_offset) {
    offset = *grammar.settings.derivation_length_offset;
  }
  return error_at(*grammar.source, offset,
                  "n = " + std::to_string(n) + " " + what);
}

}  // namespace lsys
