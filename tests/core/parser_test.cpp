// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsys/parser.hpp"

#include <gtest/gtest.h>

#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::derived;
using testing::located_error;
using testing::parse;
using testing::parse_error;

std::string parse_error_of_system(std::string_view text, std::string system) {
  try {
    (void)parse(text, {.system = std::move(system)});
  } catch (const ParseError& e) {
    return e.diagnostic().message;
  }
  return "no error";
}

TEST(Parser, AcceptsEveryArrow) {
  for (const char* arrow : {"\u2192", "->", "-->", "::=", "=", "\u27F6"}) {
    const std::string text = std::string("axiom: F\nF ") + arrow + " F+F\nn=1";
    EXPECT_EQ(derived(text), "F+F") << arrow;
  }
}

TEST(Parser, AcceptsEveryAxiomNotation) {
  for (const char* axiom :
       {"\u03C9: X", "\u03C9 : X", "axiom: X", "Axiom: X", "premise: X", "X"}) {
    const std::string text = std::string(axiom) + "\nX -> F\nn=1";
    EXPECT_EQ(derived(text), "F") << axiom;
  }
}

TEST(Parser, AcceptsEveryDerivationLengthAndAngleNotation) {
  EXPECT_EQ(parse("n=7\nF").settings.derivation_length, 7);
  EXPECT_EQ(parse("n = 7\nF").settings.derivation_length, 7);
  EXPECT_EQ(parse("derivation length: 7\nF").settings.derivation_length, 7);
  EXPECT_EQ(parse("\u03B4=22.5\u00B0\nF").settings.angle_deg, 22.5);
  EXPECT_EQ(parse("delta = 22.5\nF").settings.angle_deg, 22.5);
  EXPECT_EQ(parse("angle: 22.5\nF").settings.angle_deg, 22.5);
  EXPECT_EQ(parse("angle factor: 16\nF").settings.angle_deg, 22.5);
}

TEST(Parser, ReadsSeveralSettingsOnOneLine) {
  const Grammar g = parse("n=2, \u03B4=90\u00B0, tropism: 0, 1, -1\nF");
  EXPECT_EQ(g.settings.derivation_length, 2);
  EXPECT_EQ(g.settings.angle_deg, 90.0);
  EXPECT_EQ(g.settings.tropism, glm::dvec3(0.0, 1.0, -1.0));
}

TEST(Parser, ReadsLabelsAndConditions) {
  const Grammar g = parse(
      "\u03C9: A(1)\np1: A(x) : x < 2 \u2192 A(x+1)\np_2 : A(x) : * \u2192 "
      "B\n");
  ASSERT_EQ(g.productions.size(), 2U);
  EXPECT_TRUE(g.productions[0].condition.has_value());
  EXPECT_FALSE(g.productions[1].condition.has_value());
}

TEST(Parser, ReadsAnyLabelBeforeTheProduction) {
  EXPECT_EQ(derived("n=1\naxiom: A(2)\nP1: A(d) : d>0 -> A(d-1)\n"), "A(1)");
  EXPECT_EQ(derived("n=1\naxiom: A\nr: A -> FA\n"), "FA");
  EXPECT_EQ(derived("n=1\naxiom: A\ngrow_2 : A \u2192 FA\n"), "FA");
  // ABOP fig. 1.31 labels its context productions over 0 and 1.
  EXPECT_EQ(derived("n=1\naxiom: 101\np1: 1 < 0 > 1 \u2192 1\n"), "111");
  // A label and a condition over constants.
  EXPECT_EQ(derived("#define t 2\nn=1\naxiom: A\nr: A : t > 1 \u2192 B\n"),
            "B");
}

