// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Turtle interpretation (ABOP §1.5, p. 209 for the symbols; §1.10.3 for
// parameters; §2.2, p. 58 for tropism; §5.1 for polygons), with the
// homomorphism of cpfg and L-Py applied on the fly.
#include "lsys/interpretation.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <initializer_list>
#include <limits>
#include <numbers>
#include <optional>
#include <string>

#include "lsys/diagnostic.hpp"
#include "lsys/module_string.hpp"
#include "lsys/random.hpp"
#include "lsys/turtle.hpp"
#include "rule_index.hpp"
#include "size_model.hpp"

namespace lsys {
namespace {

// Sides of a disc: its corners stand out 0.2% of its radius (0.05 mm on a
// disc 46 mm across).
constexpr int kDiscSides = 48;

// More pieces than this in one span of a generalized cylinder would only
// cost time: cpfg's own views use up to 20.
constexpr int kMostCylinderPieces = 256;

// A move shorter than this fraction of the distance from the origin (at
// least 1) draws no segment: some ulps.
constexpr double kShortestMove = 1e-12;

bool is_one_of(TurtleCommand command,
               std::initializer_list<TurtleCommand> commands) {
  return std::find(commands.begin(), commands.end(), command) != commands.end();
}

// The place of the first module, of the axiom and then of every successor
// in file order, of one of `commands` whose parameters `matches` accepts.
std::optional<std::size_t> find_module(
    const Grammar& g, std::initializer_list<TurtleCommand> commands,
    const std::function<bool(std::span<const Expression>)>& matches) {
  std::vector<const Successor*> successors{&g.axiom};
  for (const auto* rules :
       {&g.productions, &g.decompositions, &g.homomorphisms}) {
    for (const Production& p : *rules) successors.push_back(&p.successor);
  }
  for (const Successor* successor : successors) {
    for (std::size_t i = 0; i < successor->size(); ++i) {
      if (is_one_of(g.commands[successor->symbols()[i]], commands) &&
          matches(successor->parameters(i))) {
        return successor->offset(i);
      }
    }
  }
  return std::nullopt;
}

// Where a bad turtle value most likely comes from, as a module string keeps
// no source places: the first module of `commands` whose first parameter
// is a constant that `is_bad` rejects, else the first whose parameter is
// computed, else `fallback`.
std::size_t place_of(const Grammar& g,
                     std::initializer_list<TurtleCommand> commands,
                     const std::function<bool(double)>& is_bad,
                     std::size_t fallback) {
  const auto constant =
      find_module(g, commands, [&](std::span<const Expression> parameters) {
        return !parameters.empty() && parameters[0].is_constant() &&
               is_bad(parameters[0].constant_value());
      });
  if (constant) return *constant;
  return find_module(g, commands,
                     [](std::span<const Expression> parameters) {
                       return !parameters.empty() &&
                              !parameters[0].is_constant();
                     })
      .value_or(fallback);
}

std::string number_text(double value) {
  std::string out;
  append_number(out, value);
  return out;
}

bool is_color_index(double c) {
  return c >= 0.0 && c < static_cast<double>(kMaxColorIndex) + 1.0;
}

struct TurtleState {
  Turtle turtle;
  double width = 1.0;  // diameter in model units, width_scale applied
  int color = 0;
  double step = 1.0;
  double angle_deg = 45.0;
  glm::dvec3 tropism{0.0};
  double elasticity = 0.0;
  std::int32_t last_segment = -1;
  bool turns_swapped = false;  // Fractint's `!`
  double gravity = 0.2;        // Lparser's `t`, in radians
  // cpfg's generalized cylinder: whether one is open, its last control
  // point, and the factors of its tangents (cpfg's interpret.c: 1.2).
  bool in_cylinder = false;
  glm::dvec3 cylinder_point{0.0};
  glm::dvec3 cylinder_heading{0.0};
  double cylinder_width = 0.0;
  // The segment the next span continues: its last, or at `@Gs` the one
  // drawn last (the `f` between control points does not break the tube).
  std::int32_t cylinder_parent = -1;
  std::array<double, 2> tangent_factors{1.2, 1.2};
};

class Interpreter {
 public:
  Interpreter(const Grammar& grammar, const InterpretOptions& options)
      : grammar_(grammar),
        settings_(grammar.settings),
        homomorphisms_(grammar.homomorphisms, grammar.alphabet.size()),
        roll_sign_(options.roll.value_or(settings_.roll) == RollConvention::Cpfg
                       ? -1.0
                       : 1.0) {
    state_.width = settings_.initial_width * settings_.width_scale;
    state_.color = settings_.initial_color;
    state_.step = settings_.step;
    state_.angle_deg = settings_.angle_deg;
    state_.tropism = settings_.tropism;
    state_.elasticity = settings_.elasticity;
    buffers_.resize(static_cast<std::size_t>(settings_.maximum_depth) + 1);
    slot_buffers_.resize(buffers_.size());
  }

