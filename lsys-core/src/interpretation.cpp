// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// Turtle interpretation (ABOP §1.5, p. 209 for the symbols; §1.10.3 for
// parameters; §2.2, p. 58 for tropism; §5.1 for polygons), with the
// homomorphism of cpfg and L-Py applied on the fly.
#include "lsys/interpretation.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <functional>
#include <glm/geometric.hpp>
#include <initializer_list>
#include <limits>
#include <map>
#include <numbers>
#include <optional>
#include <string>

#include "lsys/contour.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/module_string.hpp"
#include "lsys/random.hpp"
#include "lsys/turtle.hpp"
#include "queries.hpp"
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

// The commands that step the turtle, before which cpfg's movements act.
bool is_step(TurtleCommand command) {
  switch (command) {
    case TurtleCommand::Draw:
    case TurtleCommand::Move:
    case TurtleCommand::DrawNoVertex:
    case TurtleCommand::MoveNoVertex:
    case TurtleCommand::DrawHalf:
    case TurtleCommand::MoveHalf:
      return true;
    default:
      return false;
  }
}

bool is_color_index(double c) {
  return c >= 0.0 && c < static_cast<double>(kMaxColorIndex) + 1.0;
}

// One ring of a span: its centre, curve parameter and radius.
struct Ring {
  glm::dvec3 position{0.0};
  double t = 0.0;
  double radius = 0.0;
};

// Where a ring's points are in a sheet: from `first`, or all at `first`
// when the ring has shrunk to one point.
struct RingPoints {
  std::uint32_t first = 0;
  bool collapsed = false;
  [[nodiscard]] std::uint32_t at(std::uint32_t i) const {
    return collapsed ? first : first + i;
  }
};

// The least rotation that turns unit vector `from` onto unit vector `to`,
// applied to v.
glm::dvec3 least_rotation(const glm::dvec3& from, const glm::dvec3& to,
                          const glm::dvec3& v) {
  const glm::dvec3 axis = glm::cross(from, to);
  const double sin_a = glm::length(axis);
  const double cos_a = glm::dot(from, to);
  if (sin_a < 1e-15) {
    if (cos_a > 0.0) return v;
    // Turned right round: any half turn about an axis across `from`.
    glm::dvec3 across = glm::cross(from, glm::dvec3(1.0, 0.0, 0.0));
    if (glm::length(across) < 0.5) {
      across = glm::cross(from, glm::dvec3(0.0, 1.0, 0.0));
    }
    across = glm::normalize(across);
    return 2.0 * glm::dot(v, across) * across - v;
  }
  const glm::dvec3 k = axis / sin_a;
  return v * cos_a + glm::cross(k, v) * sin_a +
         k * glm::dot(k, v) * (1.0 - cos_a);
}

// v, across unit vector h, turned by `angle` radians about h.
glm::dvec3 roll_about(const glm::dvec3& h, const glm::dvec3& v, double angle) {
  return v * std::cos(angle) + glm::cross(h, v) * std::sin(angle);
}

// A generalized cylinder's last control point, as the next span needs it.
struct CylinderPoint {
  glm::dvec3 left{0.0};
  glm::dvec3 up{0.0};
  glm::dvec2 radius_tangent{0.0};
  const Contour* contour = nullptr;
  int sides = 0;
  // The sheet swept from a contour so far (−1: none) and the first of the
  // points of its last ring.
  std::int32_t sheet = -1;
  RingPoints ring;
};