// A system pasted from Houdini's parameter pane keeps its field names:
// `Premise`, `Generations`, `Angle`, and `Rule 1` to `Rule 24` before the
// productions, with `=` or `->`.
TEST(Parser, ReadsHoudinisRuleFieldNamesBeforeProductions) {
  const std::string pasted =
      "Premise: X\nGenerations: 2\nAngle: 20\n"
      "Rule 1: X = F[+X]F[-X]+X\nRULE  12 : F -> FF\n";
  EXPECT_EQ(derived(pasted), derived("premise: X\nn=2, angle=20\n"
                                     "X = F[+X]F[-X]+X\nF -> FF\n"));
  EXPECT_EQ(derived(pasted), "FF[+F[+X]F[-X]+X]FF[-F[+X]F[-X]+X]+F[+X]F[-X]+X");
  const Grammar g = parse(pasted);
  ASSERT_EQ(g.productions.size(), 2U);
  EXPECT_DOUBLE_EQ(g.settings.angle_deg, 20.0);
}

TEST(Parser, ReadsAWordBeforeAStarAsAPredecessorWithACondition) {
  const Grammar g = parse("axiom: A\nA : * \u2192 B\n");
  ASSERT_EQ(g.productions.size(), 1U);
  EXPECT_EQ(g.alphabet.name(g.productions[0].predecessor.symbol), "A");
  EXPECT_FALSE(g.productions[0].condition.has_value());
}

TEST(Parser, RefusesAColonThatMayEndALabelOrStartACondition) {
  EXPECT_EQ(located_error("#define t 2\naxiom: A\nA : t > 1 \u2192 B\n"),
            "3:1: ambiguous ':': 'A' may be a label or a predecessor with the "
            "condition 't > 1'; write 'p1: t > 1 \u2192 \u2026' for a label, "
            "'p1: A : t > 1 \u2192 \u2026' for a condition");
  // A declared name may be a predecessor too; an undeclared word may not.
  EXPECT_EQ(
      parse_error("module leaf\naxiom: A\nleaf : 1 \u2192 B\n").substr(0, 31),
      "ambiguous ':': 'leaf' may be a ");
  EXPECT_EQ(derived("n=1\naxiom: 1\nleaf : 1 \u2192 B\n"), "B");
}

TEST(Parser, StripsBlockCommentsAnywhereAndLineComments) {
  const Grammar g = parse(
      "#define a 45 /* branching angle */\n"
      "// a comment line\n"
      "# another comment line\n"
      "n=/* inline */1\n"
      "\u03C9: F\n"
      "/* a comment\n"
      "   over two lines */\n"
      "F \u2192 F[+(a)F]\n");
  EXPECT_EQ(g.constants.at("a"), 45.0);
  EXPECT_EQ(to_string(derive(g), g.alphabet), "F[+(45)F]");
}

TEST(Parser, EndsALineAtAHashStandingAloneAsAWord) {
  EXPECT_EQ(derived("n=1\naxiom: F   # comment\nF -> FF\n"), "FF");
  EXPECT_EQ(derived("n=2 # steps\naxiom: F\t#\tcomment\nF -> F[+F] #\n"),
            "F[+F][+F[+F]]");
  // Touching a module, `#` is a module (cpfg's widen).
  EXPECT_EQ(derived("n=1\naxiom: A\nA -> F#F #F # widen\n"), "F#F#F");
  EXPECT_EQ(parse("#define a 45  # degrees\n\u03C9: F\n").constants.at("a"),
            45.0);
}

TEST(Parser, RefusesASettingNameWithoutItsColon) {
  EXPECT_EQ(located_error("n=1\naxiom X\nX -> FX\n"),
            "2:6: missing ':' after 'axiom': write 'axiom: X'");
  EXPECT_EQ(located_error("n 5\nF\n"),
            "1:2: missing ':' after 'n': write 'n: 5'");
  // Fractint writes the number of turns in a circle.
  EXPECT_EQ(located_error("Angle 6\nAxiom F\n"),
            "1:6: missing ':' after 'Angle': write 'Angle: 6' for 6 degrees, "
            "or 'angle factor: 6' for Fractint's 360/6 degrees");
  // Modules that happen to spell a setting are still modules.
  EXPECT_EQ(derived("n F\n", 0), "nF");
  EXPECT_EQ(derived("module seed\nseed F\n", 0), "seed F");
}

