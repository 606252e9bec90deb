// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "dialects/symbols.hpp"

#include <string>

#include "lsys/diagnostic.hpp"

namespace lsys::dialects {

SymbolTable::SymbolTable(BuildContext& context)
    : TextScan(context.scan), draft_(context.draft), grammar_(context.grammar) {
  for (const RefusedName& refused : draft_.refused) {
    refused_.emplace_back(grammar_.alphabet.intern(refused.name), &refused);
  }
  for (const RefusedName& left_out : draft_.left_out) {
    left_out_.emplace(grammar_.alphabet.intern(left_out.name),
                      LeftOut{&left_out});
  }
}

void SymbolTable::read_aliases() {
  for (const Range& line : draft_.alias_lines) {
    std::size_t i = line.begin;
    while (i < line.end) {
      while (i < line.end && is_blank(text_[i])) ++i;
      if (i >= line.end) break;
      const std::size_t from_begin = i;
      while (i < line.end && !is_blank(text_[i]) && text_[i] != '=' &&
             text_.substr(i, 3) != "\u2192" && text_.substr(i, 2) != "->") {
        ++i;
      }
      const Range from{from_begin, i};
      while (i < line.end && is_blank(text_[i])) ++i;
      if (text_.substr(i, 1) == "=") {
        i += 1;
      } else if (text_.substr(i, 2) == "->") {
        i += 2;
      } else if (text_.substr(i, 3) == "\u2192") {
        i += 3;
      } else {
        fail(i, "expected '=' in an alias such as 'f=F'");
      }
      if (from.empty()) fail(from_begin, "expected a module before '='");
      while (i < line.end && is_blank(text_[i])) ++i;
      const std::size_t to_begin = i;
      while (i < line.end && !is_blank(text_[i])) ++i;
      std::string_view to = text_.substr(to_begin, i - to_begin);
      if (!notation_command(to) && to.size() > 1 && to.back() == ',') {
        to.remove_suffix(1);
      }
      const auto command = notation_command(to);
      if (to.empty()) fail(to_begin, "expected a turtle symbol after '='");
      if (!command) {
        fail(to_begin, "unknown turtle symbol '" + std::string(to) + "'");
      }
      if (*command == TurtleCommand::Push || *command == TurtleCommand::Pop ||
          *command == TurtleCommand::Cut) {
        fail(to_begin, "'" + std::string(to) + "' cannot be an alias target");
      }
      const SymbolId symbol = grammar_.alphabet.intern(view(from));
      if (symbol <= kCut) {
        fail(from_begin, "'" + std::string(view(from)) + "' cannot be aliased");
      }
      if (aliases_.count(symbol) != 0) {
        fail(from_begin,
             "duplicate alias for '" + std::string(view(from)) + "'");
      }
      aliases_.emplace(symbol, *command);
    }
  }
}

void SymbolTable::read_module_declarations() {
  for (const Range& names : draft_.module_lines) {
    for (const DeclaredName& declared : module_names(*this, names)) {
      if (declared.parameter_count == 0) continue;
      check_arity(*grammar_.alphabet.find(view(declared.name)),
                  declared.parameter_count, declared.name.begin);
    }
  }
}

std::optional<TurtleCommand> SymbolTable::notation_command(
    std::string_view name) const {
  if (draft_.symbols.empty()) return builtin_command(name);
  for (const SymbolCommand& s : draft_.symbols) {
    if (s.name == name) return s.command;
  }
  return std::nullopt;
}

TurtleCommand SymbolTable::command_of(SymbolId symbol) const {
  if (const auto it = aliases_.find(symbol); it != aliases_.end()) {
    return it->second;
  }
  return notation_command(grammar_.alphabet.name(symbol))
      .value_or(TurtleCommand::None);
}

void SymbolTable::check_arity(SymbolId symbol, int count, std::size_t offset) {
  const std::string& name = grammar_.alphabet.name(symbol);
  const TurtleCommand command = command_of(symbol);
  if (command != TurtleCommand::None) {
    const int most = max_parameters(command);
    const int least = min_parameters(command);
    if ((count > most && !draft_.syntax.extra_turtle_parameters) ||
        count < least) {
      std::string expected =
          least == most
              ? std::to_string(most)
              : (least == 0
                     ? "at most " + std::to_string(most)
                     : std::to_string(least) + " to " + std::to_string(most));
      fail(offset, "wrong parameter count: '" + name + "' takes " + expected +
                       (most == 1 ? " parameter" : " parameters") + ", here " +
                       std::to_string(count));
    }
    return;
  }
  // Lparser's parameters are text behind a module, not part of it.
  if (!draft_.syntax.fixed_arity) return;
  const auto [it, inserted] = arity_.emplace(symbol, std::pair{count, offset});
  if (inserted || it->second.first == count) return;
  const int expected = it->second.first;
  fail(offset, "wrong parameter count: '" + name + "' takes " +
                   std::to_string(expected) +
                   (expected == 1 ? " parameter" : " parameters") +
                   " (as on line " +
                   std::to_string(source_->location(it->second.second).line) +
                   "), here " + std::to_string(count));
}

void SymbolTable::reject_refused(SymbolId symbol, std::size_t offset) const {
  const std::string& name = grammar_.alphabet.name(symbol);
  for (const auto& [id, refused] : refused_) {
    // A one-character refused name that is a name's prefix refuses it
    // too: a predecessor `~f(t)` names cpfg's surface `~` with `f`.
    const bool prefix =
        refused->name.size() == 1 && !is_word_char(refused->name.front()) &&
        name.starts_with(refused->name) && !notation_command(name);
    if (id != symbol && !prefix) continue;
    std::string message = "'";
    message += refused->name;
    message += "' (";
    message += refused->what;
    message += ") is not supported by lsolid";
    fail(offset, std::move(message));
  }
}

void SymbolTable::build_commands() {
  grammar_.commands.resize(grammar_.alphabet.size());
  grammar_.default_parameters.resize(grammar_.alphabet.size());
  if (draft_.syntax.extra_turtle_parameters) {
    grammar_.parameters_read.resize(grammar_.alphabet.size());
  }
  for (SymbolId s = 0; s < grammar_.alphabet.size(); ++s) {
    grammar_.commands[s] = command_of(s);
    if (draft_.syntax.extra_turtle_parameters &&
        grammar_.commands[s] != TurtleCommand::None) {
      grammar_.parameters_read[s] = max_parameters(grammar_.commands[s]);
    }
    if (aliases_.count(s) != 0) continue;
    for (const SymbolCommand& symbol : draft_.symbols) {
      if (symbol.name == grammar_.alphabet.name(s)) {
        grammar_.default_parameters[s] = symbol.default_parameter;
        if (symbol.parameters_read && draft_.syntax.extra_turtle_parameters) {
          grammar_.parameters_read[s] = symbol.parameters_read;
        }
      }
    }
  }
}

bool SymbolTable::use_if_left_out(SymbolId symbol) {
  const auto it = left_out_.find(symbol);
  if (it == left_out_.end()) return false;
  ++it->second.uses;
  return true;
}

void SymbolTable::warn_of_left_out() {
  for (const auto& [symbol, left_out] : left_out_) {
    if (left_out.uses == 0) continue;
    std::string warning = "'";
    warning += left_out.name->name;
    warning += "' (";
    warning += left_out.name->what;
    warning += ") is left out: it draws nothing in a solid";
    grammar_.warnings.push_back(std::move(warning));
  }
}

}  // namespace lsys::dialects