  void reserve(std::size_t segments) { skeleton_.segments.reserve(segments); }

  /// cpfg's variables, which the homomorphism may read and draw from.
  void use_variables(Variables* variables) { variables_ = variables; }

  // A homomorphism can multiply the modules the turtle reads without
  // drawing anything; `on_limit` throws when more than `most` are read.
  void limit_modules(std::uint64_t most, std::function<void()> on_limit) {
    max_modules_ = most;
    on_limit_ = std::move(on_limit);
  }

  void run(const ModuleString& modules) {
    for (std::size_t i = 0; i < modules.size(); ++i) {
      interpret(modules.symbol(i), modules.parameters(i), modules.generation(i),
                0);
    }
  }

  Skeleton finish() {
    skeleton_.unclosed_polygons += polygons_.size();
    polygons_.clear();
    return std::move(skeleton_);
  }

 private:
  void interpret(SymbolId symbol, std::span<const double> params,
                 std::uint32_t generation, int depth) {
    if (depth < settings_.maximum_depth && homomorphisms_.has_rules(symbol)) {
      if (const Production* rule = homomorphisms_.first_applicable(
              symbol, params, variables_,
              &slot_buffers_[static_cast<std::size_t>(depth)])) {
        std::vector<double>& values = buffers_[static_cast<std::size_t>(depth)];
        rule->successor.instantiate(
            rule->has_statements()
                ? std::span<const double>(
                      slot_buffers_[static_cast<std::size_t>(depth)])
                : params,
            values, variables_);
        const auto& begins = rule->successor.parameter_begins();
        const auto& symbols = rule->successor.symbols();
        for (std::size_t k = 0; k < symbols.size(); ++k) {
          // `values` belongs to this depth; deeper levels use other buffers.
          interpret(symbols[k],
                    std::span<const double>(values).subspan(
                        begins[k], begins[k + 1] - begins[k]),
                    generation, depth + 1);
        }
        return;
      }
    }
    if (++modules_read_ > max_modules_) on_limit_();
    if (symbol < grammar_.parameters_read.size() &&
        grammar_.parameters_read[symbol] &&
        params.size() >
            static_cast<std::size_t>(*grammar_.parameters_read[symbol])) {
      params = params.first(
          static_cast<std::size_t>(*grammar_.parameters_read[symbol]));
    }
    if (params.empty() && symbol < grammar_.default_parameters.size() &&
        grammar_.default_parameters[symbol]) {
      params =
          std::span<const double>(&*grammar_.default_parameters[symbol], 1);
    }
    if (grammar_.commands[symbol] == TurtleCommand::Surface) {
      draw_surface(grammar_.surfaces.at(symbol), params);
      return;
    }
    execute(grammar_.commands[symbol], params, generation);
  }