TEST(Parser, NeverReadsDoubleSlashInsideAProductionAsAComment) {
  // The Hilbert rules end with two rolls (seed 000).
  EXPECT_EQ(derived("A\nA \u2192 F+B//\nn=1"), "F+B//");
}

TEST(Parser, TokenisesDeclaredMultiCharacterNamesByLongestMatch) {
  const Grammar g = parse(
      "\u03C9: plant\nplant \u2192 internode[plant]seg\n"
      "seg \u2192 segFseg\ninternode \u2192 internode\nn=2\n");
  const ModuleString s = derive(g);
  EXPECT_EQ(to_string(s, g.alphabet),
            "internode [ internode [ plant ] seg ] seg F seg");
  EXPECT_EQ(s.size(), 11U);
  EXPECT_FALSE(g.alphabet.find("p").has_value());
  // Undeclared words are single-character modules.
  const Grammar plain = parse("\u03C9: leaf\n");
  EXPECT_EQ(derive(plain).size(), 4U);
}

TEST(Parser, DeclaresNamesWithModuleLines) {
  const Grammar g = parse("module leaf, bud(x)\n\u03C9: F leaf bud(2)\n");
  EXPECT_EQ(to_string(derive(g, {.derivation_length = 0}), g.alphabet),
            "F leaf bud(2)");
}

TEST(Parser, JoinsIndentedContinuationLines) {
  EXPECT_EQ(derived("\u03C9: A\nA \u2192 F[+F]\n   F[-F]\n\tF\nn=1"),
            "F[+F]F[-F]F");
}

TEST(Parser, SplitsProductionsSharedOnOneLine) {
  EXPECT_EQ(derived("\u03C9: A\nA = f[^B]>>A, B = f[-B]B\nn=2"),
            "f[^f[-B]B]>>f[^B]>>A");
}

TEST(Parser, ReadsStochasticProductionsInBothForms) {
  const Grammar abop =
      parse("\u03C9: F\nF -(0.33)\u2192 F[+F]F\nF -(.67)-> F\n");
  ASSERT_EQ(abop.productions.size(), 2U);
  EXPECT_DOUBLE_EQ(abop.productions[0].probability->constant_value(), 0.33);
  EXPECT_EQ(abop.productions[0].successor.size(), 6U);
  const Grammar cpfg =
      parse("\u03C9: F\nF --> F[+F]F : 0.33\nF --> F : 1-0.33\n");
  EXPECT_DOUBLE_EQ(cpfg.productions[1].probability->constant_value(), 0.67);
  EXPECT_EQ(cpfg.productions[0].successor.size(), 6U);
}

TEST(Parser, ReadsContextsIncludingBranchesOnTheRight) {
  const Grammar g = parse("\u03C9: S\nBC < S > G[H]M \u2192 Z\n");
  const Production& p = g.productions.at(0);
  EXPECT_EQ(p.left_context.size(), 2U);
  EXPECT_EQ(p.right_context.size(), 5U);
  EXPECT_TRUE(p.is_context_sensitive());
}

TEST(Parser, BindsContextParametersInSlotOrder) {
  EXPECT_EQ(derived("\u03C9: A(1)B(2)C(3)\nA(a) < B(b) > C(c) \u2192 "
                    "B(a*100+b*10+c)\nn=1"),
            "A(1)B(123)C(3)");
}

TEST(Parser, ReadsSectionsForDecompositionAndHomomorphism) {
  const Grammar g = parse(
      "\u03C9: A\nA \u2192 AB\ndecomposition:\nB \u2192 CD\nhomomorphism:\n"
      "maximum depth: 2\nC \u2192 F\nendlsystem\n");
  EXPECT_EQ(g.productions.size(), 1U);
  EXPECT_EQ(g.decompositions.size(), 1U);
  EXPECT_EQ(g.homomorphisms.size(), 1U);
  EXPECT_EQ(g.settings.maximum_depth, 2);
}

