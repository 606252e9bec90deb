// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <functional>
#include <memory>
#include <string_view>

#include "dialects/draft.hpp"
#include "lsys/grammar.hpp"
#include "lsys/parser.hpp"
#include "lsys/source.hpp"

namespace lsys::dialects {

/// Reads lsolid's own notation (docs/language.md).
/// @throws ParseError at the place of anything malformed.
[[nodiscard]] Grammar read_ls(std::shared_ptr<const SourceFile> source,
                              const ParseOptions& options);

/// The line rules of lsolid's notation as another notation keeps them.
enum class LsVariant {
  Ls,    ///< `#` alone is a comment
  Cpfg,  ///< `#` is always a module; cpfg's blocks are refused by name
  /// As Cpfg, and before the axiom `name = value` lines (several to a line,
  /// separated by `;`) set L-system Explorer's settings and variables.
  Lowclouds,
};

/// Reads a text by the line rules of lsolid's notation, with a notation's
/// own symbols, refused names, defaults and syntax (`notation`). cpfg's
/// files, once preprocessed, are read this way.
/// @throws ParseError as read_ls.
[[nodiscard]] Grammar read_ls_lines(std::shared_ptr<const SourceFile> source,
                                    const ParseOptions& options, Draft notation,
                                    LsVariant variant);

/// Reads a cpfg `.l` file and the view file beside it
/// (docs/dialects/cpfg.md).
/// @throws ParseError as read_ls, in either file.
[[nodiscard]] Grammar read_cpfg(std::shared_ptr<const SourceFile> source,
                                const ParseOptions& options);

/// What cpfg and lpfg share: finds and reads the view file beside the
/// `.l` (its functions, surfaces and contours), runs the C preprocessor on
/// the file, and hands the preprocessed text and a Draft of the view's
/// settings to `read`, whose grammar then gets the surfaces and contours.
/// The preprocessor drops the `#include` of `ignored_headers`.
[[nodiscard]] Grammar read_with_view(
    std::shared_ptr<const SourceFile> source, const ParseOptions& options,
    const std::function<Grammar(std::shared_ptr<const SourceFile>, Draft)>&
        read,
    const std::vector<std::string>& ignored_headers);

/// Reads an lpfg `.l` file (docs/dialects/lpfg.md): cpfg's successor, whose
/// rules are C++ bodies that `produce` their successors.
[[nodiscard]] Grammar read_lpfg(std::shared_ptr<const SourceFile> source,
                                const ParseOptions& options);

/// Reads the files of Lowclouds' L-system Explorer
/// (docs/dialects/lowclouds.md).
/// @throws ParseError as read_ls.
[[nodiscard]] Grammar read_lowclouds(std::shared_ptr<const SourceFile> source,
                                     const ParseOptions& options);

/// cpfg's turtle symbols, which L-system Explorer keeps: `F f G g + - & ^
/// / \ | @v [ ] { . } ! # ; , %`, each reading one parameter at most.
[[nodiscard]] std::vector<SymbolCommand> cpfg_turtle_symbols();

/// Refuses `{(n)` wherever a successor or the axiom holds it: cpfg and
/// L-system Explorer start paths and cylinders with it, not polygons.
/// @throws ParseError at the first, with `message`.
void refuse_parameterised_braces(const Grammar& grammar,
                                 std::string_view message);

/// True when a line opens Lparser 5's keyword form: `recursion` and a
/// number (`recursion 10`).
[[nodiscard]] bool is_lparser_keyword_line(std::string_view line);

/// Reads Laurens Lapré's Lparser files (docs/dialects/lparser.md).
/// @throws ParseError as read_ls.
[[nodiscard]] Grammar read_lparser(std::shared_ptr<const SourceFile> source,
                                   const ParseOptions& options);

/// Reads one system of a Fractint `.l` file (docs/dialects/fractint.md),
/// the one ParseOptions::system names or the only one.
/// @throws ParseError as read_ls, and when the file holds several systems
///   and none is named.
[[nodiscard]] Grammar read_fractint(std::shared_ptr<const SourceFile> source,
                                    const ParseOptions& options);

/// Reads the declarative part of an L-Py file (docs/dialects/lpy.md).
/// @throws ParseError as read_ls, and at Python code in a rule.
[[nodiscard]] Grammar read_lpy(std::shared_ptr<const SourceFile> source,
                               const ParseOptions& options);

}  // namespace lsys::dialects