  // cpfg's `~l(sx, sy, sz)` (one scale for all, or none for 1): the
  // surface placed at the turtle as one sheet, then the turtle moves to the
  // surface's end point (cpfg's patches.c). The surface's z is cpfg's up,
  // lsolid's −up. A scale of 0 leaves no area: the sheet is dropped and
  // counted with the degenerate polygons.
  void draw_surface(const Surface& surface, std::span<const double> params) {
    const double sx = params.empty() ? 1.0 : params[0];
    const double sy = params.size() >= 2 ? params[1] : sx;
    const double sz = params.size() >= 3 ? params[2] : sx;
    Turtle& turtle = state_.turtle;
    const glm::dvec3 origin = turtle.position();
    const glm::dvec3 l = turtle.left();
    const glm::dvec3 h = turtle.heading();
    const glm::dvec3 u = -turtle.up();
    Sheet sheet{.color = state_.color, .parent = state_.last_segment};
    sheet.points.reserve(surface.points.size());
    for (const glm::dvec3& p : surface.points) {
      sheet.points.push_back(origin + (sx * p.x) * l + (sy * p.y) * h +
                             (sz * p.z) * u);
      turtle.set_position(sheet.points.back());
      check_finite();  // throws if the surface left the doubles
    }
    turtle.set_position(origin + sx * (surface.end_point.x * l +
                                       surface.end_point.y * h +
                                       surface.end_point.z * u));
    check_finite();
    // A scale of 0, or one that leaves the sheet some ulps across (vlab's
    // sympodial plant draws its youngest leaves at 10⁻¹⁷), flattens it.
    glm::dvec3 lo = sheet.points.front();
    glm::dvec3 hi = lo;
    for (const glm::dvec3& p : sheet.points) {
      lo = glm::min(lo, p);
      hi = glm::max(hi, p);
    }
    const glm::dvec3 size = hi - lo;
    if (sx == 0.0 || sy == 0.0 || sz == 0.0 ||
        std::max({size.x, size.y, size.z}) <=
            kShortestMove * std::max(1.0, glm::length(origin))) {
      ++skeleton_.degenerate_polygons;
      return;
    }
    sheet.triangles = surface.triangles;
    skeleton_.sheets.push_back(std::move(sheet));
  }

  // A disc as a polygon of kDiscSides whose sides touch the circle, as a
  // tube's sides touch its own: never narrower than asked. Of diameter 0
  // it is dropped and counted with the degenerate polygons.
  void draw_disc(TurtleCommand command, double diameter) {
    if (!(diameter > 0.0)) {
      ++skeleton_.degenerate_polygons;
      return;
    }
    const Turtle& turtle = state_.turtle;
    glm::dvec3 a(1.0, 0.0, 0.0);
    glm::dvec3 b(0.0, 0.0, 1.0);  // cpfg's x and y are lsolid's x and z
    if (command == TurtleCommand::DiscAcrossUp) {
      a = turtle.heading();
      b = turtle.left();
    } else if (command == TurtleCommand::DiscAcrossHeading) {
      a = turtle.left();
      b = turtle.up();
    } else if (command == TurtleCommand::DiscAcrossLeft) {
      a = turtle.heading();
      b = turtle.up();
    }
    const double r = diameter / 2.0 / std::cos(std::numbers::pi / kDiscSides);
    Polygon disc{.color = state_.color, .parent = state_.last_segment};
    for (int k = 0; k < kDiscSides; ++k) {
      const double t = 2.0 * std::numbers::pi * k / kDiscSides;
      disc.points.push_back(turtle.position() +
                            r * (std::cos(t) * a + std::sin(t) * b));
      if (!std::isfinite(glm::length(disc.points.back()))) {
        throw error_at(*grammar_.source,
                       place_of(
                           grammar_, {command},
                           [](double v) { return std::fabs(v) > 1e100; },
                           grammar_.axiom_offset),
                       "a disc this large overflows: its points are no "
                       "longer finite numbers");
      }
      if (k > 0 && disc.points[k] == disc.points[k - 1]) {
        ++skeleton_.degenerate_polygons;  // too small for the doubles
        return;
      }
    }
    skeleton_.polygons.push_back(std::move(disc));
  }

  void set_cylinder_point(std::uint32_t generation) {
    state_.in_cylinder = true;
    state_.cylinder_point = state_.turtle.position();
    state_.cylinder_heading = state_.turtle.heading();
    state_.cylinder_width = generation_width(state_.width, generation);
  }