TEST(Parser, AppliesAliasesToTheTurtleOnly) {
  const Grammar g = parse(
      "aliases:\n  f = F   /* the blog draws with f */\n  v=& <=\\ >=/\n"
      "productions:\n\u03C9: fA\nA = f>A\n");
  EXPECT_EQ(g.commands[*g.alphabet.find("f")], TurtleCommand::Draw);
  EXPECT_EQ(g.commands[*g.alphabet.find("v")], TurtleCommand::PitchDown);
  EXPECT_EQ(g.commands[*g.alphabet.find("<")], TurtleCommand::RollLeft);
  EXPECT_EQ(g.commands[*g.alphabet.find(">")], TurtleCommand::RollRight);
  EXPECT_EQ(g.commands[*g.alphabet.find("A")], TurtleCommand::None);
  EXPECT_EQ(g.productions.size(), 1U);
}

TEST(Parser, AcceptsTheBlogsOwnSettingNames) {
  const Grammar g = parse(
      "Angle : 25\nIterations: 6\nBranch radius: 0.02\n"
      "Branch radius reduction: 0.0015\nBranch length (height): 0.15\n"
      "Initial value : fffffA\nProduction rules : A = f[++Al][--Al]>>>A\n");
  EXPECT_EQ(g.settings.angle_deg, 25.0);
  EXPECT_EQ(g.settings.derivation_length, 6);
  EXPECT_DOUBLE_EQ(g.settings.initial_width, 0.04);
  EXPECT_DOUBLE_EQ(g.settings.width_decrement_per_generation, 0.003);
  EXPECT_EQ(g.settings.step, 0.15);
  EXPECT_EQ(g.productions.size(), 1U);
}

TEST(Parser, WarnsAboutCommandLineDefinesTheFileNeverReads) {
  const Grammar g = parse("#define a 1\n\u03C9: F(b)",
                          ParseOptions{.defines = {"a=2", "b=3", "typo=4"}});
  ASSERT_EQ(g.warnings.size(), 1U);
  EXPECT_EQ(g.warnings[0],
            "--define typo: the file neither defines nor uses 'typo'");
}

TEST(Parser, CommandLineDefinesOverrideTheFile) {
  const Grammar g = parse("#define a 45\n#define b a*2\n\u03C9: +(b)",
                          ParseOptions{.defines = {"a=10", "extra=3"}});
  EXPECT_EQ(g.constants.at("a"), 10.0);
  EXPECT_EQ(g.constants.at("b"), 20.0);
  EXPECT_EQ(g.constants.at("extra"), 3.0);
}

TEST(Parser, PassesClientSettingsThrough) {
  const Grammar g = parse("wall: 0.8mm\nheight = 120 mm\n\u03C9: F",
                          ParseOptions{.extra_settings = {"wall", "height"}});
  ASSERT_EQ(g.extra_settings.size(), 2U);
  EXPECT_EQ(g.extra_settings[0].key, "wall");
  EXPECT_EQ(g.extra_settings[0].value, "0.8mm");
  EXPECT_EQ(g.extra_settings[1].value, "120 mm");
}

TEST(Parser, ReadsEmptySuccessors) {
  EXPECT_EQ(derived("\u03C9: AB\nA \u2192 *\nB \u2192 \u03B5\nn=1"), "");
  EXPECT_EQ(derived("\u03C9: AB\nA \u2192\nn=1"), "B");
}

TEST(Parser, ReadsIgnoreAndConsiderLists) {
  EXPECT_EQ(parse("#ignore: + -\n\u03C9: F").settings.ignore.size(), 2U);
  EXPECT_EQ(parse("consider: ABC\n\u03C9: F").settings.consider.size(), 3U);
}

