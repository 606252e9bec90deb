// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// L-system Explorer (github.com/Lowclouds/lsystem), a browser program that
// follows ABOP and cpfg's manual: C comments and `#define` through a
// cpp-like preprocessor that keeps `//` (two rolls), settings and variables
// as `name = value` lines before the axiom, productions as cpfg writes
// them, with `{ … }` statement blocks around a condition, and mathjs for
// expressions (`and`, `or`, `not`, trigonometry in radians). Its turtle
// widths are diameters; bare `#` adds 1 and bare `!` takes 0.1 away
// (interpret.js). What it draws and lsolid cannot is refused by name
// (docs/dialects/lowclouds.md).
#include "dialects/c_preprocessor.hpp"
#include "dialects/companion_files.hpp"
#include "dialects/front_ends.hpp"

namespace lsys::dialects {
namespace {

// cpfg's symbols, with three that L-system Explorer lists and does not
// implement, so that they change nothing there either: texture and scale.
// Its `}(id)` also keeps the polygon as a mesh by that name, and its
// `!(w, 1)` and `#(w, 1)` set the width without a taper: the extra
// parameters are ignored.
const std::vector<SymbolCommand> kSymbols = [] {
  std::vector<SymbolCommand> symbols = cpfg_turtle_symbols();
  symbols.insert(symbols.end(),
                 {
                     {"@Tx", TurtleCommand::None, std::nullopt, std::nullopt},
                     // Its sphere is 1 across unless told (turtle3d.js).
                     {"@O", TurtleCommand::Sphere, 1.0, 1},
                     // Its disc too, in the heading–up plane.
                     {"@o", TurtleCommand::DiscAcrossLeft, 1.0, 1},
                     {"@D", TurtleCommand::None, std::nullopt, std::nullopt},
                     // turtle3d.js's goto with the pen down (a line) and up,
                     // and setHeading (then setUp), in its coordinates.
                     {"@M", TurtleCommand::LineTo, std::nullopt, 3},
                     {"@m", TurtleCommand::MoveTo, std::nullopt, 3},
                     {"@R", TurtleCommand::SetHeading, std::nullopt, 6},
                     {"@Di", TurtleCommand::None, std::nullopt, std::nullopt},
                 });
  return symbols;
}();

const std::vector<RefusedName> kRefused = {
    {"@c", "a circle"},
    {"@H", "the turtle's home"},
    {"@Cs", "a contour"},
    {"@Ce", "a contour"},
    {"@Ca", "a contour"},
    {"@Cb", "a contour"},
    {"@Cc", "a contour"},
    {"@Cm", "a contour"},
    {"@Cn", "a contour"},
    {"@Ct", "a contour"},
    {"@#", "a contour as the track shape"},
    {"@Gs", "a spline path"},
    {"@Gc", "a spline path"},
    {"@Ge", "a spline path"},
    {"@Gt", "a spline path"},
    {"@Gr", "a spline path"},
    {"@bo", "a circle"},
    {"@bd", "a circle"},
    {"~", "a saved mesh or surface"},
    {"$", "a sub-L-system"},
    {"?", "a query of the turtle or the environment"},
};

Draft notation() {
  Draft draft;
  draft.symbols = kSymbols;
  draft.refused = kRefused;
  draft.syntax.probability_after_successor = false;  // not stochastic
  draft.syntax.fixed_arity = false;  // `A` and `A(1)` are two modules
  draft.syntax.radians = true;       // mathjs
  draft.syntax.extra_turtle_parameters = true;
  draft.syntax.cpfg_statements = true;
  draft.syntax.mathjs = true;
  draft.syntax.numbered_labels = true;
  draft.constants = {{"pi", 3.14159265358979323846},
                     {"PI", 3.14159265358979323846},
                     {"e", 2.71828182845904523536},
                     {"E", 2.71828182845904523536},
                     {"true", 1.0},
                     {"false", 0.0}};
  Settings& s = draft.defaults;
  // `/` turns U toward L, `\` L toward U: ABOP's and cpfg's way.
  s.roll = RollConvention::Cpfg;
  s.query_frame = QueryFrame::Babylon;
  s.angle_deg = 90.0;     // `delta`
  s.step = 1.0;           // `step`
  s.initial_width = 0.1;  // `stemsize`, a diameter
  s.width_increment = 0.1;
  s.widen_increment = 1.0;
  return draft;
}

}  // namespace

Grammar read_lowclouds(std::shared_ptr<const SourceFile> source,
                       const ParseOptions& options) {
  CompanionFiles companions(source->name(), options);
  auto preprocessed =
      preprocess(*source, PreprocessOptions{.defines = options.defines,
                                            .indent_continues = true,
                                            .line_comments = false,
                                            .companions = &companions});
  Grammar grammar = read_ls_lines(std::move(preprocessed), options, notation(),
                                  LsVariant::Lowclouds);
  refuse_parameterised_braces(
      grammar,
      "L-system Explorer's '{(n)' (a path or a spline) is not supported; "
      "write '{' for a polygon");
  return grammar;
}

}  // namespace lsys::dialects