  // The span of a generalized cylinder from its last control point to the
  // turtle, as cpfg's general.c draws it: a cubic Hermite curve whose
  // tangents are the headings at both ends times the chord's length and
  // the `@Gt` factors, cut into `pieces` segments whose widths go linearly
  // from one end's to the other's (cpfg's default radius tangents). A
  // chord under 10⁻⁵ draws nothing, as in cpfg.
  void draw_cylinder_span(int pieces, std::uint32_t generation) {
    const glm::dvec3 p1 = state_.cylinder_point;
    const glm::dvec3 p2 = state_.turtle.position();
    const double length = glm::length(p2 - p1);
    if (!(length >= 1e-5)) return;
    const glm::dvec3 t1 =
        state_.cylinder_heading * (length * state_.tangent_factors[0]);
    const glm::dvec3 t2 =
        state_.turtle.heading() * (length * state_.tangent_factors[1]);
    const double w1 = state_.cylinder_width;
    const double w2 = generation_width(state_.width, generation);
    state_.last_segment = state_.cylinder_parent;
    glm::dvec3 from = p1;
    for (int k = 1; k <= pieces; ++k) {
      const double t = static_cast<double>(k) / pieces;
      const double t2x = t * t;
      const double t3x = t2x * t;
      const glm::dvec3 to =
          k == pieces
              ? p2
              : (2 * t3x - 3 * t2x + 1) * p1 + (t3x - 2 * t2x + t) * t1 +
                    (-2 * t3x + 3 * t2x) * p2 + (t3x - t2x) * t2;
      if (!std::isfinite(glm::length(to))) {
        state_.turtle.set_position(to);
        check_finite();  // throws: the curve left the doubles
      }
      if (to == from) continue;
      const double a = static_cast<double>(k - 1) / pieces;
      skeleton_.segments.push_back(Segment{from, to, w1 + (w2 - w1) * a,
                                           w1 + (w2 - w1) * t, state_.color,
                                           state_.last_segment});
      state_.last_segment =
          static_cast<std::int32_t>(skeleton_.segments.size() - 1);
      from = to;
    }
    state_.cylinder_parent = state_.last_segment;
  }

  double angle(std::span<const double> params) const {
    return params.empty() ? state_.angle_deg : params[0];
  }

  double generation_width(double width, std::uint32_t generation) const {
    return std::max(0.0, width - settings_.width_decrement_per_generation *
                                     settings_.width_scale * generation);
  }