TEST(Parser, IgnoresAByteOrderMarkAndReadsOldMacLineEnds) {
  EXPECT_EQ(parse("\xEF\xBB\xBFn=2, \u03B4=90\nF").settings.derivation_length,
            2);
  EXPECT_EQ(derived("\xEF\xBB\xBF\u03C9: A\rA \u2192 FA\rn=2"), "FFA");
}

TEST(Parser, ReadsTheTypesetMinusSignAsTurnRight) {
  const Grammar g = parse("\u03C9: F\u2212F");
  EXPECT_EQ(g.commands[*g.alphabet.find("\u2212")], TurtleCommand::TurnRight);
}

TEST(Parser, AcceptsDegreeSignsFromPdfs) {
  for (const char* sign : {"\u00B0", "\u00BA", "\u02DA", "\u25E6"}) {
    EXPECT_EQ(
        parse(std::string("angle: 22.5") + sign + "\nF").settings.angle_deg,
        22.5);
  }
}

TEST(Parser, ReadsAOneLetterNameBeforeEqualsAndModulesAsAProduction) {
  // Fractint's `N=O` beside the setting n=2, either way round.
  EXPECT_EQ(derived("n=2\nN=O\naxiom: N\n"), "O");
  EXPECT_EQ(derived("axiom: N\nN=OF\nn=2\n"), "OF");
  EXPECT_EQ(derived("n=2\naxiom: D\nD=1\n"), "1");
  // Before a number or arithmetic over constants, it is a setting.
  EXPECT_EQ(
      parse("#define k 3\nN = k*2 // steps\nF\n").settings.derivation_length,
      6);
}

TEST(Parser, RefusesAOneLetterSettingOfALetterThatIsAModule) {
  EXPECT_EQ(located_error("N=2\naxiom: NF\n"),
            "1:1: ambiguous 'N=2': it may set 'N' or rewrite the module 'N' "
            "that this file uses; write 'N: 2' for the setting, 'N \u2192 2' "
            "for a production");
  EXPECT_EQ(parse("n: 2\naxiom: nF\n").settings.derivation_length, 2);
}

TEST(Parser, AllowsTrailingCommentsOnNumericSettings) {
  const Grammar g = parse("n=2 // two steps\n\u03C9: F//F\n");
  EXPECT_EQ(g.settings.derivation_length, 2);
  EXPECT_EQ(g.axiom.size(), 4U);  // the axiom's // are rolls
}

TEST(Parser, DeclaresParameterCountsInModuleLines) {
  EXPECT_EQ(
      derived("module bud(x)\n\u03C9: bud(1)\nbud(x) \u2192 bud(x+1)\nn=2"),
      "bud(3)");
  EXPECT_EQ(located_error("module bud(x,y)\n\u03C9: bud(1)"),
            "2:4: wrong parameter count: 'bud' takes 2 parameters (as on line "
            "1), here 1");
}

