// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The second pass every notation shares: once a front end has sorted a
// file's lines into a draft, the passes of the build (build_context.hpp)
// read its names, settings, blocks, axiom and rules into one Grammar.
#include "dialects/grammar_builder.hpp"

#include <algorithm>
#include <set>
#include <string_view>
#include <unordered_map>
#include <unordered_set>
#include <utility>

#include "dialects/blocks.hpp"
#include "dialects/build_context.hpp"
#include "dialects/modules.hpp"
#include "dialects/productions.hpp"
#include "dialects/settings_reader.hpp"
#include "dialects/symbols.hpp"
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

// Runs the passes over a front end's draft, in the order their results are
// needed: constants first (labels are told from conditions over
// constants), then the names (so that the tokeniser knows every module),
// settings, blocks, the axiom and the rules, and last each symbol's
// command.
class GrammarBuilder : TextScan {
 public:
  GrammarBuilder(const TextScan& scan, Draft draft, const ParseOptions& options)
      : TextScan(scan),
        context_(scan, std::move(draft), options),
        draft_(context_.draft),
        options_(context_.options),
        grammar_(context_.grammar) {}

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
    SymbolTable symbols(context_);  // interns the refused and left out
    ModuleReader modules(context_, symbols);
    ProductionReader productions(context_, modules);
    SettingsReader settings(context_, modules);
    grammar_.warnings = draft_.warnings;
    grammar_.constants = draft_.constants;
    evaluate_defines();  // labels are told from conditions over constants
    for (const Range& a : draft_.assertions) {
      if (context_.constant(a) == 0.0) {
        fail(a.begin, "this assertion fails: " + std::string(view(a)));
      }
    }
    productions.declare_names();
    symbols.read_aliases();
    symbols.read_module_declarations();
    settings.read_settings();
    BlockReader(context_).read_blocks();
    read_axiom(modules);
    grammar_.productions.reserve(draft_.productions.size());
    for (const ProductionText& p : draft_.productions) {
      productions.read_production(p);
    }
    settings.reject_letter_settings_of_modules();
    symbols.build_commands();
    symbols.warn_of_left_out();
    for (const auto& [name, at] : context_.undefined) {
      grammar_.warnings.push_back(
          "line " + std::to_string(source_->location(at).line) + ": '" + name +
          "' is not defined: taken as 0, as cpfg takes it");
    }
    note_variables();
    for (const std::string& name : given_defines_) {
      if (context_.used_constants.count(name) == 0 &&
          !file_defines_.count(name)) {
        grammar_.warnings.push_back("--define " + name +
                                    ": the file neither defines nor uses '" +
                                    name + "'");
      }
    }
    return std::move(grammar_);
  }

 private:
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
      const Expression value = parse_expression(
          source, equals + 1, define.size(),
          ExpressionScope{.constants = &grammar_.constants,
                          .used_constants = &context_.used_constants,
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
        grammar_.initial_globals.push_back(
            value.empty() ? 0.0 : context_.constant(value));
        continue;
      }
      grammar_.constants[name] = context_.constant(value);
    }
  }

  void read_axiom(ModuleReader& modules) {
    if (draft_.axiom_python) {
      std::vector<std::string> locals;
      ExpressionScope scope = context_.statement_scope(
          ExpressionScope{.constants = &grammar_.constants,
                          .used_constants = &context_.used_constants,
                          .radians = draft_.syntax.radians},
          &locals);
      modules.read_successors_into(scope, grammar_.axiom);
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
    const ExpressionScope scope = context_.statement_scope(
        ExpressionScope{.constants = &grammar_.constants,
                        .used_constants = &context_.used_constants,
                        .radians = draft_.syntax.radians,
                        .mathjs = draft_.syntax.mathjs},
        nullptr);
    std::vector<Range> ranges{*draft_.axiom};
    ranges.insert(ranges.end(), draft_.axiom_more.begin(),
                  draft_.axiom_more.end());
    grammar_.axiom = modules.modules(ranges, scope);
    grammar_.axiom_offset = draft_.axiom->begin;
  }

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

  BuildContext context_;
  Draft& draft_;
  const ParseOptions& options_;
  Grammar& grammar_;
  std::vector<std::string> given_defines_;
  std::set<std::string> file_defines_;
};

}  // namespace

Grammar build_grammar(const TextScan& scan, Draft draft,
                      const ParseOptions& options) {
  return GrammarBuilder(scan, std::move(draft), options).run();
}

}  // namespace lsys::dialects