  void execute(TurtleCommand command, std::span<const double> params,
               std::uint32_t generation) {
    Turtle& turtle = state_.turtle;
    switch (command) {
      case TurtleCommand::None:
      case TurtleCommand::Surface:  // drawn by interpret, which knows which
      case TurtleCommand::Cut:
        return;
      case TurtleCommand::Draw:
        if (!polygons_.empty()) {
          turtle.move(params.empty() ? state_.step : params[0]);
          add_vertex();
          return;
        }
        draw(params, generation);
        return;
      case TurtleCommand::DrawNoVertex:
        draw(params, generation);
        return;
      case TurtleCommand::DrawHalf: {
        const double half = state_.step / 2;
        draw(params.empty() ? std::span<const double>(&half, 1) : params,
             generation);
        return;
      }
      case TurtleCommand::MoveHalf:
        turtle.move(params.empty() ? state_.step / 2 : params[0]);
        state_.last_segment = -1;
        add_vertex();
        return;
      case TurtleCommand::RandomTurn:
        random_turn(params.empty() ? 180.0 : params[0]);
        return;
      case TurtleCommand::Gravity: {
        // Lapré's L_draw turns the heading about left by tr times the
        // length of its horizontal part, in radians: toward the ground
        // once `$` has rolled the turtle upright.
        if (!params.empty()) state_.gravity = params[0];
        const glm::dvec3 h = turtle.heading();
        const double horizontal = std::sqrt(h.x * h.x + h.y * h.y);
        if (horizontal > 0.0) {
          turtle.pitch(state_.gravity * horizontal * 180.0 / std::numbers::pi);
        }
        return;
      }
      case TurtleCommand::Move:
        turtle.move(params.empty() ? state_.step : params[0]);
        state_.last_segment = -1;
        add_vertex();
        return;
      case TurtleCommand::MoveNoVertex:
        turtle.move(params.empty() ? state_.step : params[0]);
        state_.last_segment = -1;
        return;
      case TurtleCommand::TurnLeft:
        turtle.turn(state_.turns_swapped ? -angle(params) : angle(params));
        return;
      case TurtleCommand::TurnRight:
        turtle.turn(state_.turns_swapped ? angle(params) : -angle(params));
        return;
      case TurtleCommand::TurnRightFixed:
        turtle.turn(-angle(params));
        return;
      case TurtleCommand::SwapTurns:
        state_.turns_swapped = !state_.turns_swapped;
        return;
      case TurtleCommand::PitchDown:
        turtle.pitch(angle(params));
        return;
      case TurtleCommand::PitchUp:
        turtle.pitch(-angle(params));
        return;
      case TurtleCommand::RollRight:
        turtle.roll(roll_sign_ * angle(params));
        return;
      case TurtleCommand::RollLeft:
        turtle.roll(-roll_sign_ * angle(params));
        return;
      case TurtleCommand::TurnAround:
        turtle.turn_around();
        return;
      case TurtleCommand::RollToVertical:
        turtle.roll_to_vertical();
        return;
      case TurtleCommand::RollToVerticalSwappingTurns: {
        // Lparser's frame starts left-handed and its `$` rebuilds it
        // right-handed; its turns are about its up vector, so from then on
        // they turn the other way (pitches and rolls are about heading and
        // left, which lsolid shares). A vertical heading is left alone.
        const glm::dvec3 h = turtle.heading();
        if (h.x != 0.0 || h.y != 0.0) {
          turtle.roll_to_vertical();
          state_.turns_swapped = true;
        }
        return;
      }
      case TurtleCommand::Push:
        stack_.push_back(state_);
        return;
      case TurtleCommand::Pop:
        // Successors are balanced, so a pop always has its push.
        if (!stack_.empty()) {
          state_ = stack_.back();
          stack_.pop_back();
        }
        return;
      case TurtleCommand::PolygonBegin:
        polygons_.push_back(
            Polygon{{turtle.position()}, state_.color, state_.last_segment});
        return;
      case TurtleCommand::PolygonVertex:
        add_vertex();
        return;
      case TurtleCommand::PolygonEnd:
        close_polygon();
        return;
      case TurtleCommand::Width:
        if (!params.empty()) {
          state_.width = std::max(0.0, params[0] * settings_.width_scale);
        } else if (settings_.width_increment) {
          state_.width =
              std::max(0.0, state_.width - *settings_.width_increment *
                                               settings_.width_scale);
        } else {
          state_.width *= settings_.width_factor;
        }
        return;
      case TurtleCommand::Widen:
        if (!params.empty()) {
          state_.width = std::max(0.0, params[0] * settings_.width_scale);
        } else if (settings_.widen_increment || settings_.width_increment) {
          state_.width += settings_.widen_increment.value_or(
                              settings_.width_increment.value_or(0.0)) *
                          settings_.width_scale;
        } else {
          if (settings_.width_factor > 0.0)
            state_.width /= settings_.width_factor;
        }
        return;
      case TurtleCommand::ColorNext:
        state_.color = params.empty() ? next_color() : color_index(params[0]);
        return;
      case TurtleCommand::ColorPrevious:
        state_.color = params.empty() ? std::max(0, state_.color - 1)
                                      : color_index(params[0]);
        return;
      case TurtleCommand::SetTropism:
        state_.tropism = glm::dvec3(params[0], params[1], params[2]);
        return;
      case TurtleCommand::SetElasticity:
        state_.elasticity = params[0];
        return;
      case TurtleCommand::Sphere: {
        const double diameter =
            params.empty()
                ? state_.width
                : params[0] * settings_.sphere_diameter_per_parameter;
        if (diameter > 0.0 && std::isfinite(diameter)) {
          skeleton_.spheres.push_back(Sphere{state_.turtle.position(), diameter,
                                             state_.color,
                                             state_.last_segment});
        }
        return;
      }
      case TurtleCommand::DiscAcrossUp:
      case TurtleCommand::DiscAcrossHeading:
      case TurtleCommand::DiscAcrossLeft:
      case TurtleCommand::DiscFacingViewer:
        draw_disc(command,
                  params.empty()
                      ? state_.width
                      : params[0] * settings_.sphere_diameter_per_parameter);
        return;
      case TurtleCommand::CylinderStart:
        set_cylinder_point(generation);
        state_.cylinder_parent = state_.last_segment;
        return;
      case TurtleCommand::CylinderPoint:
      case TurtleCommand::CylinderEnd: {
        // cpfg's blackbox.c: n pieces, at least 1; without a parameter, 1.
        const double pieces = params.empty() ? 1.0 : params[0];
        // Without `@Gs` cpfg starts a cylinder here (continue_spline).
        if (!state_.in_cylinder) state_.cylinder_parent = state_.last_segment;
        if (state_.in_cylinder) {
          draw_cylinder_span(
              pieces >= kMostCylinderPieces
                  ? kMostCylinderPieces
                  : std::max(
                        1, static_cast<int>(std::isnan(pieces) ? 1.0 : pieces)),
              generation);
        }
        set_cylinder_point(generation);
        if (command == TurtleCommand::CylinderEnd) state_.in_cylinder = false;
        return;
      }
      case TurtleCommand::CylinderTangents:
        if (params.empty()) return;
        state_.tangent_factors = {params[0],
                                  params.size() > 1 ? params[1] : params[0]};
        return;
      case TurtleCommand::ElasticityChange:
        state_.elasticity =
            params.empty() ? state_.elasticity + settings_.elasticity_increment
                           : params[0];
        return;
      case TurtleCommand::MultiplyStep:
        if (!params.empty()) state_.step *= params[0];
        return;
      case TurtleCommand::MultiplyAngle:
        if (!params.empty()) state_.angle_deg *= params[0];
        return;
      case TurtleCommand::MultiplyWidth:
        if (!params.empty())
          state_.width = std::max(0.0, state_.width * params[0]);
        return;
      case TurtleCommand::ColorAdd:
        state_.color = color_index(static_cast<double>(state_.color) +
                                   std::max(-static_cast<double>(state_.color),
                                            params.empty() ? 1.0 : params[0]));
        return;
    }
  }

