// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <CLI/App.hpp>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "lsolid/print_settings.hpp"
#include "lsys/derivation.hpp"
#include "lsys/diagnostic.hpp"
#include "lsys/grammar.hpp"
#include "lsys/interpretation.hpp"

namespace lsolid::cli {

/// What every command that reads a `.ls` file takes. Numbers are kept as
/// typed and checked by derivation_options, so that `-1` or `1e300` is
/// refused with the option's name rather than wrapped or rounded.
struct GrammarInput {
  std::string file;
  std::optional<std::string> derivation_length;  ///< -n
  std::optional<std::string> seed;
  std::vector<std::string> defines;
  std::optional<std::string> max_segments;
  std::optional<std::string> max_modules;
  std::optional<std::string> max_memory;  ///< in MiB
  std::optional<std::string> roll;
  std::optional<std::string> dialect;     ///< --dialect
  std::string system;                     ///< --system
  std::string view_file;                  ///< --view
  std::vector<std::string> include_dirs;  ///< --include-dir
};

/// A whole number typed for an option: decimal digits only, from `least` to
/// `most`.
/// @throws lsys::ParseError named after the option, showing the text with a
///   caret: `expected a whole number from 1 to 9007199254740992, not '-1'`.
[[nodiscard]] std::uint64_t parse_whole_number(const std::string& text,
                                               const std::string& option,
                                               std::uint64_t least,
                                               std::uint64_t most);

/// Registers FILE, -n, --seed, --define, --max-segments, --max-modules and
/// (with `with_roll`) --roll on a command.
void add_grammar_options(CLI::App& command, GrammarInput& input, bool with_roll,
                         bool is_file_required = true);

/// Warns on standard error about polygons the turtle dropped: unclosed,
/// unmatched `}`, fewer than 3 distinct points.
void warn_about_polygons(const lsys::Skeleton& skeleton);

/// Reads the file with the command line's defines.
/// @throws lsys::ParseError.
[[nodiscard]] lsys::Grammar load_grammar(const GrammarInput& input);
/// The command line's derivation options, checked.
/// @throws lsys::ParseError for a number out of range.
[[nodiscard]] lsys::DerivationOptions derivation_options(
    const GrammarInput& input);
[[nodiscard]] lsys::InterpretOptions interpret_options(
    const GrammarInput& input);

/// `lsolid derive`: prints the derived string, or its statistics as JSON.
struct DeriveCommand {
  GrammarInput input;
  bool stats = false;
};
/// @throws lsys::ParseError, lsolid::IoError.
void run_derive(const DeriveCommand& command);

/// Print options given on the command line, as text until parsed.
struct PrintInput {
  std::optional<std::string> wall;
  std::optional<std::string> height;
  std::optional<std::string> size;
  std::optional<std::string> scale;
  std::optional<std::string> tolerance;
  std::optional<std::string> base;
  std::optional<std::string> colors;
  std::optional<std::string> profile;
};

/// Registers --wall, --height, --size, --scale, --tolerance, --base,
/// --colors and --profile.
void add_print_options(CLI::App& command, PrintInput& input);

/// The file's print settings overridden by the command line's.
/// @throws lsys::ParseError for a bad length.
[[nodiscard]] PrintSettings print_settings(const lsys::Grammar& grammar,
                                           const PrintInput& input);

/// `lsolid skeleton`: prints the turtle's segments and polygons.
struct SkeletonCommand {
  GrammarInput input;
  PrintInput print;
  bool json = false;
};
/// @throws lsys::ParseError, lsolid::IoError.
void run_skeleton(const SkeletonCommand& command);

/// `lsolid FILE.ls`: builds the printable mesh and writes it.
struct BuildCommand {
  GrammarInput input;
  PrintInput print;
  std::string output;  ///< empty: FILE with .stl beside the input
  bool ascii = false;
  bool no_union = false;
  std::string union_engine = "exact";  ///< `--union-engine`
  std::optional<std::string> threads;  ///< `--threads`, as typed
  bool no_decimate = false;
  bool multi_material = false;  ///< one volume per colour (3MF, OBJ)
  std::optional<std::string> max_triangles;  ///< as typed
  std::string preview;  ///< a PNG to render the written mesh to, or empty
  std::optional<std::string> bed;  ///< the build volume, `220x220x250mm`
  bool force = false;              ///< write even if it does not fit the bed
  bool one_piece = false;          ///< refuse a model of separate pieces
  bool quiet = false;              ///< no report (errors still go to stderr)
  bool json = false;               ///< the report as one JSON object
};
/// A build that ran to its end but whose model is not written: it is not
/// printable, does not fit the --bed, or falls apart with --one-piece. The
/// report has been printed; the message says what was refused.
class Refused : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Builds, reports and writes.
/// @throws Refused, lsys::ParseError, GeometryError, IoError.
void run_build(const BuildCommand& command);

/// What `--json` prints for a build that failed before its report: one
/// line, `{"output", "written": false, "exit_code", "error": {"message",
/// "place": {"file", "line", "column"} or null}}`.
[[nodiscard]] std::string failed_build_json(const BuildCommand& command,
                                            int exit_code,
                                            const lsys::Diagnostic& error);

/// `lsolid view FILE`: serves a page that shows the model as it is built,
/// and builds it again when the file is saved or a control changed.
struct ViewCommand {
  GrammarInput input;
  PrintInput print;
  std::optional<std::string> bed;  ///< the build volume drawn as the bed
  std::string host = "127.0.0.1";
  int port = 0;  ///< 0: the first free one from 8400 on
};
/// Serves until interrupted (Ctrl-C) or terminated.
/// @throws IoError when the port cannot be bound, lsys::ParseError for a
///   bad option or a file that is missing or not a regular file.
void run_view(const ViewCommand& command);

/// `lsolid check MESH`: validates an STL, OFF, 3MF or OBJ file.
struct CheckCommand {
  std::string file;
  bool json = false;
  bool one_piece = false;  ///< separate pieces make the verdict "not"
};
/// Returns whether the mesh is printable (and one piece, with `one_piece`).
/// @throws lsys::ParseError for a malformed file or one without triangles,
///   IoError when it cannot be read.
bool run_check(const CheckCommand& command);

}  // namespace lsolid::cli