struct TurtleState {
  Turtle turtle;
  double width = 1.0;  // diameter in model units, width_scale applied
  int color = 0;
  double step = 1.0;
  double angle_deg = 45.0;
  glm::dvec3 tropism{0.0};
  double elasticity = 0.0;
  // cpfg's movements' elasticities, which `]` restores with the rest.
  std::array<double, kMaxMovements> movement_elasticity{};
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
  // The radius tangents (`@Gr`): the first ends the span to this control
  // point, the second starts the span from it; 0 means linear.
  std::array<glm::dvec2, 2> radius_tangents{};
  bool scale_radius_tangents = false;
  // The cross-section (`@#`; none: the circle) and its sides (`@!`).
  const Contour* contour = nullptr;
  int contour_sides = 8;
  // What the span to the next control point takes from the last one.
  CylinderPoint cylinder;
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
    for (std::size_t i = 0;
         i < std::min(settings_.movements.size(), kMaxMovements); ++i) {
      state_.movement_elasticity[i] = settings_.movements[i].elasticity;
    }
    state_.contour_sides = settings_.contour_sides;
    buffers_.resize(static_cast<std::size_t>(homomorphism_depth()) + 1);
    slot_buffers_.resize(buffers_.size());
  }

  void reserve(std::size_t segments) { skeleton_.segments.reserve(segments); }

  int homomorphism_depth() const {
    return settings_.homomorphism_depth.value_or(settings_.maximum_depth);
  }

  /// cpfg's variables, which the homomorphism may read and draw from.
  void use_variables(Variables* variables) { variables_ = variables; }

  // A homomorphism can multiply the modules the turtle reads without
  // drawing anything; `on_limit` throws when more than `most` are read.
  void limit_modules(std::uint64_t most, std::function<void()> on_limit) {
    max_modules_ = most;
    on_limit_ = std::move(on_limit);
  }

  // The segments drawn, counted here where the derivation could only bound
  // them (a conditional homomorphism); `on_limit` throws past `most`.
  void limit_segments(std::uint64_t most, std::function<void()> on_limit) {
    max_segments_ = most;
    on_segment_limit_ = std::move(on_limit);
  }

  void run(const ModuleString& modules) {
    for (std::size_t i = 0; i < modules.size(); ++i) {
      interpret(modules.symbol(i), modules.parameters(i), modules.generation(i),
                0);
    }
  }

  // Writes the turtle's answer into each query module, walking the string
  // as the final interpretation will (homomorphism included), as cpfg's
  // environment pass does before each step (cpfg's interpret.c).
  void answer_queries(ModuleString& modules) {
    for (std::size_t i = 0; i < modules.size(); ++i) {
      const SymbolId symbol = modules.symbol(i);
      const TurtleCommand command = grammar_.commands[symbol];
      if (is_query(command)) {
        const glm::dvec3 v = answer(command);
        const std::span<double> out = modules.mutable_parameters(i);
        for (std::size_t k = 0; k < std::min<std::size_t>(out.size(), 3); ++k)
          out[k] = v[static_cast<glm::length_t>(k)];
        continue;
      }
      interpret(symbol, modules.parameters(i), modules.generation(i), 0);
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
    if (depth < homomorphism_depth() && homomorphisms_.has_rules(symbol)) {
      if (const Production* rule = homomorphisms_.first_applicable(
              symbol, params, variables_,
              &slot_buffers_[static_cast<std::size_t>(depth)])) {
        if (rule->successor_from_body) {
          const EmittedModules modules =
              take_emitted(*variables_, *grammar_.source, rule->offset);
          for (std::size_t k = 0; k < modules.symbols.size(); ++k) {
            interpret(modules.symbols[k],
                      std::span<const double>(modules.values)
                          .subspan(modules.begins[k],
                                   modules.begins[k + 1] - modules.begins[k]),
                      generation, depth + 1);
          }
          return;
        }
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
    if (skeleton_.segments.size() > max_segments_) on_segment_limit_();
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

  // cpfg's coordinates are Y-up: lsolid's (x, y, z) is cpfg's (x, z, −y)
  // (docs/turtle.md), and cpfg keeps U = −(H × L) where lsolid keeps
  // H × L, so cpfg's up is lsolid's −up.
  // PlantGL's turtle (L-Py) starts with left (0, −1, 0) and up (1, 0, 0)
  // (its turtleparam.cpp): lsolid's frame turned a quarter about Z.
  glm::dvec3 answer(TurtleCommand command) const {
    const Turtle& t = state_.turtle;
    const bool plantgl = settings_.query_frame == QueryFrame::PlantGL;
    const auto frame = [&](const glm::dvec3& v) {
      return plantgl ? glm::dvec3(-v.y, v.x, v.z) : glm::dvec3(v.x, v.z, -v.y);
    };
    switch (command) {
      case TurtleCommand::QueryHeading:
        return frame(t.heading());
      case TurtleCommand::QueryLeft:
        return frame(t.left());
      case TurtleCommand::QueryUp:
        return plantgl ? frame(t.up()) : -frame(t.up());
      default:
        return frame(t.position());
    }
  }

  // A point or direction given in the notation's coordinates (answer's
  // inverse), a missing z being 0.
  glm::dvec3 from_frame(std::span<const double> p) const {
    const double a = p[0];
    const double b = p[1];
    const double c = p.size() > 2 ? p[2] : 0.0;
    switch (settings_.query_frame) {
      case QueryFrame::PlantGL:
        return glm::dvec3(b, -a, c);
      case QueryFrame::Babylon:
        // Its home frame (H, L, U) = (+X, +Z, +Y) is lsolid's.
        return glm::dvec3(-c, -b, a);
      case QueryFrame::Cpfg:
        break;
    }
    return glm::dvec3(a, -c, b);
  }

  // cpfg's `@R` (blackbox.c): a zero heading is cpfg's up; an up that is
  // zero or not exactly across the heading leaves up to the least
  // rotation. PlantGL's setHead keeps the part of up across the heading.
  void set_heading(std::span<const double> params) {
    Turtle& turtle = state_.turtle;
    glm::dvec3 h =
        from_frame(params.first(std::min<std::size_t>(3, params.size())));
    // PlantGL and L-system Explorer keep up's part across the heading.
    const bool plantgl = settings_.query_frame != QueryFrame::Cpfg;
    if (h == glm::dvec3(0.0)) {
      if (plantgl) return;
      h = glm::dvec3(0.0, 0.0, 1.0);
    }
    if (params.size() < 6) {
      turtle.set_heading(h);
      return;
    }
    const glm::dvec3 u = from_frame(params.subspan(3, 3));
    if (plantgl) {
      turtle.set_heading_and_up(h, u);
    } else if (u != glm::dvec3(0.0) && glm::dot(u, h) == 0.0) {
      turtle.set_heading_and_up(h, -u);  // cpfg's up is lsolid's −up
    } else {
      turtle.set_heading(h);
    }
  }

  // PlantGL's lineTo: a segment straight to the point, of end radius r
  // when given; the frame stays as it was.
  void line_to(std::span<const double> params, std::uint32_t generation) {
    Turtle& turtle = state_.turtle;
    const glm::dvec3 p0 = turtle.position();
    turtle.set_position(from_frame(params.first(3)));
    check_finite();
    if (!polygons_.empty()) {
      add_vertex();
      return;
    }
    const double start = generation_width(state_.width, generation);
    if (params.size() > 3 && params[3] >= 0.0) {
      state_.width = params[3] * settings_.width_scale;
    }
    if (!moved_from(p0)) {
      ++skeleton_.zero_length_segments;
      return;
    }
    push_segment(p0, start, generation_width(state_.width, generation));
  }

  // Whether the turtle has moved from p0 far enough for a segment to have
  // a direction (draw says why).
  bool moved_from(const glm::dvec3& p0) const {
    return glm::length(state_.turtle.position() - p0) >
           kShortestMove * std::max(1.0, glm::length(p0));
  }

  // A segment from p0 to the turtle, joined to the last one drawn.
  void push_segment(const glm::dvec3& p0, double start, double end) {
    skeleton_.segments.push_back(Segment{p0, state_.turtle.position(), start,
                                         end, state_.color,
                                         state_.last_segment});
    state_.last_segment =
        static_cast<std::int32_t>(skeleton_.segments.size() - 1);
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
    CylinderPoint& c = state_.cylinder;
    c.left = state_.turtle.left();
    c.up = state_.turtle.up();
    c.radius_tangent = state_.radius_tangents[1];
    if (c.contour != state_.contour || c.sides != state_.contour_sides) {
      c.sheet = -1;  // a new cross-section starts a new sheet
    }
    c.contour = state_.contour;
    c.sides = state_.contour_sides;
  }

  // The span of a generalized cylinder from its last control point to the
  // turtle, as cpfg's general.c (interpolate_connection) draws it: a cubic
  // Hermite curve whose tangents are the headings at both ends times the
  // chord's length and the `@Gt` factors; along it, `pieces` + 1 rings at
  // equal steps of a second parameter r, each at curve parameter t(r) and
  // of radius ρ(r), two more Hermite cubics whose end tangents are the
  // radius tangents of `@Gr` (by default t = r and ρ linear). A chord under
  // 10⁻⁵ draws nothing, as in cpfg. Round, the rings become the ends of
  // chained segments; with a contour, the rings of one sheet.
  void draw_cylinder_span(int pieces, std::uint32_t generation) {
    const glm::dvec3 p1 = state_.cylinder_point;
    const glm::dvec3 p2 = state_.turtle.position();
    const double length = glm::length(p2 - p1);
    if (!(length >= 1e-5)) return;
    const glm::dvec3 t1 =
        state_.cylinder_heading * (length * state_.tangent_factors[0]);
    const glm::dvec3 t2 =
        state_.turtle.heading() * (length * state_.tangent_factors[1]);
    const double r1 = state_.cylinder_width / 2.0;
    const double r2 = generation_width(state_.width, generation) / 2.0;
    glm::dvec2 rt1 = state_.cylinder.radius_tangent;
    glm::dvec2 rt2 = state_.radius_tangents[0];
    if (state_.scale_radius_tangents) {
      rt1.y *= length;
      rt2.y *= length;
    }
    if (rt1 == glm::dvec2(0.0)) rt1 = {1.0, r2 - r1};
    if (rt2 == glm::dvec2(0.0)) rt2 = {1.0, r2 - r1};
    const auto curve = [&](double t) {
      const double tt = t * t;
      const double ttt = tt * t;
      return (2 * ttt - 3 * tt + 1) * p1 + (ttt - 2 * tt + t) * t1 +
             (-2 * ttt + 3 * tt) * p2 + (ttt - tt) * t2;
    };
    const auto tangent = [&](double t) {
      const double tt = t * t;
      return (6 * tt - 6 * t) * p1 + (3 * tt - 4 * t + 1) * t1 +
             (-6 * tt + 6 * t) * p2 + (3 * tt - 2 * t) * t2;
    };
    std::vector<Ring>& rings = rings_;
    rings.clear();
    for (int k = 0; k <= pieces; ++k) {
      const double r = static_cast<double>(k) / pieces;
      const double rr = r * r;
      const double rrr = rr * r;
      const double h01 = -2 * rrr + 3 * rr;
      const double h10 = rrr - 2 * rr + r;
      const double h11 = rrr - rr;
      const double t =
          k == 0 ? 0.0 : (k == pieces ? 1.0 : h01 + h10 * rt1.x + h11 * rt2.x);
      const double radius =
          k == 0        ? r1
          : k == pieces ? r2
                        : r1 + (r2 - r1) * h01 + h10 * rt1.y + h11 * rt2.y;
      const glm::dvec3 at = k == 0 ? p1 : (k == pieces ? p2 : curve(t));
      if (!std::isfinite(glm::length(at)) || !std::isfinite(radius)) {
        state_.turtle.set_position(at * radius);
        check_finite();  // throws: the curve left the doubles
      }
      rings.push_back(Ring{at, t, radius});
    }
    if (state_.cylinder.contour == nullptr) {
      state_.last_segment = state_.cylinder_parent;
      for (int k = 1; k <= pieces; ++k) {
        const Ring& from = rings[static_cast<std::size_t>(k - 1)];
        const Ring& to = rings[static_cast<std::size_t>(k)];
        if (to.position == from.position) continue;
        skeleton_.segments.push_back(Segment{
            from.position, to.position, 2.0 * std::fabs(from.radius),
            2.0 * std::fabs(to.radius), state_.color, state_.last_segment});
        state_.last_segment =
            static_cast<std::int32_t>(skeleton_.segments.size() - 1);
      }
      state_.cylinder_parent = state_.last_segment;
      return;
    }
    sweep_contour(rings, tangent);
  }

  // The rings of a span swept from the contour into the cylinder's sheet.
  // Between the control points' frames each ring's frame is the first's
  // turned along with the heading (the least rotation, where cpfg's
  // adjust_up_and_leftS takes an arcsine that stops at 90°), then rolled
  // by the twist times t, the twist being what brings it onto the last
  // frame with `twist of cylinders: on`, else 0; the last ring takes the
  // turtle's own frame. A ring point (x, y) of the contour at radius ρ is
  // at the ring's centre + ρ (x cpfg-up − y left), cpfg-up being −up here.
  template <class Tangent>
  void sweep_contour(const std::vector<Ring>& rings, const Tangent& tangent) {
    CylinderPoint& c = state_.cylinder;
    const Turtle& turtle = state_.turtle;
    const glm::dvec3 h1 = state_.cylinder_heading;
    const auto carried = [&](const glm::dvec3& h, const glm::dvec3& v) {
      return least_rotation(h1, h, v);
    };
    double twist = 0.0;
    if (settings_.twist_cylinders) {
      const glm::dvec3 u = carried(turtle.heading(), c.up);
      twist = std::atan2(glm::dot(glm::cross(u, turtle.up()), turtle.heading()),
                         glm::dot(u, turtle.up()));
    }
    const std::vector<glm::dvec2>& shape = contour_points(*c.contour, c.sides);
    if (c.sheet < 0) {
      skeleton_.sheets.push_back(
          Sheet{.color = state_.color, .parent = state_.cylinder_parent});
      c.sheet = static_cast<std::int32_t>(skeleton_.sheets.size() - 1);
      c.ring = add_ring(skeleton_.sheets.back(), shape, rings.front().position,
                        rings.front().radius, c.up, c.left);
    }
    Sheet& sheet = skeleton_.sheets[static_cast<std::size_t>(c.sheet)];
    sheet.color = state_.color;
    for (std::size_t k = 1; k < rings.size(); ++k) {
      const Ring& ring = rings[k];
      glm::dvec3 up = turtle.up();
      glm::dvec3 left = turtle.left();
      if (k + 1 < rings.size()) {
        glm::dvec3 h = tangent(ring.t);
        h = glm::length(h) > 0.0 ? glm::normalize(h) : turtle.heading();
        up = roll_about(h, carried(h, c.up), twist * ring.t);
        left = roll_about(h, carried(h, c.left), twist * ring.t);
      }
      const RingPoints next =
          add_ring(sheet, shape, ring.position, ring.radius, up, left);
      join_rings(sheet, c.ring, next, shape.size());
      c.ring = next;
    }
    state_.last_segment = state_.cylinder_parent;
  }

  // A ring's points, one only where it has shrunk to a point (a leaf's
  // tip drawn at radius 0).
  static RingPoints add_ring(Sheet& sheet, const std::vector<glm::dvec2>& shape,
                             const glm::dvec3& centre, double radius,
                             const glm::dvec3& up, const glm::dvec3& left) {
    RingPoints ring{.first = static_cast<std::uint32_t>(sheet.points.size())};
    for (const glm::dvec2& p : shape) {
      sheet.points.push_back(centre - radius * (p.x * up + p.y * left));
    }
    const glm::dvec3 first = sheet.points[ring.first];
    if (std::all_of(sheet.points.begin() + ring.first, sheet.points.end(),
                    [&](const glm::dvec3& p) { return p == first; })) {
      sheet.points.resize(ring.first + 1);
      ring.collapsed = true;
    }
    return ring;
  }

  // Two triangles between each pair of neighbouring points of two rings,
  // but none without area (at a ring shrunk to a point, a fan).
  static void join_rings(Sheet& sheet, RingPoints a, RingPoints b,
                         std::size_t count) {
    const auto add = [&](std::uint32_t i, std::uint32_t j, std::uint32_t k) {
      if (sheet.points[i] == sheet.points[j] ||
          sheet.points[j] == sheet.points[k] ||
          sheet.points[i] == sheet.points[k]) {
        return;
      }
      sheet.triangles.push_back({i, j, k});
    };
    for (std::uint32_t i = 0; i + 1 < count; ++i) {
      add(a.at(i), a.at(i + 1), b.at(i + 1));
      add(a.at(i), b.at(i + 1), b.at(i));
    }
  }

  // The contour `@#(id)` names.
  const Contour& contour_of(double id) const {
    const auto is_unknown = [this](double v) {
      return v != std::trunc(v) || !grammar_.contours.contains(static_cast<int>(
                                       std::clamp(v, -1e9, 1e9)));
    };
    if (is_unknown(id)) {
      throw error_at(
          *grammar_.source,
          place_of(grammar_, {TurtleCommand::SelectContour}, is_unknown,
                   grammar_.axiom_offset),
          "no contour: line of the view file names contour " + number_text(id));
    }
    const Contour& contour = grammar_.contours.at(static_cast<int>(id));
    if (contour.closed) {
      throw error_at(
          *grammar_.source,
          place_of(
              grammar_, {TurtleCommand::SelectContour},
              [&](double v) { return v == id; }, grammar_.axiom_offset),
          "contour " + number_text(id) +
              " is closed; closed contours (a solid cross-section other than "
              "the circle) are not supported yet");
    }
    return contour;
  }

  // A contour sampled at `sides` (cached: every ring of a model uses one
  // or two).
  const std::vector<glm::dvec2>& contour_points(const Contour& contour,
                                                int sides) {
    auto& points = sampled_contours_[{&contour, sides}];
    if (points.empty()) points = sample_contour(contour, sides);
    return points;
  }

  double angle(std::span<const double> params) const {
    return params.empty() ? state_.angle_deg : params[0];
  }

  double generation_width(double width, std::uint32_t generation) const {
    return std::max(0.0, width - settings_.width_decrement_per_generation *
                                     settings_.width_scale * generation);
  }

  // cpfg's movements (movements.c, Mech 1994), before each step. The
  // tropisms sum to one direction V = Σ e·cos γ·T + Σ e·sin γ·T × (H × T)
  // / |H × T|, toward which the heading turns about H × V by |H × V|
  // radians, at most 1. The torques sum to one direction D, and the turtle
  // rolls about its heading, up toward D's part across the heading, by the
  // sine of the angle between them times |D|, at most 1 radian. cpfg
  // rebuilds up from the last step's frame (adjust_up_and_left), which
  // forgets a roll made since; lsolid turns the whole frame, keeping it.
  void adjust_for_movements() {
    Turtle& turtle = state_.turtle;
    const glm::dvec3 h = turtle.heading();
    glm::dvec3 toward{0.0};
    glm::dvec3 torque{0.0};
    const std::size_t count =
        std::min(settings_.movements.size(), kMaxMovements);
    for (std::size_t i = 0; i < count; ++i) {
      const Movement& m = settings_.movements[i];
      const double e = state_.movement_elasticity[i];
      if (e == 0.0) continue;
      if (m.kind == Movement::Kind::Torque) {
        torque += e * m.direction;
        continue;
      }
      const SinCos sc = sin_cos_deg(m.angle_deg);
      toward += e * sc.cos * m.direction;
      if (sc.sin == 0.0) continue;
      glm::dvec3 across = glm::cross(h, m.direction);
      double length = glm::length(across);
      if (length < 1e-7) {
        // H along T: cpfg turns about left instead.
        across = turtle.left();
        length = 1.0;
      }
      toward += e * sc.sin / length * glm::cross(m.direction, across);
    }
    const double bend = glm::length(glm::cross(h, toward));
    if (bend >= 1e-6) turtle.bend(toward * (std::min(bend, 1.0) / bend), 1.0);
    if (torque == glm::dvec3(0.0)) return;
    const glm::dvec3 heading = turtle.heading();
    const glm::dvec3 d = glm::normalize(torque);
    const glm::dvec3 side = glm::cross(heading, d);
    if (glm::dot(side, side) <= 1e-8) return;
    // D's part across the heading, as long as D.
    const glm::dvec3 across = glm::cross(side, heading) * glm::length(torque);
    const glm::dvec3 axis = glm::cross(turtle.up(), across);
    const double sine = glm::length(axis);
    if (sine < 1e-7) return;
    const double angle = std::min(sine, 1.0) * 180.0 / std::numbers::pi;
    // A roll turns about the heading, up toward −left: up turns toward D
    // by a positive roll when up × D runs with the heading.
    turtle.roll(glm::dot(axis, heading) > 0.0 ? angle : -angle);
  }

  // cpfg's tropism also bends after `f` and `g` (interpret.c's bend()).
  void bend_after_move() {
    if (settings_.bend_after_moves && state_.elasticity != 0.0) {
      state_.turtle.bend(state_.tropism, state_.elasticity);
    }
  }

  void change_movement(TurtleCommand command, std::span<const double> params) {
    if (params.empty()) return;
    const double index = params[0];
    const std::size_t count =
        std::min(settings_.movements.size(), kMaxMovements);
    // cpfg ignores a movement it does not have ("Movement index out of
    // range!"); the front end warns where the index is written.
    if (!(index >= 1.0 && index < static_cast<double>(count) + 1.0)) return;
    const auto i = static_cast<std::size_t>(index) - 1;
    double& e = state_.movement_elasticity[i];
    const double step =
        params.size() > 1 ? params[1] : settings_.movements[i].elasticity_step;
    switch (command) {
      case TurtleCommand::MovementElasticity:
        e = params.size() > 1 ? params[1] : 0.0;
        break;
      case TurtleCommand::MovementElasticityUp:
        e += step;
        break;
      default:
        e -= step;
        break;
    }
  }

  void execute(TurtleCommand command, std::span<const double> params,
               std::uint32_t generation) {
    Turtle& turtle = state_.turtle;
    if (!settings_.movements.empty() && is_step(command)) {
      adjust_for_movements();
    }
    switch (command) {
      case TurtleCommand::None:
      case TurtleCommand::Surface:  // drawn by interpret, which knows which
      case TurtleCommand::Cut:
      case TurtleCommand::QueryPosition:  // answered by answer_queries
      case TurtleCommand::QueryHeading:
      case TurtleCommand::QueryLeft:
      case TurtleCommand::QueryUp:
        return;
      case TurtleCommand::Draw:
        if (!polygons_.empty()) {
          turtle.move(params.empty() ? state_.step : params[0]);
          add_vertex();
          bend_after_move();
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
        bend_after_move();
        return;
      case TurtleCommand::MoveNoVertex:
        turtle.move(params.empty() ? state_.step : params[0]);
        state_.last_segment = -1;
        bend_after_move();
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
        state_.cylinder.sheet = -1;
        set_cylinder_point(generation);
        state_.cylinder_parent = state_.last_segment;
        return;
      case TurtleCommand::CylinderPoint:
      case TurtleCommand::CylinderEnd: {
        // cpfg's blackbox.c: n pieces, at least 1; without a parameter, 1.
        const double pieces = params.empty() ? 1.0 : params[0];
        // Without `@Gs` cpfg starts a cylinder here (continue_spline).
        if (!state_.in_cylinder) {
          state_.cylinder_parent = state_.last_segment;
          state_.cylinder.sheet = -1;
        }
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
      case TurtleCommand::CylinderRadiusTangents:
        // cpfg's blackbox.c: one parameter switches the scaling, two set
        // both tangents, four set each.
        if (params.size() == 1) {
          state_.scale_radius_tangents = params[0] != 0.0;
        } else if (params.size() >= 2) {
          const auto tangent = [](double angle_deg, double size) {
            const double a = angle_deg * std::numbers::pi / 180.0;
            return glm::dvec2(std::cos(a) * size, std::sin(a) * size);
          };
          state_.radius_tangents[0] = tangent(params[0], params[1]);
          state_.radius_tangents[1] = params.size() >= 4
                                          ? tangent(params[2], params[3])
                                          : state_.radius_tangents[0];
        }
        return;
      case TurtleCommand::SelectContour:
        state_.contour = params.empty() ? nullptr : &contour_of(params[0]);
        return;
      case TurtleCommand::ContourSides:
        // cpfg's blackbox.c: 8 without n, at least 3.
        state_.contour_sides =
            params.empty() || std::isnan(params[0])
                ? settings_.contour_sides
                : static_cast<int>(
                      std::clamp(params[0], 3.0, double{kMostContourSides}));
        return;
      case TurtleCommand::CylinderTangents:
        if (params.empty()) return;
        state_.tangent_factors = {params[0],
                                  params.size() > 1 ? params[1] : params[0]};
        return;
      case TurtleCommand::MovementElasticity:
      case TurtleCommand::MovementElasticityUp:
      case TurtleCommand::MovementElasticityDown:
        change_movement(command, params);
        return;
      case TurtleCommand::SetHeading:
        set_heading(params);
        return;
      case TurtleCommand::MoveTo:
        turtle.set_position(
            from_frame(params.first(std::min<std::size_t>(3, params.size()))));
        check_finite();
        state_.last_segment = -1;
        return;
      case TurtleCommand::LineTo:
        line_to(params, generation);
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
    const bool moved = length != 0.0 && moved_from(p0);
    if (!moved) ++skeleton_.zero_length_segments;
    // Inside a generalized cylinder `F` only moves (cpfg's start_spline:
    // "not to interpret f and F"); the cylinder draws the curve.
    if (moved && !state_.in_cylinder) {
      push_segment(p0, start,
                   generation_width(state_.width, generation) * scale);
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
  std::uint64_t max_segments_ = std::numeric_limits<std::uint64_t>::max();
  std::function<void()> on_segment_limit_;
  std::vector<Ring> rings_;
  std::map<std::pair<const Contour*, int>, std::vector<glm::dvec2>>
      sampled_contours_;
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
  interpreter.limit_segments(derivation.max_segments, [&] {
    throw limit_error(
        grammar, derivation, n,
        "draws more than the limit of " +
            count_text(static_cast<double>(derivation.max_segments)) +
            " segments (--max-segments)");
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

ParseError width_error(const Grammar& grammar, double width,
                       std::string message) {
  const double scale = grammar.settings.width_scale;
  const auto at_least = [&](double v) { return std::fabs(v * scale) >= width; };
  const auto constant =
      find_module(grammar, {TurtleCommand::Width},
                  [&](std::span<const Expression> parameters) {
                    return !parameters.empty() && parameters[0].is_constant() &&
                           at_least(parameters[0].constant_value());
                  });
  std::size_t place = grammar.axiom_offset;
  if (constant) {
    place = *constant;
  } else if (grammar.settings.width_offset &&
             at_least(grammar.settings.initial_width)) {
    // Placed in the view file where the width comes from there (cpfg).
    const SourceFile& source = grammar.settings.width_source
                                   ? *grammar.settings.width_source
                                   : *grammar.source;
    return error_at(source, *grammar.settings.width_offset, std::move(message));
  } else {
    // A computed width, else the setting however the notation scales it
    // (Lparser's thickness is a share of the length).
    place = place_of(
        grammar, {TurtleCommand::Width}, [](double) { return false; },
        grammar.settings.width_offset && !grammar.settings.width_source
            ? *grammar.settings.width_offset
            : grammar.axiom_offset);
  }
  return error_at(*grammar.source, place, std::move(message));
}

bool uses_queries(const Grammar& grammar) {
  const auto writes_query = [&](const Successor& s) {
    return std::any_of(s.symbols().begin(), s.symbols().end(), [&](SymbolId m) {
      return is_query(grammar.commands[m]);
    });
  };
  if (writes_query(grammar.axiom)) return true;
  return std::any_of(
             grammar.productions.begin(), grammar.productions.end(),
             [&](const Production& p) { return writes_query(p.successor); }) ||
         std::any_of(
             grammar.decompositions.begin(), grammar.decompositions.end(),
             [&](const Production& p) { return writes_query(p.successor); });
}

void answer_queries(const Grammar& grammar, ModuleString& modules,
                    Variables* variables) {
  Interpreter interpreter(grammar, {});
  interpreter.use_variables(variables);
  interpreter.answer_queries(modules);
}

}  // namespace lsys