  // A colour index from a parameter: truncated, and refused outside 0 to
  // kMaxColorIndex before any conversion to int (1e300 or 2^31 would not
  // fit one).
  int color_index(double c) const {
    if (!is_color_index(c)) {
      throw error_at(
          *grammar_.source,
          place_of(
              grammar_,
              {TurtleCommand::ColorNext, TurtleCommand::ColorPrevious,
               TurtleCommand::ColorAdd},
              [](double v) { return !is_color_index(v); },
              // A sum of Fractint's `<nn` leaves the range with no bad
              // parameter of its own: name the first such module.
              find_module(grammar_, {TurtleCommand::ColorAdd},
                          [](std::span<const Expression>) { return true; })
                  .value_or(grammar_.axiom_offset)),
          "colour index " + number_text(c) + " is out of range 0 to " +
              std::to_string(kMaxColorIndex));
    }
    return static_cast<int>(c);
  }

  int next_color() const {
    if (state_.color < kMaxColorIndex) return state_.color + 1;
    throw error_at(*grammar_.source,
                   find_module(grammar_, {TurtleCommand::ColorNext},
                               [](std::span<const Expression> parameters) {
                                 return parameters.empty();
                               })
                       .value_or(grammar_.axiom_offset),
                   "colour index " + std::to_string(kMaxColorIndex + 1) +
                       " is out of range 0 to " +
                       std::to_string(kMaxColorIndex));
  }