TEST(Parser, ParsesAHundredThousandProductionsInLinearWork) {
  // They did not finish in 120 s when each line searched the rest of the
  // file and each name was matched against every other (bench/core_bench
  // times it).
  std::string text = "\u03C9: A0\n";
  for (int i = 0; i < 100'000; ++i) {
    // (Appending piecewise avoids a GCC 12 -Wrestrict false alarm.)
    text.append("A").append(std::to_string(i)).append(" \u2192 F A");
    text.append(std::to_string(i + 1)).append("\n");
  }
  const Grammar g = parse(text);
  ASSERT_EQ(g.productions.size(), 100'000U);
  EXPECT_EQ(g.alphabet.name(g.productions.back().predecessor.symbol), "A99999");
  EXPECT_LE(g.alphabet.bytes_examined(), 2 * text.size());
  EXPECT_EQ(derived(text, 3), "FFF A3");
}

TEST(Parser, ReadsALoneStarContextAsNoContextAsCpfgDoes) {
  // cpfg: `*` as the whole context is no context, so A grows every step.
  EXPECT_EQ(derived("n=3\naxiom: A\n* < A > * -> AF\n"), "AFFF");
  EXPECT_EQ(derived("\u03C9: +1\n* < + \u2192 -\nn=1"), "-1");
  EXPECT_FALSE(parse("\u03C9: A\n* < A > * -> AF\n")
                   .productions[0]
                   .is_context_sensitive());
  // ABOP fig. 1.31's p9 `* < + > * → -` then turns every `+`.
  EXPECT_EQ(derived("ignore: F\n\u03C9: +1F+F1-1\n* < + > * \u2192 -\n"
                    "* < - > * \u2192 +\nn=1"),
            "-1F-F1+1");
}

TEST(Parser, ReadsAStarAmongContextModulesAsAnyOneModule) {
  // The wildcard needs a module there: none before the first A.
  EXPECT_EQ(derived("\u03C9: AAB\n* A < B \u2192 C\nn=1"), "AAC");
  EXPECT_EQ(derived("\u03C9: AB\n* A < B \u2192 C\nn=1"), "AB");
  // It matches no bracket: in A[B]C, A's right context skips the branch.
  EXPECT_EQ(derived("\u03C9: A[B]C\nA > * C \u2192 X\nn=1"), "A[B]C");
  EXPECT_EQ(derived("\u03C9: ABC\nA > * C \u2192 X\nn=1"), "XBC");
}

TEST(Parser, ReportsEachMistakeWithItsOwnMessage) {
  EXPECT_EQ(located_error("angel: 20\nF"), "1:1: unknown setting 'angel'");
  EXPECT_EQ(located_error("angel = 20\nF"), "1:1: unknown setting 'angel'");
  EXPECT_EQ(located_error("target: Lsystem\npanel name: L-system\n"),
            "1:1: unknown setting 'target': this is a vlab control panel, "
            "not an L-system; give the object's L-system file");
  EXPECT_EQ(located_error("\u03C9: F\nF F[+F]F"),
            "2:1: missing arrow: a production needs '\u2192' or '->' "
            "between predecessor and successor");
  EXPECT_EQ(located_error("\u03C9: F\nF \u2192 F]F"),
            "2:6: unbalanced ']': no '[' before it");
  EXPECT_EQ(located_error("\u03C9: F\nF \u2192 F[F"),
            "2:6: unclosed '[': no ']' after it");
  EXPECT_EQ(located_error("\u03C9: A(1)\nA(x) \u2192 A(x, 1)"),
            "2:8: wrong parameter count: 'A' takes 1 parameter (as on line "
            "1), here 2");
  EXPECT_EQ(located_error("\u03C9: +(1, 2)"),
            "1:4: wrong parameter count: '+' takes at most 1 parameter, "
            "here 2");
  EXPECT_EQ(located_error("\u03C9: A(1)\nA(x) \u2192 A(y)"),
            "2:10: undefined name 'y'");
  EXPECT_EQ(located_error("#define a 1/0\n\u03C9: F"),
            "1:12: division by zero");
  EXPECT_EQ(located_error("n = 1.2.3\n\u03C9: F"), "1:5: bad number '1.2.3'");
  EXPECT_EQ(located_error("#define a 1\n#define a 2\n\u03C9: F"),
            "2:9: duplicate definition of 'a' (first defined on line 1)");
  EXPECT_EQ(located_error("\u03C9: A(1,1)\nA(x, x) \u2192 F"),
            "2:6: duplicate definition of parameter 'x'");
  EXPECT_EQ(located_error("n=1\nn=2\n\u03C9: F"),
            "2:1: duplicate setting 'n' (first set on line 1)");
  EXPECT_EQ(located_error("\u03C9: F\n/* open"),
            "2:1: unterminated comment '/*'");
  EXPECT_EQ(located_error("\u03C9: F\nA(1) \u2192 F"),
            "2:3: a parameter of a predecessor or context must be a name, "
            "not '1'");
  EXPECT_EQ(located_error("\u03C9: F\nA B \u2192 F"),
            "2:1: the predecessor must be a single module");
  EXPECT_EQ(located_error("\u03C9: F\n[ \u2192 F"),
            "2:1: brackets cannot be rewritten");
  EXPECT_EQ(located_error("\u03C9: F\nA[B] < C \u2192 F"),
            "2:2: a left context cannot contain brackets");
  EXPECT_EQ(located_error("\u03C9: F\nF \u2192 F(1"), "2:6: unclosed '('");
  EXPECT_EQ(located_error("\u03C9: F\nF \u2192 (1)"),
            "2:5: unexpected '(': parameters follow a module name, as in F(1)");
  EXPECT_EQ(located_error("#include \"x\"\n\u03C9: F"),
            "1:1: #include is not supported");
  EXPECT_EQ(testing::located_error_of([] {
              (void)parse_grammar_text(
                  "#include <math.h>\n#include <lpfgall.h>\n",
                  {.dialect = Dialect::Ls}, "a.ls");
            }),
            "1:1: this is an lpfg file, whose rules are C++: read it with "
            "--dialect lpfg");
  EXPECT_EQ(located_error("#pragma once\n\u03C9: F"),
            "1:1: unknown directive '#pragma'");
  EXPECT_EQ(located_error("aliases: f=Q\n\u03C9: F"),
            "1:12: unknown turtle symbol 'Q'");
  EXPECT_EQ(located_error("aliases: f=F f=G\n\u03C9: F"),
            "1:14: duplicate alias for 'f'");
  EXPECT_EQ(located_error("\u03C9: F\nF -(-1)\u2192 G"),
            "2:5: a probability cannot be negative");
  EXPECT_EQ(located_error("roll: left\n\u03C9: F"),
            "1:7: expected 'lpfg' or 'cpfg'");
  EXPECT_EQ(located_error("n: -1\n\u03C9: F"),
            "1:4: expected a whole number from 0 to 10000");
  EXPECT_EQ(located_error("tropism: 0, 1\n\u03C9: F"),
            "1:10: expected three numbers x, y, z");
  EXPECT_EQ(located_error("width increment: 1\nwidth factor: 0.5\n\u03C9: F"),
            "2:1: give either 'width increment' or 'width factor', not both");
  EXPECT_EQ(located_error("\u03C9: F\ndecomposition:\nA < B \u2192 C"),
            "3:5: a decomposition rule cannot have a context");
  EXPECT_EQ(located_error("\u03C9: F\nhomomorphism:\nA -(0.5)\u2192 C"),
            "3:5: a homomorphism rule cannot be stochastic");
  EXPECT_EQ(located_error("\u03C9: F\n\u03C9: G"),
            "2:1: duplicate setting '\u03C9' (first set on line 1)");
  EXPECT_EQ(located_error("F\nF \u2192 G\naxiom: G"),
            "3:1: duplicate axiom (the first is on line 1)");
  EXPECT_EQ(located_error("anlge=90, n=2\nF"), "1:1: unknown setting 'anlge'");
  EXPECT_EQ(located_error("n=2, anlge=90\nF"), "1:6: unknown setting 'anlge'");
  EXPECT_EQ(located_error("setp = 0.5*2\nF"), "1:1: unknown setting 'setp'");
  EXPECT_EQ(located_error("angle: 20\nangle factor: 16\nF"),
            "2:1: give either 'angle' or 'angle factor', not both");
  EXPECT_EQ(located_error("radius: 1\nwidth: 1\nF"),
            "2:1: give either 'width' or 'radius', not both");
  EXPECT_EQ(located_error(std::string("\u03C9: B(") + std::string(300, '(') +
                          "1" + std::string(300, ')') + ")"),
            "1:206: expression is nested too deeply");
  EXPECT_EQ(parse_error("F \u2192 G"),
            "no axiom: give one as 'axiom: F', '\u03C9: F' or a line of "
            "modules before the productions");
}

TEST(Parser, ReadsCpfgsWidenAsTheOppositeOfItsNarrow) {
  const Skeleton s =
      interpret(parse("width: 1\nwidth increment: 0.25\nF#F!F#(3)F\nn=0"));
  ASSERT_EQ(s.segments.size(), 4U);
  EXPECT_DOUBLE_EQ(s.segments[0].start_diameter, 1.0);
  EXPECT_DOUBLE_EQ(s.segments[1].start_diameter, 1.25);
  EXPECT_DOUBLE_EQ(s.segments[2].start_diameter, 1.0);
  EXPECT_DOUBLE_EQ(s.segments[3].start_diameter, 3.0);
}

TEST(Parser, KeepsCpfgsAtModulesWholeAndRefusesThoseItCannotBuild) {
  const Grammar g = parse("@GsF@Gc(4)F@Ge\nn=0");
  EXPECT_EQ(to_string(derive(g), g.alphabet), "@Gs F @Gc(4) F @Ge");
  EXPECT_EQ(interpret(g).segments.size(), 2U);
  EXPECT_EQ(located_error("F[@o(2)]\nn=0"),
            "1:3: '@o' (a disc) is not supported by lsolid");
  // cpfg's sphere, as the cpfg notation reads it.
  const Skeleton ball = interpret(parse("width: 0.5\nF@OF@O(3)\nn=0"));
  ASSERT_EQ(ball.spheres.size(), 2U);
  EXPECT_DOUBLE_EQ(ball.spheres[0].diameter, 0.5);
  EXPECT_DOUBLE_EQ(ball.spheres[1].diameter, 3.0);
  EXPECT_EQ(located_error("F~l(0.5)\nn=0"),
            "1:2: '~' (a predefined surface in cpfg, a random turn in "
            "Houdini) is not supported by lsolid");
}

TEST(Parser, ContinuesALongAxiomOnIndentedLines) {
  EXPECT_EQ(derived("axiom: F[+F]\n    F[-F]\nF -> FF\nn=1"), "FF[+FF]FF[-FF]");
  EXPECT_EQ(derived("F[+F]\n  F[-F]\n  F\nn=0"), "F[+F]F[-F]F");
}

TEST(Parser, EndsADefineAtACommentAsTheCPreprocessorDoes) {
  EXPECT_EQ(derived("#define R 0.5 // ratio\nn=1\nF\nF -> F(R)"), "F(0.5)");
}

TEST(Parser, RefusesASystemNameForANotationOfOneSystem) {
  EXPECT_EQ(parse_error_of_system("F\nF -> FF\n", "Koch"),
            "--system picks one system of a Fractint file; this file is "
            "read as ls (--dialect)");
}

TEST(Parser, ReadsJonLeechsLsysStartAxiomAndItsMaxgenAndDeltaMacros) {
  // ABOP fig. 1.24a as typed up for lsys: 5 generations of F -> 5 F.
  const Grammar g = parse(
      "/* figure 1.24a */\n#define maxgen 5\n#define delta 25.7\n\n"
      "START : F\np1 : F -> F[+F]F[-F]F\n");
  EXPECT_EQ(g.settings.derivation_length, 5);
  EXPECT_DOUBLE_EQ(g.settings.angle_deg, 25.7);
  EXPECT_EQ(interpret(g).segments.size(), 3125U);
  // The file's own settings win; without START the macros are constants.
  const Grammar own = parse("#define maxgen 5\nn: 2\nSTART : F\nF -> FF\n");
  EXPECT_EQ(own.settings.derivation_length, 2);
  const Grammar plain = parse("#define maxgen 5\naxiom: F\nF -> FF\n");
  EXPECT_EQ(plain.settings.derivation_length, 1);
  EXPECT_EQ(plain.constants.at("maxgen"), 5.0);
}

}  // namespace
}  // namespace lsys
