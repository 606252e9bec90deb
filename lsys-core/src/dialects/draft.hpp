// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <cstddef>
#include <functional>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <string_view>
#include <unordered_set>
#include <utility>
#include <vector>

#include "dialects/text_scan.hpp"
#include "lsys/expression.hpp"
#include "lsys/settings.hpp"
#include "lsys/turtle_command.hpp"

namespace lsys::dialects {

/// Where a production goes.
enum class Section { Productions, Decomposition, Homomorphism, Aliases };

/// The settings a front end can hand over as text.
enum class Key {
  Axiom,
  DerivationLength,
  Angle,
  AngleFactor,
  Step,
  Width,
  Radius,
  WidthIncrement,
  WidthFactor,
  WidthScale,
  WidthPerGeneration,
  RadiusPerGeneration,
  Color,
  Tropism,
  Elasticity,
  Seed,
  Roll,
  MaximumDepth,
  HomomorphismDepth,
  Ignore,
  Consider,
  LsystemLabel,
  Extra
};

/// A setting as written: its key, where the key and the value stand.
struct SettingText {
  Key key;
  std::string extra_key;  ///< the client's name, for Key::Extra
  Range key_range;
  Range value;
};

/// A production as written, before the successor is read.
struct ProductionText {
  Range lhs;
  std::optional<Range> probability;  ///< ABOP's -(p)→
  std::vector<Range> rhs;            ///< continuation lines append
  Section section = Section::Productions;
  /// L-Py's rule body in Python, when the rule has one: each of its
  /// `produce` statements is a production of its own, with the body as its
  /// statements and `produce == python_branch` as its condition
  /// (parse_python_statements); rhs is that produce's successor.
  std::optional<Range> python_body;
  int python_branch = 0;
  /// How many productions the body makes (its `produce` statements).
  int python_branches = 0;
  /// The body builds its successor as it runs (`nproduce`,
  /// Production::successor_from_body): one production, rhs an empty
  /// range.
  bool python_builds = false;
  /// The body is lpfg's C++ (`{ … produce …; }`), read as cpfg's
  /// statements; python_builds is then set too.
  bool c_body = false;
};

/// A name of a `module` line, and the parameter count its list gives.
struct DeclaredName {
  Range name;
  int parameter_count = 0;  ///< of `bud(x)`; 0 without a list
};

/// A module's name and the command it has in a notation.
struct SymbolCommand {
  std::string_view name;
  TurtleCommand command;
  /// The parameter a bare module has in this notation (Lparser's `'`
  /// multiplies the length by 0.9); none when the command has its own.
  std::optional<double> default_parameter;
  /// How many parameters the turtle reads, where the notation ignores any
  /// more (Syntax::extra_turtle_parameters); the command's most if absent.
  std::optional<int> parameters_read;
};

/// A module a notation names but lsolid cannot build (L-Py's `@O`
/// sphere): refused where it stands rather than split into letters.
struct RefusedName {
  std::string_view name;
  std::string_view what;  ///< "a sphere"
};

/// A parameter written without parentheses, as Fractint writes `\30` and
/// `C5`: where its text ends and its value.
struct InlineParameter {
  std::size_t end;
  double value;
};

/// What the notation's productions and modules may hold beyond a
/// predecessor and a string of single-character modules.
struct Syntax {
  /// `lc < pred > rc : condition` on the left of the arrow; without them
  /// the left side is the predecessor as written (Lparser's `<` rolls).
  bool contexts_and_conditions = true;
  /// cpfg's `succ : probability` (Lparser's `:` scales the angle).
  bool probability_after_successor = true;
  /// `F(1, 2)`; without them `(` and `)` are modules (Fractint).
  bool parameter_lists = true;
  /// `%` cuts the branch and `*` is any module in a context; without them
  /// both are modules of the notation's table (Lparser's `%` rolls 180°).
  bool cut_and_wildcard = true;
  /// A module other than the turtle's takes the same number of parameters
  /// everywhere; without it, any (Lparser's parameters are text behind it).
  bool fixed_arity = true;
  /// Trigonometric functions in radians (L-Py's Python), not degrees.
  bool radians = false;
  /// A turtle symbol may carry more parameters than it reads, and the turtle
  /// ignores the rest (cpfg: `+(20,0)`, `@Ts(1,e)`).
  bool extra_turtle_parameters = false;
  /// cpfg's expressions and statements: `%`, `?:`, random functions,
  /// blocks `{ … }` around a condition, global variables.
  bool cpfg_statements = false;
  /// L-system Explorer's mathjs expressions: `and`, `or`, `not`, `mod`,
  /// and statements without a last `;` (ExpressionScope::mathjs).
  bool mathjs = false;
  /// Every module is one character besides the notation's own names
  /// (cpfg: `FA` is F then A, `@Gc` one module). Without it, a
  /// predecessor's name is one module, however long.
  bool single_character_modules = false;
  /// A production's predecessor may be several modules in a row, which
  /// the successor replaces together (cpfg's and L-Py's).
  bool several_module_predecessors = false;
  /// cpfg's `=` in a right context skips to the end of the current branch
  /// (`A > [B=]C`, `A > F=]g`); without it `=` is a module.
  bool skip_to_branch_end = false;
  /// Python's expressions (ExpressionScope::python), as L-Py writes them.
  bool python = false;
  /// lpfg's C++ in statements and bodies (ExpressionScope::c_language).
  bool c_language = false;
  /// A module is a C identifier, which must be the notation's or declared
  /// (lpfg); `SB()` takes no parameters.
  bool identifier_modules = false;
  /// Only `p1:`, `P12:` are labels (L-system Explorer): `P : * → …` is the
  /// module P with the condition "always".
  bool numbered_labels = false;
};

/// When a block of cpfg's statements runs.
enum class BlockKind { Start, StartEach, EndEach, End, Define };

/// A `Start: { … }` block and its kin: the statements, braces included;
/// or cpfg's `define: { … }`, its arrays.
struct StatementBlock {
  BlockKind kind;
  Range text;
  bool python = false;  ///< L-Py's `def Start():` and its kin
};

/// What a front end hands the grammar builder: the pieces of a file sorted
/// by what they are, as places in the scanned text, and what the notation
/// itself decides (its symbols and defaults).
struct Draft {
  std::optional<Range> axiom;
  std::vector<Range> axiom_more;  ///< indented lines that continue it
  /// L-Py's axiom as a Python body of `nproduce` (Grammar::axiom_body).
  std::optional<Range> axiom_python;
  std::vector<ProductionText> productions;
  std::vector<SettingText> settings;
  std::vector<std::pair<Range, Range>> defines;  ///< name, value
  std::vector<Range> module_lines;               ///< after `module`
  std::vector<Range> alias_lines;                ///< `f=F`, `.ls` only
  /// Names of `module` lines, known while sorting lines.
  std::unordered_set<std::string> declared_modules;
  Syntax syntax;
  /// The notation's settings before the file changes any.
  Settings defaults;
  /// The notation's symbols; when empty, lsolid's (builtin_command).
  std::vector<SymbolCommand> symbols;
  /// Names the notation defines before the file does (L-Py's `True`).
  std::map<std::string, double> constants;
  /// Modules refused wherever they appear.
  std::vector<RefusedName> refused;
  /// Modules that draw nothing in a solid and whose arguments are not read
  /// (L-Py's label `@L("text")`), left out with a warning.
  std::vector<RefusedName> left_out;
  /// Names among `defines` that statements assign (L-system Explorer's
  /// variables): global variables that start at their value, not
  /// constants.
  std::unordered_set<std::string> variables;
  /// L-Py: the names `import math as m` and `import random as rd` bind.
  std::vector<std::string> python_modules;
  /// Names bound by L-Py's imports of modules other than math and random
  /// (ExpressionScope::python_imports).
  std::map<std::string, std::string> python_imports;
  /// L-Py's functions of one `return`, by name.
  std::map<std::string, PythonFunction> python_functions;
  /// L-Py's lists of numbers at the top level (`color = [1, 3, 2]`): the
  /// name and the elements, which rules index (`color[m]`).
  struct PythonList {
    Range name;
    std::vector<Range> elements;
  };
  std::vector<PythonList> python_lists;
  /// L-Py's top-level `assert c`: conditions over constants that must hold.
  std::vector<Range> assertions;
  /// cpfg's blocks of statements, in file order.
  std::vector<StatementBlock> blocks;
  /// cpfg's functions for `func(id, x)`, from the view file.
  std::shared_ptr<const FunctionTable> functions;
  /// Things the front end left out, for the caller to show.
  std::vector<std::string> warnings;
  /// Reads a parameter written without parentheses after a module name at
  /// `at`, if the notation has such and one stands there.
  std::function<std::optional<InlineParameter>(std::string_view name,
                                               std::size_t at, Range r)>
      inline_parameter;
};

/// The names of a `module` line: `plant, internode seg, bud(x)`.
/// @throws ParseError for an unclosed `(`.
[[nodiscard]] std::vector<DeclaredName> module_names(const TextScan& scan,
                                                     Range names);

}  // namespace lsys::dialects