  // Lengths and widths are finite, but their sums need not be: refuse a
  // turtle that has left the doubles rather than draw NaN.
  void check_finite() const {
    const glm::dvec3& p = state_.turtle.position();
    if (std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z) &&
        std::isfinite(state_.width)) {
      return;
    }
    const bool is_width = !std::isfinite(state_.width);
    throw error_at(
        *grammar_.source,
        place_of(
            grammar_,
            is_width
                ? std::initializer_list<TurtleCommand>{TurtleCommand::Width}
                : std::initializer_list<
                      TurtleCommand>{TurtleCommand::Draw, TurtleCommand::Move,
                                     TurtleCommand::DrawNoVertex,
                                     TurtleCommand::MoveNoVertex},
            [](double v) { return std::fabs(v) > 1e100; },
            grammar_.axiom_offset),
        std::string("the turtle's ") + (is_width ? "width" : "position") +
            " overflows: it is no longer a finite number");
  }

  // Lparser's `~`: three rotations, about up, left and heading, each by
  // an angle drawn uniformly from [-most, most] degrees. The numbers are
  // keyed by the seed and the count of `~` so far, so a file draws the
  // same every run (Lparser seeds with the time).
  void random_turn(double most_deg) {
    const std::uint64_t n = random_turns_++;
    const auto angle = [&](std::uint64_t k) {
      return (2.0 * stochastic_uniform(settings_.seed ^ 0x7E7A11ULL, n, k) -
              1.0) *
             most_deg;
    };
    state_.turtle.turn(angle(0));
    state_.turtle.pitch(angle(1));
    state_.turtle.roll(angle(2));
  }

  void draw(std::span<const double> params, std::uint32_t generation) {
    Turtle& turtle = state_.turtle;
    const double length = params.empty() ? state_.step : params[0];
    const glm::dvec3 p0 = turtle.position();
    turtle.move(length);
    // Lparser's widths are a fraction of the segment's own length.
    const double scale =
        settings_.widths_relative_to_length ? std::fabs(length) : 1.0;
    const double start = generation_width(state_.width, generation) * scale;
    if (params.size() > 1) {
      state_.width = std::max(0.0, params[1] * settings_.width_scale);
    }
    check_finite();
    // A step far smaller than where the turtle stands (F(1e38) at 1e308)
    // moves it nowhere: no segment, as for F(0) (found by ls_fuzzer). Nor
    // does one that moves it by a few ulps (vlab's sympodial plant draws
    // F(l) with l computed to 10⁻¹⁶): a tube that short has no direction,
    // and its mitres made its neighbour cut itself.
    const bool moved =
        length != 0.0 && glm::length(turtle.position() - p0) >
                             kShortestMove * std::max(1.0, glm::length(p0));
    if (!moved) ++skeleton_.zero_length_segments;
    // Inside a generalized cylinder `F` only moves (cpfg's start_spline:
    // "not to interpret f and F"); the cylinder draws the curve.
    if (moved && !state_.in_cylinder) {
      skeleton_.segments.push_back(
          Segment{p0, turtle.position(), start,
                  generation_width(state_.width, generation) * scale,
                  state_.color, state_.last_segment});
      state_.last_segment =
          static_cast<std::int32_t>(skeleton_.segments.size() - 1);
    }
    if (state_.elasticity != 0.0) {
      turtle.bend(state_.tropism, state_.elasticity);
    }
  }

  void add_vertex() {
    check_finite();
    if (polygons_.empty()) return;
    auto& points = polygons_.back().points;
    const glm::dvec3& p = state_.turtle.position();
    if (points.empty() || !is_same_point(points.back(), p)) {
      points.push_back(p);
    }
  }

  bool is_same_point(const glm::dvec3& a, const glm::dvec3& b) const {
    return glm::length(a - b) <= 1e-9 * std::max(1.0, std::fabs(state_.step));
  }

  void close_polygon() {
    if (polygons_.empty()) {
      ++skeleton_.unmatched_polygon_ends;
      return;
    }
    Polygon polygon = std::move(polygons_.back());
    polygons_.pop_back();
    auto& points = polygon.points;
    if (points.size() > 1 && is_same_point(points.front(), points.back())) {
      points.pop_back();
    }
    if (points.size() < 3) {
      ++skeleton_.degenerate_polygons;
      return;
    }
    skeleton_.polygons.push_back(std::move(polygon));
  }

