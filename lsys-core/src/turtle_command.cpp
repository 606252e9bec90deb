// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/turtle_command.hpp"

#include <array>
#include <utility>

namespace lsys {
namespace {

// ABOP p. 209 and the cpfg manual for the single characters (cpfg's `#`
// widens as its `!` narrows); `∧` and `−`
// (U+2212) are how seed 000 and typeset ABOP print `^` and `-`; `@v`, `@Tp`,
// `@Ts` are L-Py's and cpfg's spellings, and so is the sphere `@O`.
constexpr std::array<std::pair<std::string_view, TurtleCommand>, 30> kNames{{
    {"F", TurtleCommand::Draw},
    {"f", TurtleCommand::Move},
    {"G", TurtleCommand::DrawNoVertex},
    {"g", TurtleCommand::MoveNoVertex},
    {"+", TurtleCommand::TurnLeft},
    {"-", TurtleCommand::TurnRight},
    {"\u2212", TurtleCommand::TurnRight},
    {"&", TurtleCommand::PitchDown},
    {"^", TurtleCommand::PitchUp},
    {"\u2227", TurtleCommand::PitchUp},
    {"/", TurtleCommand::RollRight},
    {"\\", TurtleCommand::RollLeft},
    {"|", TurtleCommand::TurnAround},
    {"$", TurtleCommand::RollToVertical},
    {"@v", TurtleCommand::RollToVertical},
    {"[", TurtleCommand::Push},
    {"]", TurtleCommand::Pop},
    {"{", TurtleCommand::PolygonBegin},
    {".", TurtleCommand::PolygonVertex},
    {"}", TurtleCommand::PolygonEnd},
    {"!", TurtleCommand::Width},
    {"#", TurtleCommand::Widen},
    {"'", TurtleCommand::ColorNext},
    {";", TurtleCommand::ColorNext},
    {",", TurtleCommand::ColorPrevious},
    {"%", TurtleCommand::Cut},
    {"@Tp", TurtleCommand::SetTropism},
    {"@Ts", TurtleCommand::SetElasticity},
    {"\u2019", TurtleCommand::ColorNext},
    {"@O", TurtleCommand::Sphere},
}};

}  // namespace

std::optional<TurtleCommand> builtin_command(std::string_view name) noexcept {
  for (const auto& [spelling, command] : kNames) {
    if (spelling == name) return command;
  }
  return std::nullopt;
}

int max_parameters(TurtleCommand command) noexcept {
  switch (command) {
    case TurtleCommand::None:
      return 1 << 20;
    case TurtleCommand::Draw:
    case TurtleCommand::DrawNoVertex:
      return 2;
    case TurtleCommand::SetHeading:
      return 6;
    case TurtleCommand::LineTo:
      return 4;
    case TurtleCommand::MoveTo:
    case TurtleCommand::SetTropism:
    case TurtleCommand::Surface:
    case TurtleCommand::QueryPosition:
    case TurtleCommand::QueryHeading:
    case TurtleCommand::QueryLeft:
    case TurtleCommand::QueryUp:
      return 3;
    case TurtleCommand::CylinderTangents:
    case TurtleCommand::MovementElasticity:
    case TurtleCommand::MovementElasticityUp:
    case TurtleCommand::MovementElasticityDown:
      return 2;
    case TurtleCommand::CylinderRadiusTangents:
      return 4;
    case TurtleCommand::CylinderStart:
      return 0;
    case TurtleCommand::TurnAround:
    case TurtleCommand::RollToVertical:
    case TurtleCommand::RollToVerticalSwappingTurns:
    case TurtleCommand::Push:
    case TurtleCommand::Pop:
    case TurtleCommand::PolygonBegin:
    case TurtleCommand::PolygonVertex:
    case TurtleCommand::Cut:
    case TurtleCommand::SwapTurns:
      return 0;
    default:
      return 1;
  }
}

int min_parameters(TurtleCommand command) noexcept {
  switch (command) {
    case TurtleCommand::SetTropism:
    case TurtleCommand::LineTo:
      return 3;
    case TurtleCommand::SetHeading:
    case TurtleCommand::MoveTo:
      return 2;
    case TurtleCommand::SetElasticity:
    case TurtleCommand::CylinderTangents:
      return 1;
    default:
      return 0;
  }
}

}  // namespace lsys
