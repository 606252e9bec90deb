// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// cpfg, the L-system program of vlab (Prusinkiewicz, Hanan, Měch and
// others): a `.l` file run through the C preprocessor, and beside it a view
// file `.v` that holds the angle, the widths and the tropism. The symbol
// meanings are cpfg's (CPFG Reference Manual §6, and cpfg's interpret.c
// where they differ), which are not ABOP's in three places: `$` ends a
// sub-L-system, `'` means nothing, `_` changes the elasticity. What cpfg
// can draw and lsolid cannot is refused by name (docs/dialects/cpfg.md).
#include <filesystem>
#include <map>
#include <system_error>

#include "dialects/c_preprocessor.hpp"
#include "dialects/companion_files.hpp"
#include "dialects/cpfg_contour.hpp"
#include "dialects/cpfg_functions.hpp"
#include "dialects/cpfg_surface.hpp"
#include "dialects/cpfg_view.hpp"
#include "dialects/front_ends.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/module_string.hpp"

namespace lsys::dialects {
namespace {

// cpfg draws lines `w` pixels wide by default; on paper a pixel is taken
// as a tenth of a step, the width lsolid gives a file that sets none, so a
// one-pixel line prints as lsolid's line drawings do.
constexpr double kStepsPerPixel = 0.1;

const std::vector<SymbolCommand> kSymbols = [] {
  std::vector<SymbolCommand> symbols = cpfg_turtle_symbols();
  symbols.insert(
      symbols.end(),
      {
          {"_", TurtleCommand::ElasticityChange, std::nullopt, 1},
          // A sphere of the width, or of the diameter given.
          {"@O", TurtleCommand::Sphere, std::nullopt, 1},
          // The elasticities of the view file's movements (blackbox.c).
          {"@Ts", TurtleCommand::MovementElasticity, std::nullopt, 2},
          {"@Ti", TurtleCommand::MovementElasticityUp, std::nullopt, 2},
          {"@Td", TurtleCommand::MovementElasticityDown, std::nullopt, 2},
          // Heading and position set outright (blackbox.c).
          {"@R", TurtleCommand::SetHeading, std::nullopt, 6},
          {"@M", TurtleCommand::MoveTo, std::nullopt, 3},
          // Generalized cylinders, with round cross-sections (general.c).
          {"@Gs", TurtleCommand::CylinderStart, std::nullopt, 0},
          {"@Gc", TurtleCommand::CylinderPoint, std::nullopt, 1},
          {"@Ge", TurtleCommand::CylinderEnd, std::nullopt, 1},
          {"@Gt", TurtleCommand::CylinderTangents, std::nullopt, 2},
          {"@Gr", TurtleCommand::CylinderRadiusTangents, std::nullopt, 4},
          // The cross-section of the cylinders to come, and its sides.
          {"@#", TurtleCommand::SelectContour, std::nullopt, 1},
          {"@!", TurtleCommand::ContourSides, std::nullopt, 1},
          // Discs of the width, or of the diameter given (blackbox.c).
          {"@c", TurtleCommand::DiscAcrossUp, std::nullopt, 1},
          {"@o", TurtleCommand::DiscFacingViewer, std::nullopt, 1},
          // Queries: the turtle writes its position or frame into them
          // before each step (docs/dialects/cpfg.md).
          {"?P", TurtleCommand::QueryPosition, std::nullopt, 3},
          {"?H", TurtleCommand::QueryHeading, std::nullopt, 3},
          {"?L", TurtleCommand::QueryLeft, std::nullopt, 3},
          {"?U", TurtleCommand::QueryUp, std::nullopt, 3},
          // The end of a sub-L-system (whose call `?` is refused); no drawing.
          {"$", TurtleCommand::None, std::nullopt, std::nullopt},
          // Back-side colours, twist and texture: about rendering, nothing
          // to print.
          {"@;", TurtleCommand::None, std::nullopt, std::nullopt},
          {"@,", TurtleCommand::None, std::nullopt, std::nullopt},
          {"@Tf", TurtleCommand::None, std::nullopt, std::nullopt},
          {"@Tp", TurtleCommand::None, std::nullopt, std::nullopt},
          {"@Tx", TurtleCommand::None, std::nullopt, std::nullopt},
      });
  return symbols;
}();

// A label is text on the screen: nothing to print.
const std::vector<RefusedName> kLeftOut = {{"@L", "a label"}};

const std::vector<RefusedName> kRefused = {
    {"@bo", "a circle"},
    {"@bc", "a circle"},
    {"@S", "a system call"},
    {"@D", "the turtle's scale"},
    {"@Di", "the turtle's scale"},
    {"@Dd", "the turtle's scale"},
    {"@PS", "a bicubic patch"},
    {"@PC", "a bicubic patch"},
    {"@PD", "a bicubic patch"},
    {"~", "a predefined surface that no surface: line of the view names"},
    {"?E",
     "a query of the environment, which needs cpfg's environment "
     "programs"},
    {"?Q", "a query of the turtle's frame as a quaternion"},
    {"?", "a sub-L-system call"},
};

// The only file of `extension` in `folder`, if there is exactly one.
std::optional<std::filesystem::path> only_file(
    const std::filesystem::path& folder, std::string_view extension) {
  std::error_code ec;
  std::optional<std::filesystem::path> only;
  for (const auto& entry : std::filesystem::directory_iterator(
           folder.empty() ? std::filesystem::path(".") : folder, ec)) {
    if (entry.path().extension() != extension || !entry.is_regular_file(ec))
      continue;
    if (only) return std::nullopt;
    only = entry.path();
  }
  return only;
}

// The view file cpfg would be given: the one named, else the `.v` of the
// same name, else the only `.v` in the folder. One found by looking must
// be a file the model may read (a `.v` in a downloaded folder may be a
// link to any file of the user's).
std::optional<std::filesystem::path> find_view(
    const SourceFile& source, const ParseOptions& options,
    const CompanionFiles& companions) {
  if (!options.view_file.empty()) return options.view_file;
  std::error_code ec;
  const std::filesystem::path l(source.name());
  if (!std::filesystem::is_regular_file(l, ec)) return std::nullopt;
  std::filesystem::path same = l;
  same.replace_extension(".v");
  std::optional<std::filesystem::path> found;
  if (std::filesystem::exists(std::filesystem::symlink_status(same, ec))) {
    found = same;
  } else {
    found = only_file(l.parent_path(), ".v");
  }
  if (found) {
    if (const auto why = companions.refusal(*found)) {
      throw ParseError(Diagnostic{.file = found->string(),
                                  .message = "the view file: " + *why});
    }
  }
  return found;
}

Draft notation(const CpfgView& view) {
  Draft draft;
  draft.symbols = kSymbols;
  draft.refused = kRefused;
  draft.left_out = kLeftOut;
  draft.syntax.fixed_arity = false;
  draft.syntax.extra_turtle_parameters = true;
  draft.syntax.cpfg_statements = true;
  draft.syntax.single_character_modules = true;
  draft.syntax.several_module_predecessors = true;
  draft.syntax.skip_to_branch_end = true;
  Settings& s = draft.defaults;
  s.roll = RollConvention::Cpfg;
  s.angle_deg = view.angle_deg.value_or(45.0);
  const CpfgLineStyle style = view.line_style.value_or(CpfgLineStyle::Pixel);
  s.width_scale = style == CpfgLineStyle::Pixel ? kStepsPerPixel : 1.0;
  s.initial_width = view.line_width.value_or(1.0);  // scaled as all widths
  if (view.line_width_offset) {
    s.width_offset = view.line_width_offset;
    s.width_source = view.source;
  }
  s.width_increment = view.width_increment.value_or(0.0);
  s.initial_color = view.initial_color.value_or(0);  // 0 to 511
  if (view.tropism_direction) {
    // cpfg's Y is up; lsolid's Z.
    const glm::dvec3& t = *view.tropism_direction;
    s.tropism = glm::dvec3(t.x, -t.z, t.y);
  }
  s.elasticity = view.elasticity.value_or(0.0);
  s.bend_after_moves = true;
  for (Movement m : view.movements) {
    m.direction = glm::dvec3(m.direction.x, -m.direction.z, m.direction.y);
    s.movements.push_back(m);
  }
  s.elasticity_increment = view.elasticity_increment.value_or(0.0);
  s.contour_sides = view.contour_sides.value_or(8);
  s.twist_cylinders = view.twist_cylinders.value_or(false);
  draft.warnings = view.warnings;
  if (view.color_increment && *view.color_increment != 1.0) {
    draft.warnings.emplace_back(
        "the view file's color increment is taken as 1 (colours are "
        "indices here)");
  }
  return draft;
}

// cpfg makes an L-system stochastic only with `seed:`; without it the
// probabilities are ignored, with a warning (lsys_input.y).
void drop_probabilities_without_seed(Grammar& grammar) {
  if (grammar.settings.seed_offset) return;
  bool dropped = false;
  for (Production& p : grammar.productions) {
    dropped = dropped || p.probability.has_value();
    p.probability.reset();
  }
  if (dropped) {
    grammar.warnings.emplace_back(
        "probabilities without 'seed:' are ignored, as cpfg ignores them: "
        "the first applicable production is taken");
  }
}

// cpfg ignores `@Ts(i, …)` of a movement its view file does not define
// ("Movement index out of range!"), and so does lsolid: say so where a
// constant index shows it.
void warn_of_missing_movements(Grammar& grammar) {
  const double count = static_cast<double>(grammar.settings.movements.size());
  const auto check = [&](const Successor& successor) {
    for (std::size_t i = 0; i < successor.size(); ++i) {
      const TurtleCommand c = grammar.commands[successor.symbols()[i]];
      if (c != TurtleCommand::MovementElasticity &&
          c != TurtleCommand::MovementElasticityUp &&
          c != TurtleCommand::MovementElasticityDown) {
        continue;
      }
      const auto parameters = successor.parameters(i);
      if (parameters.empty() || !parameters[0].is_constant()) continue;
      const double index = parameters[0].constant_value();
      if (index >= 1.0 && index < count + 1.0) continue;
      const SourceLocation at = grammar.source->location(successor.offset(i));
      std::string warning = "line " + std::to_string(at.line) + ": '" +
                            grammar.alphabet.name(successor.symbols()[i]) +
                            "' of movement ";
      append_number(warning, index);
      warning += ", which the view file does not define (it has ";
      warning += std::to_string(grammar.settings.movements.size());
      warning += " tropism: and torque: lines): ignored, as cpfg ignores it";
      grammar.warnings.push_back(std::move(warning));
      return;
    }
  };
  check(grammar.axiom);
  for (const auto* list : {&grammar.productions, &grammar.decompositions,
                           &grammar.homomorphisms}) {
    for (const Production& p : *list) check(p.successor);
  }
}

// The view file's functions, read beside it: `function:` files give func's
// ids in order; a `function set:` gives names too, which cpfg passes to
// the preprocessor as macros of their ids (`func(LEAF_GROWTH, t)`).
struct Functions {
  std::shared_ptr<const FunctionTable> table;
  std::vector<std::pair<std::string, std::string>> names;
};

// A function file named several times is read and sampled once.
Functions read_functions(const CpfgView& view, CompanionFiles& companions) {
  Functions out;
  std::vector<CpfgFunction> functions;
  std::map<std::string, std::vector<CpfgFunction>> read;
  const auto load = [&](const ViewFileName& file, std::string_view what) {
    auto cached = read.find(file.name);
    if (cached == read.end()) {
      const auto source =
          companions.load(*view.source, file.offset, what, file.name);
      check_text(*source);
      cached = read.emplace(file.name, read_cpfg_functions(*source)).first;
    }
    functions.insert(functions.end(), cached->second.begin(),
                     cached->second.end());
  };
  if (view.function_set) {
    load(*view.function_set, "function set:");
    for (std::size_t i = 0; i < functions.size(); ++i) {
      if (!functions[i].name.empty()) {
        out.names.emplace_back(functions[i].name, std::to_string(i + 1));
      }
    }
  }
  for (const ViewFileName& name : view.functions) load(name, "function:");
  if (functions.empty()) return out;
  auto table = std::make_shared<FunctionTable>();
  for (CpfgFunction& f : functions) table->push_back(std::move(f.samples));
  out.table = std::move(table);
  return out;
}

// The view file's surfaces, each the module `~` and its one-letter id.
struct Surfaces {
  std::vector<std::string> names;  // "~l"
  std::vector<Surface> meshes;
};

Surfaces read_surfaces(const CpfgView& view, CompanionFiles& companions) {
  Surfaces out;
  for (const CpfgView::SurfaceLine& line : view.surfaces) {
    const auto file = companions.load(*view.source, line.file.offset,
                                      "surface:", line.file.name);
    check_text(*file);
    std::string name = "~";
    name += line.id;
    out.names.push_back(std::move(name));
    out.meshes.push_back(read_cpfg_surface(
        *file,
        SurfaceOptions{
            .size = line.size, .s_divisions = line.s, .t_divisions = line.t}));
  }
  return out;
}

std::map<int, Contour> read_contours(const CpfgView& view,
                                     CompanionFiles& companions) {
  std::map<int, Contour> out;
  for (const CpfgView::ContourLine& line : view.contours) {
    const auto file = companions.load(*view.source, line.file.offset,
                                      "contour:", line.file.name);
    check_text(*file);
    out[line.id] = read_cpfg_contour(*file);
  }
  return out;
}

}  // namespace

Grammar read_cpfg(std::shared_ptr<const SourceFile> source,
                  const ParseOptions& options) {
  return read_with_view(
      std::move(source), options,
      [&](std::shared_ptr<const SourceFile> preprocessed, Draft draft) {
        return read_ls_lines(std::move(preprocessed), options, std::move(draft),
                             LsVariant::Cpfg);
      },
      {});
}

Grammar read_with_view(
    std::shared_ptr<const SourceFile> source, const ParseOptions& options,
    const std::function<Grammar(std::shared_ptr<const SourceFile>, Draft)>&
        read,
    const std::vector<std::string>& ignored_headers) {
  CompanionFiles companions(source->name(), options);
  CpfgView view;
  std::optional<std::filesystem::path> view_path =
      find_view(*source, options, companions);
  if (view_path) {
    const auto view_source = read_as_windows_1252(load_source(*view_path));
    check_text(*view_source);
    view = read_cpfg_view(*view_source, companions);
    if (!ignored_headers.empty() && !view.function_set &&
        view.functions.empty()) {
      // lpfg is given its function set on the command line (the object's
      // `specifications`): the folder's only `.fset`, if it has one.
      if (const auto fset = only_file(view_path->parent_path(), ".fset")) {
        if (const auto why = companions.refusal(*fset)) {
          throw ParseError(Diagnostic{.file = fset->string(),
                                      .message = "the function set: " + *why});
        }
        view.function_set =
            ViewFileName{.name = fset->filename().string(), .offset = 0};
      }
    }
  }
  const Functions functions =
      view_path ? read_functions(view, companions) : Functions{};
  auto preprocessed =
      preprocess(*source, PreprocessOptions{.defines = options.defines,
                                            .tab_continues = true,
                                            .predefined = functions.names,
                                            .ignored_headers = ignored_headers,
                                            .companions = &companions});
  Surfaces surfaces = view_path ? read_surfaces(view, companions) : Surfaces{};
  std::map<int, Contour> contours =
      view_path ? read_contours(view, companions) : std::map<int, Contour>{};
  Draft draft = notation(view);
  draft.functions = functions.table;
  for (const std::string& name : surfaces.names) {
    draft.symbols.push_back(
        SymbolCommand{name, TurtleCommand::Surface, std::nullopt, 3});
  }
  if (!view_path) {
    draft.warnings.insert(
        draft.warnings.begin(),
        "no view file (.v) found for " + source->name() +
            ": cpfg's defaults are used (45 degrees, lines 1 pixel wide); "
            "name one with --view");
  }
  Grammar grammar = read(std::move(preprocessed), std::move(draft));
  for (std::size_t i = 0; i < surfaces.names.size(); ++i) {
    if (const auto symbol = grammar.alphabet.find(surfaces.names[i])) {
      grammar.surfaces[*symbol] = std::move(surfaces.meshes[i]);
    }
  }
  grammar.contours = std::move(contours);
  refuse_parameterised_braces(
      grammar,
      "cpfg's '{(n)' (a generalized cylinder) is not supported; write '{' "
      "for a polygon");
  drop_probabilities_without_seed(grammar);
  warn_of_missing_movements(grammar);
  return grammar;
}

std::vector<SymbolCommand> cpfg_turtle_symbols() {
  return {
      {"F", TurtleCommand::Draw, std::nullopt, 1},
      {"f", TurtleCommand::Move, std::nullopt, 1},
      {"G", TurtleCommand::DrawNoVertex, std::nullopt, 1},
      {"g", TurtleCommand::MoveNoVertex, std::nullopt, 1},
      {"+", TurtleCommand::TurnLeft, std::nullopt, 1},
      {"-", TurtleCommand::TurnRight, std::nullopt, 1},
      {"&", TurtleCommand::PitchDown, std::nullopt, 1},
      {"^", TurtleCommand::PitchUp, std::nullopt, 1},
      {"/", TurtleCommand::RollRight, std::nullopt, 1},
      {"\\", TurtleCommand::RollLeft, std::nullopt, 1},
      {"|", TurtleCommand::TurnAround, std::nullopt, 0},
      {"@v", TurtleCommand::RollToVertical, std::nullopt, 0},
      {"[", TurtleCommand::Push, std::nullopt, 0},
      {"]", TurtleCommand::Pop, std::nullopt, 0},
      {"{", TurtleCommand::PolygonBegin, std::nullopt, 0},
      {".", TurtleCommand::PolygonVertex, std::nullopt, 0},
      {"}", TurtleCommand::PolygonEnd, std::nullopt, 0},
      {"!", TurtleCommand::Width, std::nullopt, 1},
      {"#", TurtleCommand::Widen, std::nullopt, 1},
      {";", TurtleCommand::ColorNext, std::nullopt, 1},
      {",", TurtleCommand::ColorPrevious, std::nullopt, 1},
      {"%", TurtleCommand::Cut, std::nullopt, 0},
  };
}

void refuse_parameterised_braces(const Grammar& grammar,
                                 std::string_view message) {
  const auto check = [&](const Successor& successor) {
    for (std::size_t i = 0; i < successor.size(); ++i) {
      if (grammar.commands[successor.symbols()[i]] ==
              TurtleCommand::PolygonBegin &&
          !successor.parameters(i).empty()) {
        throw error_at(*grammar.source, successor.offset(i),
                       std::string(message));
      }
    }
  };
  check(grammar.axiom);
  for (const auto* list : {&grammar.productions, &grammar.decompositions,
                           &grammar.homomorphisms}) {
    for (const Production& p : *list) check(p.successor);
  }
}

}  // namespace lsys::dialects
