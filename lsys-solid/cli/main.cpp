// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The lsolid command line: a client of lsys-core and lsys-solid, and the one
// place where errors become messages and exit codes (docs/cli.md).
#include <unistd.h>

#include <CLI/CLI.hpp>
#include <array>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <exception>

#include "commands.hpp"
#include "lsolid/errors.hpp"
#include "lsys/diagnostic.hpp"
#include "memory.hpp"

namespace {

constexpr int kExitNotPrintable = 1;  // lsolid check's verdict
constexpr int kExitInput = 2;
constexpr int kExitGeometry = 3;
constexpr int kExitIo = 4;

constexpr const char* kExamples = R"(
Examples:
  lsolid printables/abop-1.25-bush.ls --wall 0.8mm -o bush.stl
  lsolid printables/hilbert-cube.ls --size 60mm
  lsolid check bush.stl
  lsolid printables/abop-1.25-bush.ls -n 5 --preview bush.png
  lsolid view printables/abop-1.25-bush.ls -n 5
  lsolid derive printables/hilbert-cube.ls -n 2
  lsolid derive printables/abop-1.25-bush.ls --stats
  lsolid skeleton printables/honda-2.1a.ls --json
  lsolid skeleton tree.ls --define r2=0.7 --seed 7 --roll cpfg

Exit codes: 0 success, 2 bad input, 3 geometry failure, 4 I/O failure.
Documentation: docs/cli.md, docs/language.md, docs/turtle.md.)";

}  // namespace