  const Grammar& grammar_;
  const Settings& settings_;
  std::vector<std::vector<double>> slot_buffers_;
  RuleIndex homomorphisms_;
  double roll_sign_;
  TurtleState state_;
  std::vector<TurtleState> stack_;
  std::vector<Polygon> polygons_;  // open ones, innermost last
  std::vector<std::vector<double>> buffers_;
  Skeleton skeleton_;
  std::uint64_t modules_read_ = 0;
  std::uint64_t random_turns_ = 0;
  Variables* variables_ = nullptr;
  std::uint64_t max_modules_ = std::numeric_limits<std::uint64_t>::max();
  std::function<void()> on_limit_;
};

}  // namespace

Skeleton interpret(const Grammar& grammar, const DerivationOptions& derivation,
                   const InterpretOptions& options) {
  Derivation d(grammar, derivation);
  Interpreter interpreter(grammar, options);
  interpreter.use_variables(d.variables());
  const int n = d.derivation_length();
  const std::string limit =
      " modules after the homomorphism, more than the limit of " +
      count_text(static_cast<double>(derivation.max_modules)) +
      " (--max-modules)";
  if (d.prediction() && d.prediction()->interpreted_modules >
                            static_cast<double>(derivation.max_modules)) {
    throw limit_error(grammar, derivation, n,
                      "would make the turtle read " +
                          count_text(d.prediction()->interpreted_modules) +
                          limit);
  }
  interpreter.limit_modules(derivation.max_modules, [&] {
    throw limit_error(
        grammar, derivation, n,
        "makes the turtle read more than " +
            count_text(static_cast<double>(derivation.max_modules)) +
            " modules after the homomorphism (--max-modules)");
  });
  if (d.prediction()) {
    interpreter.reserve(static_cast<std::size_t>(
        std::min(d.prediction()->segments,
                 static_cast<double>(derivation.max_segments))));
  }
  ModuleString chunk;
  while (d.next(chunk)) interpreter.run(chunk);
  return interpreter.finish();
}

ParseError nothing_drawn_error(const Grammar& grammar,
                               const Skeleton& skeleton) {
  const SourceFile& source = *grammar.source;
  const std::size_t axiom = grammar.axiom_offset;
  const std::string nothing = "nothing to build: ";
  if (skeleton.zero_length_segments > 0) {
    if (grammar.settings.step == 0.0 && grammar.settings.step_offset) {
      return error_at(source, *grammar.settings.step_offset,
                      nothing +
                          "the step is 0, so F without a length draws "
                          "a segment of length 0");
    }
    return error_at(
        source,
        place_of(
            grammar, {TurtleCommand::Draw, TurtleCommand::DrawNoVertex},
            [](double v) { return v == 0.0; }, axiom),
        nothing + "every segment has length 0");
  }
  if (skeleton.degenerate_polygons > 0 || skeleton.unclosed_polygons > 0) {
    return error_at(
        source,
        find_module(grammar, {TurtleCommand::PolygonBegin},
                    [](std::span<const Expression>) { return true; })
            .value_or(axiom),
        nothing + (skeleton.degenerate_polygons > 0
                       ? "every polygon has fewer than 3 distinct points"
                       : "no polygon is closed with '}'"));
  }
  return error_at(source, axiom,
                  nothing +
                      "the L-system draws no segment and no polygon; modules "
                      "without a turtle meaning draw nothing (map them with "
                      "an alias block, e.g. 'aliases: Fl=F Fr=F')");
}

Skeleton interpret_string(const Grammar& grammar, const ModuleString& modules,
                          const InterpretOptions& options) {
  Interpreter interpreter(grammar, options);
  Variables variables = initial_variables(grammar);
  interpreter.use_variables(&variables);
  interpreter.run(modules);
  return interpreter.finish();
}

}  // namespace lsys