int main(int argc, char** argv) {
  lsolid::cli::keep_freed_memory();
  // Reports are held until the end and written by one flush, whose failure
  // then names its cause (a full disk); a terminal keeps its line buffer.
  static std::array<char, std::size_t{1} << 16U> report_buffer{};
  if (::isatty(STDOUT_FILENO) == 0) {
    std::setvbuf(stdout, report_buffer.data(), _IOFBF, report_buffer.size());
  }
  CLI::App app{"lsolid turns Lindenmayer systems into 3D-printable solids."};
  app.footer(kExamples);
  app.set_version_flag("--version", "lsolid " LSOLID_VERSION);
  app.require_subcommand(0, 1);

  lsolid::cli::BuildCommand build;
  lsolid::cli::add_grammar_options(app, build.input, true, false);
  app.add_option(
      "-o,--output", build.output,
      "output file: .stl (binary), .off, .scad (OpenSCAD), .3mf or .obj (with "
      "colours); default FILE.stl");
  app.add_flag("--ascii", build.ascii, "write ASCII STL");
  auto* bed = app.add_option(
      "--bed", build.bed,
      "the printer's build volume, e.g. 220x220x250mm: refuse to write a "
      "model that does not fit");
  app.add_flag("--force", build.force,
               "write the model even if it does not fit the --bed")
      ->needs(bed);
  app.add_flag("--one-piece", build.one_piece,
               "refuse (exit 3, nothing written) a model that falls apart "
               "into separate pieces");
  app.add_flag("-q,--quiet", build.quiet,
               "print no report (errors still go to standard error)");
  app.add_flag("--json", build.json,
               "print the report as one JSON object instead of text");
  app.add_option("--preview", build.preview,
                 "also render the mesh, shaded, to this PNG (offscreen)");
  auto* no_union = app.add_flag(
      "--no-union", build.no_union,
      "write the overlapping parts without uniting them (debugging)");
  app.add_option("--union-engine", build.union_engine,
                 "the union's engine: exact (lsolid's own, the default) or "
                 "corefine (CGAL's corefinement, to compare or report a bug)")
      ->check(CLI::IsMember({"exact", "corefine"}))
      ->excludes(no_union);
  app.add_option(
         "--threads", build.threads,
         "the threads the parts, union and decimation may use, 1 to 256 "
         "(default: all the "
         "machine's); the model is the same whatever the number")
      ->type_name("N");
  app.add_flag("--multi-material", build.multi_material,
               "in a .3mf or .obj, one volume per colour, not overlapping, "
               "for a printer with an extruder per colour")
      ->excludes(no_union);
  auto* no_decimate = app.add_flag(
      "--no-decimate", build.no_decimate,
      "keep every triangle of the union (decimation is on by default, within "
      "--tolerance)");
  app.add_option("--max-triangles", build.max_triangles,
                 "decimate to at most N triangles (4 to 4294967295), beyond "
                 "--tolerance if need be (never at the cost of validity)")
      ->type_name("N")
      ->excludes(no_decimate);
  lsolid::cli::add_print_options(app, build.print);

  lsolid::cli::DeriveCommand derive;
  CLI::App* derive_app =
      app.add_subcommand("derive", "print the derived string of an L-system");
  lsolid::cli::add_grammar_options(*derive_app, derive.input, false);
  derive_app->add_flag("--stats", derive.stats,
                       "print {\"length\", \"modules\", \"max_depth\"} as JSON "
                       "instead of the string");

  lsolid::cli::SkeletonCommand skeleton;
  CLI::App* skeleton_app = app.add_subcommand(
      "skeleton", "print the turtle's segments and polygons (model units)");
  lsolid::cli::add_grammar_options(*skeleton_app, skeleton.input, true);
  lsolid::cli::add_print_options(*skeleton_app, skeleton.print);
  skeleton_app->add_flag("--json", skeleton.json,
                         "print every segment and polygon as JSON");

  lsolid::cli::ViewCommand view;
  CLI::App* view_app = app.add_subcommand(
      "view",
      "serve a page that shows the model as it is built and builds it again "
      "when the file is saved (http://127.0.0.1:8400/)");
  lsolid::cli::add_grammar_options(*view_app, view.input, true);
  lsolid::cli::add_print_options(*view_app, view.print);
  view_app->add_option("--bed", view.bed,
                       "the printer's build volume, e.g. 220x220x250mm, drawn "
                       "as the bed; the report says whether the model fits "
                       "(default 220x220x250mm)");
  view_app->add_option(
      "--host", view.host,
      "the address to listen on (default 127.0.0.1; any but a loopback "
      "address serves the network)");
  view_app
      ->add_option("--port", view.port,
                   "the port (default the first free one from 8400)")
      ->check(CLI::Range(0, 65535));

  lsolid::cli::CheckCommand check;
  CLI::App* check_app = app.add_subcommand(
      "check",
      "check that an STL, OFF, 3MF or OBJ mesh is printable (exit 0 yes, 1 no, "
      "2 unreadable)");
  check_app->add_option("MESH", check.file, "the mesh to check")->required();
  check_app->add_flag("--json", check.json, "print the report as JSON");
  check_app->add_flag("--one-piece", check.one_piece,
                      "also require the mesh to be one piece (exit 1 if it "
                      "falls apart into several)");

  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& e) {
    const int code = app.exit(e);
    return code == 0 ? 0 : kExitInput;
  }

  const bool is_build = !check_app->parsed() && !derive_app->parsed() &&
                        !skeleton_app->parsed() && !view_app->parsed();
  if (is_build && build.input.file.empty()) {
    std::fputs(app.help().c_str(), stderr);
    return kExitInput;
  }
  const bool is_check = check_app->parsed();
  // A build with --json prints a JSON object whatever happens: its report,
  // or, when it failed before one, the error (docs/cli.md).
  const auto failed = [&](int exit_code, lsys::Diagnostic error) {
    if (is_build && build.json) {
      std::fputs(
          lsolid::cli::failed_build_json(build, exit_code, error).c_str(),
          stdout);
      std::fflush(stdout);
    }
    return exit_code;
  };
  const auto message = [](const char* what) {
    return lsys::Diagnostic{.message = what};
  };
  try {
    int code = 0;
    if (is_check && !lsolid::cli::run_check(check)) code = kExitNotPrintable;
    if (derive_app->parsed()) lsolid::cli::run_derive(derive);
    if (skeleton_app->parsed()) lsolid::cli::run_skeleton(skeleton);
    if (view_app->parsed()) lsolid::cli::run_view(view);
    if (is_build) lsolid::cli::run_build(build);
    // A report that could not be written is lost, whatever else succeeded
    // (`lsolid x.ls > /dev/full`).
    errno = 0;
    if (std::fflush(stdout) != 0 || std::ferror(stdout) != 0) {
      std::fprintf(stderr, "error: cannot write to standard output%s%s\n",
                   errno != 0 ? ": " : "",
                   errno != 0 ? std::strerror(errno) : "");
      return kExitIo;
    }
    return code;
  } catch (const lsys::ParseError& e) {
    std::fputs(lsys::format_diagnostic(e.diagnostic()).c_str(), stderr);
    return failed(kExitInput, e.diagnostic());
  } catch (const lsolid::cli::Refused& e) {
    // Its report, with "written": false, is out already.
    std::fprintf(stderr, "error: %s\n", e.what());
    return kExitGeometry;
  } catch (const lsolid::GeometryError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    return failed(kExitGeometry, message(e.what()));
  } catch (const lsolid::IoError& e) {
    std::fprintf(stderr, "error: %s\n", e.what());
    // A mesh that cannot be read is check's third verdict, "unreadable".
    return failed(is_check ? kExitInput : kExitIo, message(e.what()));
  } catch (const std::bad_alloc&) {
    std::fputs("error: out of memory\n", stderr);
    return failed(kExitGeometry, message("out of memory"));
  } catch (const std::exception& e) {
    // A check inside a library (CGAL's preconditions throw) that no stage
    // turned into one of lsolid's errors: still an error, never a crash.
    const std::string text =
        std::string(
            "an internal check failed (a bug in lsolid; please "
            "report it with this file): ") +
        e.what();
    std::fprintf(stderr, "error: %s\n", text.c_str());
    return failed(kExitGeometry, message(text.c_str()));
  }
}
