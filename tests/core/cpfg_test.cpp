// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The cpfg front end (docs/dialects/cpfg.md): the C preprocessor, the view
// file beside the `.l`, cpfg's symbols and what it refuses.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <numbers>
#include <string>

#include "lsys/interpretation.hpp"
#include "support/core_helpers.hpp"

namespace lsys {
namespace {

using testing::located_error_of;

constexpr testing::Notation kCpfg{Dialect::Cpfg, "plant.l"};

constexpr std::string_view kHead = "Lsystem: 1\nderivation length: 1\n";

// A folder of its own for files that the front end finds beside each other.
class CpfgFiles : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ =
        std::filesystem::temp_directory_path() /
        ("lsolid_cpfg_" +
         std::string(
             ::testing::UnitTest::GetInstance()->current_test_info()->name()));
    std::filesystem::remove_all(dir_);
    std::filesystem::create_directories(dir_);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::filesystem::path write(const std::string& name,
                              std::string_view text) const {
    const auto path = dir_ / name;
    std::ofstream(path) << text;
    return path;
  }

  Grammar read(const std::string& name, ParseOptions options = {}) const {
    return parse_grammar(load_source(dir_ / name), options);
  }

  std::filesystem::path dir_;
};

TEST(Cpfg, IsDetectedByItsLsystemLineUnlessTheFileIsNamedLs) {
  const std::string text =
      "#define N 3\nLsystem: 1\nderivation length: N\nAxiom: F\nendlsystem\n";
  EXPECT_EQ(detect_dialect(text, "plant.l"), Dialect::Cpfg);
  EXPECT_EQ(detect_dialect("lsystem:2\naxiom: F\n", "leaf.l"), Dialect::Cpfg);
  EXPECT_EQ(detect_dialect(text, "plant.ls"), Dialect::Ls);
  EXPECT_EQ(detect_dialect("axiom: F\nF -> FF\n", "plant.l"), Dialect::Ls);
  EXPECT_EQ(dialect_named("cpfg"), Dialect::Cpfg);
}

TEST_F(CpfgFiles, TakesTheAngleAndThePixelWidthsFromTheViewFileOfTheSameName) {
  write("plant.l", std::string(kHead) + "Axiom: F+F\nendlsystem\n");
  write("plant.v",
        "/* a view */\nangle factor: 4\ninitial line width: 3 pixels\n"
        "line width increment: 0.5\nviewpoint: 0,0,1\n");
  write("other.v", "angle increment: 30\n");
  const Grammar g = read("plant.l");
  EXPECT_DOUBLE_EQ(g.settings.angle_deg, 90.0);
  EXPECT_DOUBLE_EQ(g.settings.initial_width, 3.0);
  EXPECT_DOUBLE_EQ(g.settings.width_scale, 0.1);  // a pixel is 0.1 step
  EXPECT_DOUBLE_EQ(*g.settings.width_increment, 0.5);
  EXPECT_EQ(g.settings.roll, RollConvention::Cpfg);
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 2U);
  EXPECT_NEAR(glm::dot(s.segments[0].p1 - s.segments[0].p0,
                       s.segments[1].p1 - s.segments[1].p0),
              0.0, 1e-12);
}

TEST_F(CpfgFiles, ReadsAWidthWithoutAUnitInModelUnitsAsCpfgDoes) {
  write("tree.l", std::string(kHead) + "Axiom: F\nendlsystem\n");
  write("view.v",
        "initial line width: 3\ntropism direction: 0,-1,0\n"
        "initial elasticity: 0.2\nelasticity increment: 0.05\n");
  const Grammar g = read("tree.l");  // the folder's only .v
  EXPECT_DOUBLE_EQ(g.settings.initial_width, 3.0);
  EXPECT_DOUBLE_EQ(g.settings.width_scale, 1.0);
  // cpfg's Y is up, lsolid's Z: gravity (0,-1,0) is (0,0,-1).
  EXPECT_EQ(g.settings.tropism, glm::dvec3(0.0, 0.0, -1.0));
  EXPECT_DOUBLE_EQ(g.settings.elasticity, 0.2);
  EXPECT_DOUBLE_EQ(g.settings.elasticity_increment, 0.05);
}

TEST_F(CpfgFiles, ReadsTheViewFileItIsGivenAndWarnsWithoutOne) {
  write("a.l", std::string(kHead) + "Axiom: F\nendlsystem\n");
  write("a.v", "angle increment: 10\n");
  write("b.v", "angle increment: 20\n");
  EXPECT_DOUBLE_EQ(read("a.l").settings.angle_deg, 10.0);
  EXPECT_DOUBLE_EQ(
      read("a.l", {.view_file = (dir_ / "b.v").string()}).settings.angle_deg,
      20.0);
  std::filesystem::remove(dir_ / "a.v");
  EXPECT_DOUBLE_EQ(read("a.l").settings.angle_deg, 20.0);  // the only one
  write("c.v", "angle increment: 30\n");
  const Grammar g = read("a.l");  // two others: neither is the one
  EXPECT_DOUBLE_EQ(g.settings.angle_deg, 45.0);
  ASSERT_FALSE(g.warnings.empty());
  EXPECT_NE(g.warnings.front().find("no view file (.v) found"),
            std::string::npos);
}

TEST_F(CpfgFiles, ExpandsMacrosInTheViewFileAndPlacesItsErrorsAtTheValue) {
  write("p.l", std::string(kHead) + "Axiom: F\nendlsystem\n");
  write("p.v", "#define SIDES 6\nangle factor: SIDES\nangle factor: many\n");
  const std::string error = located_error_of([&] { (void)read("p.l"); });
  EXPECT_EQ(error, "3:15: expected a number");
  write("p.v", "#define SIDES 6\nangle factor: SIDES // sixths\n");
  EXPECT_DOUBLE_EQ(read("p.l").settings.angle_deg, 60.0);
}

TEST(Cpfg, ExpandsMacrosWithParametersAndModuleStringsAsTheCPreprocessor) {
  const Grammar g = kCpfg.parse(
      "#define STEPS 2 /* kept as a constant */\n"
      "#define BRANCH(a) [+(a*2)F]\n"
      "#define TWIG BRANCH(10)F\n"
      "Lsystem: 1\n"
      "derivation length: STEPS\n"
      "Axiom: A\n"
      "A --> TWIG A // a comment\n"
      "endlsystem\n");
  EXPECT_EQ(g.settings.derivation_length, 2);
  EXPECT_EQ(g.constants.at("STEPS"), 2.0);
  EXPECT_EQ(to_string(derive(g), g.alphabet), "[+(20)F]F[+(20)F]FA");
}

TEST(Cpfg, KeepsTheTextualMeaningOfAMacroThatIsNotAConstant) {
  // cpp gives 2*1+1 = 3, not 2*(1+1) = 4.
  EXPECT_EQ(kCpfg.derived("#define SUM 1+1\nLsystem: 1\nAxiom: A(2*SUM)\n"
                          "endlsystem\n"),
            "A(3)");
}

TEST(Cpfg, ChoosesTheBranchOfAnIfdef) {
  const std::string text =
      "#define LONG\n"
      "Lsystem: 1\nderivation length: 1\nAxiom: A\n"
      "#ifdef LONG\nA --> FF\n#else\nA --> F\n#endif\nendlsystem\n";
  EXPECT_EQ(kCpfg.derived(text), "FF");
  EXPECT_EQ(kCpfg.derived(text.substr(text.find('\n') + 1)), "F");
}

TEST(Cpfg, PlacesErrorsAfterAnExpandedMacroWhereTheyStandInTheFile) {
  EXPECT_EQ(kCpfg.error("#define LONGNAME F\nLsystem: 1\n"
                        "Axiom: LONGNAME F(\nendlsystem\n"),
            "3:18: unclosed '('");
  EXPECT_EQ(kCpfg.error("#define M(a,b) F(a)\nLsystem: 1\nAxiom: M(1)\n"),
            "3:8: macro 'M' takes 2 arguments, here 1");
  // An unclosed call inside a macro's body is placed at the use.
  EXPECT_EQ(kCpfg.error("#define A(x) x\n#define B A(1\nLsystem: 1\n"
                        "Axiom: F B\n"),
            "4:10: unclosed '(' in the call of macro 'A'");
  EXPECT_EQ(kCpfg.error("Lsystem: 1\n#if 1\nAxiom: F\n"),
            "2:1: '#if' without '#endif'");
  EXPECT_EQ(kCpfg.error("#include \"leaf.h\"\nLsystem: 1\nAxiom: F\n"),
            "1:1: #include \"leaf.h\": no such file beside this one (leaf.h)");
  EXPECT_EQ(kCpfg.error("#include <stdio.h>\nLsystem: 1\nAxiom: F\n"),
            "1:1: #include <stdio.h>: a header lsolid does not have");
}

TEST_F(CpfgFiles, ReadsAnIncludedFileBesideItWithItsMacrosAndConstants) {
  // As Adel's models keep their parameters in a header of the object.
  write("params.h",
        "/* parameters */\n#define N 3\n#define GROW(x) F(x)\n"
        "#ifndef LEN\n#define LEN 2\n#endif\n");
  write("plant.l",
        "#include \"params.h\"\nLsystem: 1\nderivation length: N\n"
        "Axiom: A(1)\nA(x) --> GROW(LEN*x)A(x+1)\nendlsystem\n");
  const Grammar g = read("plant.l");
  EXPECT_EQ(g.settings.derivation_length, 3);
  EXPECT_EQ(to_string(derive(g), g.alphabet), "F(2)F(4)F(6)A(4)");
  write("broken.h", "#define N 3\n#if N\n");
  write("broken.l", "#include \"broken.h\"\nLsystem: 1\nAxiom: F\n");
  EXPECT_EQ(located_error_of([&] { (void)read("broken.l"); }),
            "2:1: '#if' without '#endif'");
  // cpfg includes other `.l` files for sub-L-systems.
  write("sub.l", "Lsystem: 2\nAxiom: G\nendlsystem\n");
  write("main.l", "Lsystem: 1\nAxiom: F\nendlsystem\n#include \"sub.l\"\n");
  EXPECT_EQ(located_error_of([&] { (void)read("main.l"); }),
            "4:1: a second L-system (a sub-L-system; the first is on line 1) "
            "is not supported");
  write("self.l", "#include \"self.l\"\nLsystem: 1\nAxiom: F\n");
  EXPECT_EQ(located_error_of([&] { (void)read("self.l"); }),
            "1:1: #include nested too deeply (a file that includes itself?)");
}

// What an error says, wherever it is placed: the name as written, never
// the text of a file outside the model's folder.
template <typename Work>
std::string message_of(const Work& work) {
  try {
    work();
  } catch (const ParseError& e) {
    return e.diagnostic().message + " | " + e.diagnostic().source_line;
  }
  return "no error";
}

constexpr std::string_view kOnlyOwnFolder =
    "a model reads only files in its own folder (--include-dir allows "
    "another)";

TEST_F(CpfgFiles, IncludesOnlyFilesInsideTheModelsFolder) {
  std::filesystem::create_directories(dir_ / "model" / "sub");
  std::filesystem::create_directories(dir_ / "outside");
  write("outside/secret.h", "#define SECRET_TEXT 1\n");
  write("model/params.h", "#define N 2\n");
  const auto plant = [&](const std::string& header) {
    write("model/plant.l", "#include \"" + header +
                               "\"\nLsystem: 1\nderivation length: N\n"
                               "Axiom: F\nF --> FF\nendlsystem\n");
    return message_of([&] { (void)read("model/plant.l"); });
  };
  const std::string absolute = (dir_ / "outside" / "secret.h").string();
  EXPECT_EQ(plant(absolute), "#include \"" + absolute +
                                 "\": an absolute name; " +
                                 std::string(kOnlyOwnFolder) +
                                 " | #include \"" + absolute + "\"");
  EXPECT_EQ(plant("../outside/secret.h"),
            "#include \"../outside/secret.h\": a name that leaves the folder "
            "('..'); " +
                std::string(kOnlyOwnFolder) +
                " | #include \"../outside/secret.h\"");
  // `..` is refused even where it would come back in.
  EXPECT_NE(plant("sub/../params.h").find("leaves the folder"),
            std::string::npos);
  // A link that leads out, to a file or through a folder.
  std::filesystem::create_symlink(dir_ / "outside" / "secret.h",
                                  dir_ / "model" / "link.h");
  std::filesystem::create_symlink(dir_ / "outside", dir_ / "model" / "out");
  for (const std::string header : {"link.h", "out/secret.h"}) {
    EXPECT_EQ(plant(header), "#include \"" + header +
                                 "\": a symbolic link leads it out of the "
                                 "model's folder; " +
                                 std::string(kOnlyOwnFolder) +
                                 " | #include \"" + header + "\"");
  }
  EXPECT_EQ(plant("sub"),
            "#include \"sub\": it is a directory, not a "
            "regular file | #include \"sub\"");
  // Links and folders inside the model's folder are read.
  std::filesystem::create_symlink("params.h", dir_ / "model" / "alias.h");
  write("model/sub/outer.h", "#include \"inner.h\"\n");
  write("model/sub/inner.h", "#define N 3\n");
  for (const std::string header : {"params.h", "alias.h", "sub/outer.h"}) {
    EXPECT_EQ(plant(header), "no error") << header;
  }
  EXPECT_EQ(read("model/plant.l").settings.derivation_length, 3);
  // --include-dir allows another folder, whose names resolve there.
  write("model/plant.l",
        "#include \"secret.h\"\nLsystem: 1\nAxiom: F\nendlsystem\n");
  EXPECT_EQ(message_of([&] { (void)read("model/plant.l"); }),
            "#include \"secret.h\": no such file beside this one (" +
                (dir_ / "model" / "secret.h").string() +
                ") | #include \"secret.h\"");
  EXPECT_EQ(message_of([&] {
              (void)read("model/plant.l",
                         {.include_dirs = {(dir_ / "outside").string()}});
            }),
            "no error");
}

TEST_F(CpfgFiles, ReadsOnlyTheViewFilesCompanionsInsideTheModelsFolder) {
  std::filesystem::create_directories(dir_ / "model");
  std::filesystem::create_directories(dir_ / "outside");
  write("outside/secret.func", "SECRET TEXT\n");
  write("model/leaf.l", "Lsystem: 1\nAxiom: F\nendlsystem\n");
  const std::string secret = (dir_ / "outside" / "secret.func").string();
  const auto view = [&](const std::string& text) {
    write("model/leaf.v", text);
    const std::string message = message_of([&] { (void)read("model/leaf.l"); });
    EXPECT_EQ(message.find("SECRET"), std::string::npos) << message;
    return message;
  };
  for (const std::string label :
       {"function:", "function set:", "surface: l", "contour: 1"}) {
    const std::string what = label.substr(0, label.find(':') + 1);
    EXPECT_EQ(view(label + " " + secret + "\n"),
              what + " \"" + secret + "\": an absolute name; " +
                  std::string(kOnlyOwnFolder) + " | " + label + " " + secret);
    EXPECT_EQ(view(label + " ../outside/secret.func\n"),
              what +
                  " \"../outside/secret.func\": a name that leaves the "
                  "folder ('..'); " +
                  std::string(kOnlyOwnFolder) + " | " + label +
                  " ../outside/secret.func");
  }
  EXPECT_EQ(view("#include \"" + secret + "\"\n"),
            "#include \"" + secret + "\": an absolute name; " +
                std::string(kOnlyOwnFolder) + " | #include \"" + secret + "\"");
  // A FIFO named by the view is refused before it is opened (opening it
  // would wait for a writer for ever).
  ASSERT_EQ(::mkfifo((dir_ / "model" / "f.func").c_str(), 0644), 0);
  EXPECT_EQ(view("function: f.func\n"),
            "function: \"f.func\": it is a FIFO (named pipe), not a regular "
            "file | function: f.func");
  // The view file itself, found beside the model, may not lead out.
  std::filesystem::remove(dir_ / "model" / "leaf.v");
  std::filesystem::create_symlink(secret, dir_ / "model" / "leaf.v");
  EXPECT_EQ(message_of([&] { (void)read("model/leaf.l"); }),
            "the view file: a symbolic link leads it out of the model's "
            "folder; " +
                std::string(kOnlyOwnFolder) + " | ");
  // One the user names is read from where it is, with its companions.
  write("outside/mine.v", "angle increment: 30\n");
  EXPECT_EQ(read("model/leaf.l",
                 {.view_file = (dir_ / "outside" / "mine.v").string()})
                .settings.angle_deg,
            30.0);
}

TEST_F(CpfgFiles, ReadsAFunctionFileNamedManyTimesOnce) {
  // A view of 400 lines naming one function file: 400 functions, the file
  // read and sampled once.
  write("leaf.l", "Lsystem: 1\nAxiom: A(func(400, 0.25))\nendlsystem\n");
  std::string view;
  for (int i = 0; i < 400; ++i) view += "function: line.func 100\n";
  write("leaf.v", view);
  write("line.func",
        "fver 1 1\nname: line\nsamples: 0\nflip: off\npoints: 4\n"
        "0 0 1\n0.333333 0.333333 1\n0.666667 0.666667 1\n1 1 1\n");
  EXPECT_NEAR(derive(read("leaf.l")).parameters(0)[0], 0.25, 1e-4);
}

TEST_F(CpfgFiles, BoundsTheTextThatIncludedFilesComeTo) {
  // Fifteen headers that each include the next six times.
  for (int k = 1; k <= 15; ++k) {
    std::string text = "#define LEVEL";
    text += std::to_string(k);
    text += " 1\n";
    for (int j = 0; k < 15 && j < 6; ++j) {
      text += "#include \"h";
      text += std::to_string(k + 1);
      text += ".h\"\n";
    }
    std::string name = "h";
    name += std::to_string(k);
    name += ".h";
    write(name, text);
  }
  write("plant.l", "#include \"h1.h\"\nLsystem: 1\nAxiom: F\nendlsystem\n");
  // Placed at the directive that passes the bound, in its header.
  EXPECT_EQ(message_of([&] { (void)read("plant.l"); }),
            "more than 1000 #include directives read in all (files that "
            "include each other many times?) | #include \"h15.h\"");
}

// `A0` is F and each of 40 more macros uses the one before twice, through a
// macro E that the text defines first: `#define A1 E(A0)E(A0)`.
std::string doubling_macros() {
  std::string text = "#define A0 F\n";
  for (int k = 1; k <= 40; ++k) {
    const std::string before = std::to_string(k - 1);
    text += "#define A";
    text += std::to_string(k);
    text += " E(A" + before + ")E(A" + before + ")\n";
  }
  return text;
}

TEST(Cpfg, ExpandsAMacrosArgumentOnlyWhereItsBodyUsesIt) {
  // Each line uses the one before twice, through a macro that drops its
  // argument: expanding arguments first would take 2^40 steps.
  const std::string text = "#define E(x)\n" + doubling_macros();
  EXPECT_EQ(kCpfg.derived(text + std::string(kHead) + "Axiom: G A40 G\n"),
            "GG");
  // An argument used twice is expanded once, to the same text.
  EXPECT_EQ(kCpfg.derived("#define TWICE(x) x x\n#define B F(1)\n" +
                          std::string(kHead) + "Axiom: TWICE(B)\n"),
            "F(1)F(1)");
}

TEST(Cpfg, RefusesMacrosThatExpandToTooMuchAtTheirUse) {
  // Nothing comes out, but the work doubles with each line.
  std::string text = "#define G(x)\n#define E(x) G(x)\n" + doubling_macros();
  EXPECT_EQ(kCpfg.error(text + std::string(kHead) + "Axiom: F A40\n"),
            "46:10: the macros take too much work to expand (more than "
            "67108864 bytes scanned; macros that use each other many "
            "times?)");
  // A macro of half a megabyte used forty times passes the 16 MiB a file
  // may come to, on the line where it does.
  text = "#define B0 FFFFFFFFF\n";
  for (int k = 1; k <= 16; ++k) {
    text += "#define B" + std::to_string(k) + " B" + std::to_string(k - 1) +
            " B" + std::to_string(k - 1) + "\n";
  }
  text += std::string(kHead) + "Axiom: F\n";
  for (int k = 0; k < 40; ++k) text += "B --> B16\n";
  EXPECT_EQ(kCpfg.error(text),
            "46:7: the text with its macros and included files expanded "
            "comes to more than 16777216 bytes, the limit for a file");
}

TEST(Cpfg, ExpandsAMacroAgainOnceItIsDefinedAnew) {
  // A macro's expansion is kept between uses, but not past a #define or an
  // #undef of one it uses.
  EXPECT_EQ(kCpfg.derived("#define A F\n#define B A\n"
                          "Lsystem: 1\nderivation length: 2\nAxiom: B X\n"
                          "#undef A\n#define A G\nX --> B Y\n"
                          "#define A H\nY --> B\nendlsystem\n"),
            "FGH");
}

TEST(Cpfg, ContinuesAStatementOnALineThatStartsWithATab) {
  EXPECT_EQ(kCpfg.derived(std::string(kHead) +
                          "Axiom: A(2)\nA(t) : t>0\n\t--> F(t)A(t-1)\n"
                          "endlsystem\n"),
            "F(2)A(1)");
}

TEST(Cpfg, TakesProbabilitiesOnlyWithASeedAsCpfgDoes) {
  const std::string rules =
      "derivation length: 1\nAxiom: A\nA --> B : 1\nA --> C : 99\n"
      "endlsystem\n";
  const Grammar plain = kCpfg.parse("Lsystem: 1\n" + rules);
  EXPECT_EQ(to_string(derive(plain), plain.alphabet), "B");
  const auto warns_of_seed = [](const Grammar& g) {
    return std::count_if(
        g.warnings.begin(), g.warnings.end(), [](const std::string& w) {
          return w.find("without 'seed:'") != std::string::npos;
        });
  };
  EXPECT_EQ(warns_of_seed(plain), 1);
  const Grammar seeded = kCpfg.parse("Lsystem: 1\nseed: 7\n" + rules);
  EXPECT_TRUE(seeded.productions.front().probability.has_value());
  EXPECT_EQ(warns_of_seed(seeded), 0);
}

TEST(Cpfg, IgnoresTheParametersTheTurtleDoesNotRead) {
  const Grammar g =
      kCpfg.parse("Lsystem: 1\nAxiom: F(2,5,1)+(90,0)F(1)\nendlsystem\n");
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 2U);
  EXPECT_NEAR(glm::length(s.segments[0].p1 - s.segments[0].p0), 2.0, 1e-12);
  EXPECT_DOUBLE_EQ(s.segments[0].start_diameter,
                   g.settings.initial_width * g.settings.width_scale);
  EXPECT_NEAR(glm::dot(s.segments[0].p1 - s.segments[0].p0,
                       s.segments[1].p1 - s.segments[1].p0),
              0.0, 1e-12);
}

TEST_F(CpfgFiles, BendsTowardTheTropismOnceTheUnderscoreGivesElasticity) {
  write("bend.l", "Lsystem: 1\nAxiom: FF_FFF\nendlsystem\n");
  write("bend.v", "tropism direction: 1,0,0\nelasticity increment: 0.3\n");
  const Skeleton bent = interpret(read("bend.l"));
  ASSERT_EQ(bent.segments.size(), 5U);
  EXPECT_DOUBLE_EQ(bent.segments[1].p1.x, 0.0);  // before `_`: straight
  EXPECT_GT(bent.segments[4].p1.x, 0.1);
  write("bend.l", "Lsystem: 1\nAxiom: FF_(0)FFF\nendlsystem\n");
  EXPECT_DOUBLE_EQ(interpret(read("bend.l")).segments[4].p1.x, 0.0);
}

glm::dvec3 direction_of(const Segment& s) {
  return glm::normalize(s.p1 - s.p0);
}

// Mech's movements (cpfg's movements.c): before each step the heading turns
// toward the tropism's direction by |H × e·T| radians.
TEST_F(CpfgFiles, TurnsTowardATropismBeforeEachStepAsItsElasticitySays) {
  write("t.l", "Lsystem: 1\nAxiom: FF[@Ts(1,0)F]F@Ti(1)F\nendlsystem\n");
  write("t.v", "tropism: T: 1,0,0 E: 0.5 S: 0.25\n");
  const Grammar g = read("t.l");
  ASSERT_EQ(g.settings.movements.size(), 1U);
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 5U);
  const auto angle_from_up = [&](std::size_t i) {
    return std::acos(direction_of(s.segments[i]).z);
  };
  EXPECT_NEAR(angle_from_up(0), 0.5, 1e-12);
  EXPECT_NEAR(direction_of(s.segments[0]).y, 0.0, 1e-12);
  const double second = 0.5 + 0.5 * std::cos(0.5);
  EXPECT_NEAR(angle_from_up(1), second, 1e-12);
  EXPECT_NEAR(angle_from_up(2), second, 1e-12);          // elasticity 0 in [ ]
  const double third = second + 0.5 * std::cos(second);  // `]` restored it
  EXPECT_NEAR(angle_from_up(3), third, 1e-12);
  EXPECT_NEAR(angle_from_up(4), third + 0.75 * std::cos(third), 1e-12);
}

// A = 90° is plagiotropism: the heading settles across the direction (here
// cpfg's up, lsolid's +Z); along it, cpfg turns toward −left first.
TEST_F(CpfgFiles, SettlesAcrossAPlagiotropismsDirection) {
  write("p.l", "Lsystem: 1\nAxiom: FFFFFFFFFFFFFFFFFFFF\nendlsystem\n");
  write("p.v", "tropism: T: 0 2 0 A: 90 E: 1\n");
  const Skeleton s = interpret(read("p.l"));
  ASSERT_EQ(s.segments.size(), 20U);
  EXPECT_NEAR(direction_of(s.segments[0]).y, -std::sin(1.0), 1e-12);
  EXPECT_NEAR(direction_of(s.segments[19]).z, 0.0, 1e-6);
  EXPECT_NEAR(direction_of(s.segments[19]).y, -1.0, 1e-6);
}

// A torque rolls the turtle about its heading, up toward the direction:
// the turn that follows shows the roll.
TEST_F(CpfgFiles, RollsUpTowardATorquesDirection) {
  write("r.l", "Lsystem: 1\nAxiom: F+(90)F\nendlsystem\n");
  write("r.v", "torque: T: 1 0 0 E: 0.5\n");
  const Skeleton s = interpret(read("r.l"));
  ASSERT_EQ(s.segments.size(), 2U);
  EXPECT_NEAR(glm::length(direction_of(s.segments[0]) - glm::dvec3(0, 0, 1)),
              0.0, 1e-12);
  EXPECT_NEAR(glm::length(direction_of(s.segments[1]) -
                          glm::dvec3(-std::cos(0.5), -std::sin(0.5), 0.0)),
              0.0, 1e-12);
}

TEST_F(CpfgFiles, RefusesAMovementItCannotReadAndWarnsOfOneNotDefined) {
  write("m.l", "Lsystem: 1\nAxiom: F@Ts(2,1)F\nendlsystem\n");
  write("m.v", "tropism: T: 0 1 0\n");
  const Grammar g = read("m.l");
  ASSERT_EQ(g.warnings.size(), 1U);
  EXPECT_EQ(g.warnings[0],
            "line 2: '@Ts' of movement 2, which the view file does not define "
            "(it has 1 tropism: and torque: lines): ignored, as cpfg ignores "
            "it");
  write("m.v", "angle factor: 8\ntropism: T: 0 0 0 E: 1\n");
  EXPECT_EQ(located_error_of([&] { (void)read("m.l"); }),
            "2:10: a movement toward no direction (T: 0 0 0)");
  write("m.v", "torque: T: 0 1 0 X: 3\n");
  EXPECT_EQ(located_error_of([&] { (void)read("m.l"); }),
            "1:18: unknown part 'X' of a movement: expected T, I, A, E or S");
}

TEST(Cpfg, DrawsNothingForTheEndOfASubLsystemOrAnApostrophe) {
  const Skeleton s = interpret(
      kCpfg.parse("Lsystem: 1\nAxiom: F$F'F@!(3)@Tx(1)\nendlsystem\n"));
  ASSERT_EQ(s.segments.size(), 3U);
  EXPECT_NEAR(s.segments[2].p1.z, 3.0, 1e-12);
}

TEST(Cpfg, DrawsASphereOfTheWidthOrOfTheDiameterGiven) {
  // cpfg's blackbox.c: `@O` without a parameter takes the line width.
  const Skeleton s =
      interpret(kCpfg.parse("Lsystem: 1\nAxiom: !(3)F@O@O(2.5)\nendlsystem\n"));
  ASSERT_EQ(s.spheres.size(), 2U);
  EXPECT_DOUBLE_EQ(s.spheres[0].diameter, s.segments[0].end_diameter);
  EXPECT_DOUBLE_EQ(s.spheres[1].diameter, 2.5);
  EXPECT_EQ(s.spheres[0].center, s.segments[0].p1);
}

TEST(Cpfg, DrawsDiscsAcrossUpOrFacingTheViewer) {
  // blackbox.c: `@c` lies in the turtle's heading–left plane, `@o` faces
  // the viewer on cpfg's z axis (lsolid's y); without a parameter, of the
  // line width.
  const Skeleton s =
      interpret(kCpfg.parse("Lsystem: 1\nAxiom: !(0.5)F&(90)@c(2)@o@c(0)\n"
                            "endlsystem\n"));
  ASSERT_EQ(s.polygons.size(), 2U);
  const glm::dvec3 tip = s.segments[0].p1;
  testing::expect_disc(s.polygons[0], tip, glm::dvec3(0, 0, 1), 2.0);
  testing::expect_disc(s.polygons[1], tip, glm::dvec3(0, 1, 0),
                       s.segments[0].end_diameter);
  EXPECT_EQ(s.polygons[0].parent, 0);
  EXPECT_EQ(s.degenerate_polygons, 1U);  // the disc of diameter 0
}

TEST(Cpfg, DrawsAGeneralizedCylinderInPiecesAlongItsHermiteCurve) {
  // Straight: its pieces on the axis, chained, `F` inside drawing none.
  const Skeleton line =
      interpret(kCpfg.parse("Lsystem: 1\nAxiom: @Gs F(2) @Gc(4) f(2) @Ge(2)\n"
                            "endlsystem\n"));
  ASSERT_EQ(line.segments.size(), 6U);
  EXPECT_EQ(line.segments[0].p0, glm::dvec3(0, 0, 0));
  EXPECT_EQ(line.segments[5].p1, glm::dvec3(0, 0, 4));
  for (std::size_t i = 0; i < 6; ++i) {
    EXPECT_EQ(line.segments[i].p1.x, 0.0);
    EXPECT_EQ(line.segments[i].parent, static_cast<std::int32_t>(i) - 1);
  }
  // Turned by 90° between the ends: the heading (0, 0, 1) and then the
  // first left (-1, 0, 0), times the chord 1 and cpfg's factor 1.2, make
  // the middle of the curve (p1 + p2) / 2 + (t1 - t2) / 8.
  const Skeleton bent =
      interpret(kCpfg.parse("Lsystem: 1\nAxiom: !(2)@Gs +(90) f(1) !(4)@Ge(2)\n"
                            "endlsystem\n"));
  ASSERT_EQ(bent.segments.size(), 2U);
  EXPECT_NEAR(bent.segments[0].p1.x, -0.5 + 1.2 / 8, 1e-12);
  EXPECT_NEAR(bent.segments[0].p1.y, 0.0, 1e-12);
  EXPECT_NEAR(bent.segments[0].p1.z, 1.2 / 8, 1e-12);
  // Widths go linearly from one control point's to the other's.
  const double w = bent.segments[0].start_diameter;
  EXPECT_DOUBLE_EQ(bent.segments[0].end_diameter, 1.5 * w);
  EXPECT_DOUBLE_EQ(bent.segments[1].end_diameter, 2.0 * w);
  // `@Gt(0)`: no tangents, a straight chord.
  const Skeleton chord = interpret(kCpfg.parse(
      "Lsystem: 1\nAxiom: @Gt(0)@Gs +(90) f(1) @Ge(2)\nendlsystem\n"));
  ASSERT_EQ(chord.segments.size(), 2U);
  EXPECT_NEAR(chord.segments[0].p1.x, -0.5, 1e-12);
  EXPECT_NEAR(chord.segments[0].p1.z, 0.0, 1e-12);
}

TEST(Cpfg, ShapesACylindersRadiusAlongTheTangentsOfGr) {
  // From radius 0 to 0: a start tangent (0, 2) (90°, length 2) and the
  // default (1, 0) at the end make the ring at r = 1/2 sit at curve
  // parameter t = h01 + h11 = 0.375 with radius 2·h10 = 0.25.
  const Skeleton s = interpret(kCpfg.parse(
      "Lsystem: 1\nAxiom: !(0) @Gr(0,0,90,2) @Gs f(2) @Gr(0,0) @Ge(2)\n"
      "endlsystem\n"));
  ASSERT_EQ(s.segments.size(), 2U);
  EXPECT_EQ(s.segments[0].start_diameter, 0.0);
  // The radius tangents are in model units, whatever unit the widths are.
  EXPECT_NEAR(s.segments[0].end_diameter, 0.5, 1e-15);
  // The Hermite curve of the chord 2 with tangents 2 × 1.2 at t = 0.375.
  EXPECT_NEAR(s.segments[0].p1.z, 0.7734375, 1e-12);
  EXPECT_EQ(s.segments[1].end_diameter, 0.0);
}

TEST(Cpfg, RefusesWhatLsolidCannotDrawByNameAtItsPlace) {
  EXPECT_EQ(kCpfg.error("Lsystem: 1\nAxiom: F~l(2)\n"),
            "2:9: '~' (a predefined surface that no surface: line of the "
            "view names) is not supported by lsolid");
  EXPECT_EQ(kCpfg.error("Lsystem: 1\nAxiom: F\nF --> F@bo(2)\n"),
            "3:8: '@bo' (a circle) is not supported by lsolid");
  EXPECT_EQ(kCpfg.error("Lsystem: 1\nAxiom: A\nA > ?E(x) --> B\n"),
            "3:5: '?E' (a query of the environment, which needs cpfg's "
            "environment programs) is not supported by lsolid");
  EXPECT_EQ(kCpfg.error("Lsystem: 1\nAxiom: A?(2,1)B$\n"),
            "2:9: '?' (a sub-L-system call) is not supported by lsolid");
  EXPECT_EQ(kCpfg.error("Lsystem: 1\nAxiom: {(1)F}(1)\n"),
            "2:8: cpfg's '{(n)' (a generalized cylinder) is not supported; "
            "write '{' for a polygon");
}

// cpfg's environment pass (interpret.c): before each step the turtle walks
// the string and each query takes the position or frame where it stands, in
// cpfg's Y-up coordinates, so a context can read where the apex is.
TEST(Cpfg, AnswersQueriesWithThePositionAndFrameBeforeEachStep) {
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 1\n"
                          "Axiom: F(2)+(90)F(3)?P(0,0,0)?H(0,0,0)?L(0,0,0)"
                          "?U(0,0,0)\n"),
            "F(2)+(90)F(3) ?P(-3,2,0) ?H(-1,0,0) ?L(0,-1,0) ?U(0,0,-1)");
  // cpfg's `&` turns H toward its U, (0, 0, −1) at the start.
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 1\n"
                          "Axiom: &(90)F?P(0,0,0)?U(0,0,0)\n"),
            "&(90)F ?P(0,0,-1) ?U(0,-1,0)");
  // The apex grows while it is below y = 3, reading its height from the
  // query beside it, and stops the step after; a query with fewer
  // parameters takes the first coordinates only.
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 6\n"
                          "Axiom: A?P(0,0)\n"
                          "A > ?P(x,y) : y < 3 --> FA\n"),
            "FFFA ?P(0,3)");
  // The homomorphism draws what the turtle walks, as in cpfg.
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 1\n"
                          "Axiom: B?P(0,0,0)\n"
                          "homomorphism\nB --> F(5)\nendlsystem\n"),
            "B ?P(0,5,0)");
}

// cpfg takes a name that nothing defines as 0, with a warning
// ("Identifier not previously defined"), and so does lsolid.
TEST(Cpfg, TakesAnUndefinedNameAsAVariableOfZeroWithAWarning) {
  const Grammar g = kCpfg.parse(
      "Lsystem: 1\nderivation length: 1\nAxiom: A(2)\n"
      "A(x) --> B(x + t) C(t)\nendlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet), "B(2)C(0)");
  EXPECT_NE(std::find(g.warnings.begin(), g.warnings.end(),
                      "line 4: 't' is not defined: taken as 0, as cpfg "
                      "takes it"),
            g.warnings.end());
  // A statement that assigns it makes it a variable from there on.
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 1\nAxiom: A(2)\n"
                          "A(x) : {y = u + 1; u = 5;} * --> B(y, u)\n"
                          "endlsystem\n"),
            "B(1,5)");
}

TEST(Cpfg, RefusesRingLsystemsAtTheirPlace) {
  EXPECT_EQ(kCpfg.error("Lsystem: 1\nring lsystem\nAxiom: F\n"),
            "2:1: a ring L-system (contexts that wrap around the string) is "
            "not supported");
}

// cpfg's `define:` block (lsys_input.y): arrays of global variables, row by
// row, which expressions index and statements assign.
TEST(Cpfg, ReadsTheArraysOfADefineBlock) {
  const Grammar g = kCpfg.parse(
      "Lsystem: 1\nderivation length: 1\n"
      "define: { array a[3] = {1, 2, 3}, m[2][3] =\n"
      "    {1, 2, 3, 4, 5, 6};\n  array z[2]; }\n"
      "Start: {a[0] = a[2] * 10; m[1][0] = m[0][1] + z[1];}\n"
      "Axiom: A(1)\nA(i) --> F(a[i])F(m[1][i+1])F(a[0])F(m[1][0])F(m[1.5][0])\n"
      "endlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet), "F(2)F(6)F(30)F(2)F(5)");
  EXPECT_EQ(g.warnings.size(), 1U);  // no view file
  const Grammar few = kCpfg.parse(
      "Lsystem: 1\ndefine: { array a[3] = {1}; }\nAxiom: F(a[2])\n");
  EXPECT_EQ(to_string(derive(few), few.alphabet), "F(0)");
  EXPECT_EQ(few.warnings.back(),
            "line 2: array 'a' of 3 elements is given 1 values: the rest are "
            "0, as in cpfg");
  EXPECT_EQ(located_error_of([] {
              (void)derive(
                  kCpfg.parse("Lsystem: 1\ndefine: { array a[3]; }\n"
                              "Axiom: A(3)\nA(i) --> F(a[i])\n"));
            }),
            "4:14: subscript 3 is out of range: this dimension of the array "
            "has 3 elements, 0 to 2");
  EXPECT_EQ(kCpfg.error("Lsystem: 1\ndefine: { array a[3]; }\nAxiom: F(a)\n"),
            "3:11: 'a' is an array of 1 dimension: expected '['");
  EXPECT_EQ(kCpfg.error("Lsystem: 1\ndefine: { array a[0]; }\nAxiom: F\n"),
            "2:19: an array's dimension must be a whole number, at least 1");
  EXPECT_EQ(kCpfg.error("Lsystem: 1\ndefine: { x = 1; }\nAxiom: F\n"),
            "2:11: expected 'array' in a define: block");
}

// `@R` and `@M` (blackbox.c) in cpfg's Y-up coordinates; cpfg's up is
// lsolid's −up. A label `@L` draws nothing and is left out.
TEST(Cpfg, SetsTheHeadingAndThePositionOutright) {
  const Skeleton s = interpret(
      kCpfg.parse("Lsystem: 1\nAxiom: @M(1,2,3)F@R(1,0,0)F@R(1,0,0,0,1,0)+(90)F"
                  "@L(\"%.f\", 2)\nendlsystem\n"));
  ASSERT_EQ(s.segments.size(), 3U);
  EXPECT_EQ(s.segments[0].p0, glm::dvec3(1.0, -3.0, 2.0));
  EXPECT_NEAR(glm::length(direction_of(s.segments[1]) - glm::dvec3(1, 0, 0)),
              0.0, 1e-12);
  EXPECT_NEAR(glm::length(direction_of(s.segments[2]) - glm::dvec3(0, -1, 0)),
              0.0, 1e-12);
  const Grammar g = kCpfg.parse("Lsystem: 1\nAxiom: F@L(\"x\")\n");
  EXPECT_EQ(g.warnings.back(),
            "'@L' (a label) is left out: it draws nothing in a solid");
}

TEST(Cpfg, RunsStartBlocksOnceAndStartEachBeforeEveryStepWithGlobals) {
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 3\n"
                          "Start: {count = 0; length = 2;}\n"
                          "StartEach: {count = count + 1;}\n"
                          "End: {length = 5;}\n"
                          "Axiom: A(0)\n"
                          "A(x) --> F(length)A(count)\n"
                          "endlsystem\n"),
            "F(2)F(2)F(2)A(3)");
}

TEST(Cpfg, RunsStatementsBeforeAConditionAlwaysAndAfterItWhenItHolds) {
  EXPECT_EQ(kCpfg.derived(
                std::string(kHead) +
                "Axiom: A(5)\n"
                "A(t) : {t = t - 2; half = t / 2;} t > 0 {twice = half * 4;}"
                " --> B(t, half, twice)\nendlsystem\n"),
            "B(3,1.5,6)");
  // A rule whose condition fails leaves the parameters to the next one.
  EXPECT_EQ(kCpfg.derived(std::string(kHead) +
                          "Axiom: A(5)\nA(t) : {t = t - 10;} t > 0 --> X\n"
                          "A(t) --> Y(t)\nendlsystem\n"),
            "Y(5)");
}

TEST(Cpfg, RunsTheStatementsOfAStochasticChoiceOnce) {
  // Both rules apply; the first always wins (the second weighs 0). Its
  // statements ran once, when the candidates were weighed.
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nseed: 3\nderivation length: 1\n"
                          "Start: {c = 0;}\nAxiom: A\n"
                          "A : {c = c + 1;} 1 --> B(c) : 1\n"
                          "A --> C(c) : 0\nendlsystem\n"),
            "B(1)");
}

TEST(Cpfg, RunsStatementsInDecompositionAndHomomorphismRules) {
  const Grammar g =
      kCpfg.parse(std::string(kHead) +
                  "Axiom: A(1)\nA(t) --> A(t)\n"
                  "decomposition\nA(t) : {t = t * 2;} 1 --> B(t)\n"
                  "homomorphism\nB(t) : * {l = t + 1;} --> F(l)\n"
                  "endlsystem\n");
  EXPECT_EQ(to_string(derive(g), g.alphabet), "B(2)");
  const Skeleton s = interpret(g);
  ASSERT_EQ(s.segments.size(), 1U);
  EXPECT_NEAR(s.segments[0].p1.z, 3.0, 1e-12);
}

TEST(Cpfg, ReadsLoopsBranchesTheConditionalOperatorAndCpfgsFunctions) {
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\n"
                          "Start: {s = 0; i = 0; while (i < 4) {s = s + i; "
                          "i = i + 1;}\n"
                          "  if (s == 6) {r = 1;} else {r = 2;}\n"
                          "  do {i = i - 1;} while (i > 0);\n"
                          "  printf(\"s=%f\\n\", s);}\n"
                          "Axiom: A(s, r, i, 7 % 3, 1 < 2 ? 7 : 8, trunc(2.5), "
                          "sign(-3), fabs(-2))\nendlsystem\n"),
            "A(6,1,0,1,7,3,-1,2)");
}

TEST(Cpfg, DrawsRandomNumbersFromCpfgsGeneratorErand48) {
  // glibc's erand48 from cpfg's start {0x330E, 0, 0}: 0.17082803610628972,
  // then 0.74990198048496381; srand(21) starts it at {0x330E, 21, 0}.
  const Grammar g =
      kCpfg.parse("Lsystem: 1\nAxiom: A(ran(1), ran(2))\nendlsystem\n");
  const ModuleString s = derive(g);
  ASSERT_EQ(s.parameters(0).size(), 2U);
  EXPECT_DOUBLE_EQ(s.parameters(0)[0], 0.17082803610628972);
  EXPECT_DOUBLE_EQ(s.parameters(0)[1], 2 * 0.74990198048496381);
  const Grammar seeded = kCpfg.parse(
      "Lsystem: 1\nStart: {srand(21);}\nAxiom: A(ran(1))\nendlsystem\n");
  EXPECT_DOUBLE_EQ(derive(seeded).parameters(0)[0], 0.45767651808364818);
  // A seed with no integer (beyond 64 bits) starts from 0, as srand(0).
  const Grammar huge = kCpfg.parse(
      "Lsystem: 1\nStart: {srand(1e300);}\nAxiom: A(ran(1))\nendlsystem\n");
  const Grammar zero = kCpfg.parse(
      "Lsystem: 1\nStart: {srand(0);}\nAxiom: A(ran(1))\nendlsystem\n");
  EXPECT_DOUBLE_EQ(derive(huge).parameters(0)[0],
                   derive(zero).parameters(0)[0]);
  EXPECT_TRUE(g.uses_variables);
}

TEST(Cpfg, StopsALoopThatNeverEnds) {
  const Grammar g = kCpfg.parse(
      "Lsystem: 1\nStart: {while (1) {x = 1;}}\nAxiom: A\nendlsystem\n");
  EXPECT_EQ(located_error_of([&] { (void)derive(g); }),
            "2:9: a loop ran a million times; lsolid stops it");
}

TEST(Cpfg, HasNoLabelsSoAWordBeforeAColonIsAPredecessor) {
  EXPECT_EQ(kCpfg.derived("#define LEFT 1\n" + std::string(kHead) +
                          "Axiom: A\nA : LEFT --> F\nendlsystem\n"),
            "F");
}

// cpfg's modules are single characters: `FA` is F then A, and a
// predecessor of several modules replaces them all (generate.c).
TEST(Cpfg, ReadsLettersAsModulesAndRewritesAPredecessorOfSeveral) {
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 2\n"
                          "Axiom: FAFB\nFA --> FFA\n"),
            "FFFAFB");
  // The modules must stand together; the parameters bind in order, then
  // the right context's.
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 1\n"
                          "Axiom: A(1)B(2)C(3) A(4)[B(5)]C(6)\n"
                          "A(x)B(y) > C(z) --> D(x+y+z)\n"),
            "D(6)C(3)A(4)[B(5)]C(6)");
  const Grammar g =
      kCpfg.parse("Lsystem: 1\nderivation length: 1\nAxiom: FA\nFA --> FFA\n");
  EXPECT_EQ(interpret(g).segments.size(), 2U);  // F F A
  // A homomorphism's predecessor of several letters is read as one name,
  // which rewrites the same where its letters stand together.
  EXPECT_EQ(to_string(derive(kCpfg.parse("Lsystem: 1\nAxiom: Sl\nhomomorphism\n"
                                         "Sl --> F\nendlsystem\n")),
                      kCpfg
                          .parse("Lsystem: 1\nAxiom: Sl\nhomomorphism\n"
                                 "Sl --> F\nendlsystem\n")
                          .alphabet),
            "Sl");
  EXPECT_EQ(kCpfg.error("Lsystem: 1\nAxiom: A\nA * --> B\n"),
            "3:3: '*' matches any module only in a context");
}

// cpfg's `=` in a right context skips the rest of the branch (generate.c's
// skipright), so a context can look past a branch, or out of its own.
TEST(Cpfg, SkipsToTheEndOfABranchForAnEqualsSignInARightContext) {
  // Past the first branch into the second.
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 1\n"
                          "Axiom: F[+A][-D]\nF > [=][-D=] --> G\n"),
            "G[+A][-D]");
  // Out of the predecessor's branch: A then the end of its branch, then g.
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 1\n"
                          "Axiom: [BAC[D]E]g [BA]h\nB > A=]g --> X\n"),
            "[XAC[D]E]g[BA]h");
  // The branch's modules bind, `=` binds nothing.
  EXPECT_EQ(kCpfg.derived("Lsystem: 1\nderivation length: 1\n"
                          "Axiom: A(1)[B(2)C]B(3)\n"
                          "A(x) > [B(y)=]B(z) --> A(x+y+z)\n"),
            "A(6)[B(2)C]B(3)");
}

TEST_F(CpfgFiles, ReadsTheFunctionsTheViewFileNames) {
  write("leaf.l",
        "Lsystem: 1\nAxiom: A(func(1, 0.25), func(GROWTH, 2))\n"
        "endlsystem\n");
  write("leaf.v", "function set: g.fset\nfunction: line.func 100\n");
  // Collinear control points: the curve is the line y = x...
  write("line.func",
        "fver 1 1\nname: line\nsamples: 0\nflip: off\npoints: 4\n"
        "0 0 1\n0.333333 0.333333 1\n0.666667 0.666667 1\n1 1 1\n");
  // ...and here y = 2.
  write("g.fset",
        "funcgalleryver 1 1\nitems: 1\nfver 1 1\nname: GROWTH\n"
        "samples: 100\nflip: off\npoints: 4\n0 2\n0.3 2\n0.6 2\n1 2\n");
  const Grammar g = read("leaf.l");
  const ModuleString s = derive(g);
  ASSERT_EQ(s.parameters(0).size(), 2U);
  // The set comes first: GROWTH is func 1, line.func func 2.
  EXPECT_NEAR(s.parameters(0)[0], 2.0, 1e-9);
  EXPECT_NEAR(s.parameters(0)[1], 2.0, 1e-9);  // x clamped to 1
  write("leaf.l", "Lsystem: 1\nAxiom: A(func(2, 0.25))\nendlsystem\n");
  EXPECT_NEAR(derive(read("leaf.l")).parameters(0)[0], 0.25, 1e-4);
  // x that is not a number reads as 0, the low end of the clamp.
  write("leaf.l", "Lsystem: 1\nAxiom: A(func(2, sqrt(-1)) + 5)\nendlsystem\n");
  EXPECT_NEAR(derive(read("leaf.l")).parameters(0)[0], 5.0, 1e-9);
  write("leaf.l", "Lsystem: 1\nAxiom: A(func(3, 0.25))\nendlsystem\n");
  EXPECT_EQ(located_error_of([&] { (void)read("leaf.l"); }),
            "2:15: func(3, ...): the view file names 2 functions");
  write("line.func",
        "fver 1 1\nname: line\nsamples: 1e9\nflip: off\npoints: 4\n");
  EXPECT_EQ(located_error_of([&] { (void)read("leaf.l"); }),
            "3:10: samples must be a whole number from 0 to 100000");
}

// One bicubic Bézier patch in the form of vlab's bezieredit: a flat
// square, its control points (j/3, i/3, 0) in row i, and a first row that
// is one point when `pointed`.
std::string square_patch(bool pointed) {
  std::string text;
  for (int i = 0; i < 4; ++i) {
    for (int j = 0; j < 4; ++j) {
      const double x = i == 0 && pointed ? 0.5 : j / 3.0;
      text += std::to_string(x) + " " + std::to_string(i / 3.0) + " 0 ";
    }
    text += "\n";
  }
  return "patch\nTOP COLOR: 0 DIFFUSE: 0.00 BOTTOM COLOR: 0 DIFFUSE: 0.00\n"
         "AL: ~ A: ~ AR: ~\nL: ~ R: ~\nBL: ~ B: ~ BR: ~\n" +
         text;
}

constexpr std::string_view kSurfaceHead =
    "0 1 0 1 0 0\nCONTACT POINT X: 0 Y: 0 Z: 0\n"
    "END POINT X: 0 Y: 1 Z: 0\nHEADING X: 0 Y: 1 Z: 0\n"
    "UP X: 0 Y: 0 Z: 1\nSIZE: 1\n";

TEST_F(CpfgFiles, DrawsASurfaceAsOneSheetWhereTheTurtleStands) {
  write("leaf.l", "Lsystem: 1\nAxiom: F~l\nendlsystem\n");
  write("leaf.v", "surface: l sq.s 2 3 2\n");
  write("sq.s", std::string(kSurfaceHead) + square_patch(false));
  const Skeleton s = interpret(read("leaf.l"));
  ASSERT_EQ(s.sheets.size(), 1U);
  const Sheet& sheet = s.sheets[0];
  // Meshed 3 × 2 as the view asks: 4 × 3 points, two triangles a cell.
  EXPECT_EQ(sheet.points.size(), 12U);
  EXPECT_EQ(sheet.triangles.size(), 12U);
  EXPECT_EQ(sheet.parent, 0);
  // The file's x runs along the turtle's left, its y along the heading,
  // scaled by the view's 2 for the file's SIZE 1, from the contact point.
  const Segment& stem = s.segments[0];
  const glm::dvec3 heading = glm::normalize(stem.p1 - stem.p0);
  const glm::dvec3 far = sheet.points.back();  // row 3, column 3: (1, 1)
  EXPECT_NEAR(glm::dot(far - stem.p1, heading), 2.0, 1e-12);
  EXPECT_NEAR(glm::length(far - stem.p1), 2.0 * std::sqrt(2.0), 1e-12);
  EXPECT_EQ(sheet.points.front(), stem.p1);
  // The turtle ends at the end point: a second F starts 2 further on.
  write("leaf.l", "Lsystem: 1\nAxiom: F~lF\nendlsystem\n");
  const Skeleton moved = interpret(read("leaf.l"));
  ASSERT_EQ(moved.segments.size(), 2U);
  EXPECT_NEAR(glm::length(moved.segments[1].p0 - moved.segments[0].p1), 2.0,
              1e-12);
}

TEST_F(CpfgFiles, WeldsTheEdgesPatchesShareAndAPointedRow) {
  write("leaf.l", "Lsystem: 1\nAxiom: ~l\nendlsystem\n");
  write("leaf.v", "surface: l sq.s 1 3 3\n");
  // A first row of one point: its 4 grid points are one, and the 3 cells
  // beside it one triangle each.
  write("sq.s", std::string(kSurfaceHead) + square_patch(true));
  const Skeleton pointed = interpret(read("leaf.l"));
  ASSERT_EQ(pointed.sheets.size(), 1U);
  EXPECT_EQ(pointed.sheets[0].points.size(), 16U - 3U);
  EXPECT_EQ(pointed.sheets[0].triangles.size(), 18U - 3U);
  // The same patch twice shares all its points with itself.
  write("sq.s",
        std::string(kSurfaceHead) + square_patch(false) + square_patch(false));
  const Skeleton twice = interpret(read("leaf.l"));
  ASSERT_EQ(twice.sheets.size(), 1U);
  EXPECT_EQ(twice.sheets[0].points.size(), 16U);
  EXPECT_EQ(twice.sheets[0].triangles.size(), 36U);
}

TEST_F(CpfgFiles, ScalesASurfaceByItsParametersAndDropsAFlatOne) {
  write("leaf.l", "Lsystem: 1\nAxiom: ~l(1,3)~l(0)~l(1e-17)\nendlsystem\n");
  write("leaf.v", "surface: l sq.s 1 1 1\n");
  write("sq.s", std::string(kSurfaceHead) + square_patch(false));
  const Skeleton s = interpret(read("leaf.l"));
  ASSERT_EQ(s.sheets.size(), 1U);
  EXPECT_EQ(s.degenerate_polygons, 2U);  // some ulps across: flat too
  // ~l(1, 3): x by 1, y (along the heading) by 3, z by 1.
  EXPECT_NEAR(glm::length(s.sheets[0].points.back() - s.sheets[0].points[0]),
              std::sqrt(1.0 + 9.0), 1e-12);
}

// A contour from (-1, 0) to (1, 0), its ends counted three times.
constexpr std::string_view kLineContour =
    "cver 1 3\nname: line\npoints: 2 6\ntype: or\nsamples: 8\n"
    "-1 0 0 3\n1 0 0 3\n";

TEST_F(CpfgFiles, SweepsAContourAlongAGeneralizedCylinderAsOneSheet) {
  write("leaf.l",
        "Lsystem: 1\nAxiom: F !(2) @#(1) @!(4) @Gt(1) @Gs f(3) @Ge(3)\n"
        "endlsystem\n");
  write("leaf.v", "line style: cylinder\ncontour: 1 line.con\n");
  write("line.con", kLineContour);
  const Skeleton s = interpret(read("leaf.l"));
  ASSERT_EQ(s.segments.size(), 1U);  // the F; the cylinder is a sheet
  ASSERT_EQ(s.sheets.size(), 1U);
  const Sheet& sheet = s.sheets[0];
  // 4 rings of 4 + 1 points, two triangles between neighbours.
  ASSERT_EQ(sheet.points.size(), 20U);
  EXPECT_EQ(sheet.triangles.size(), 24U);
  EXPECT_EQ(sheet.parent, 0);
  // The contour's x runs along cpfg's up, lsolid's −up (0, −1, 0) at the
  // start, times the radius 1; its points are evenly spaced (to the
  // 64 chords a span of the table of lengths). With tangents of the
  // chord's length (`@Gt(1)`) the rings are evenly spaced too.
  for (std::size_t ring = 0; ring < 4; ++ring) {
    for (std::size_t i = 0; i < 5; ++i) {
      const glm::dvec3 p = sheet.points[ring * 5 + i];
      EXPECT_NEAR(p.x, 0.0, 1e-12);
      EXPECT_NEAR(p.y, -1.0 + 0.5 * static_cast<double>(i), 1e-4);
      EXPECT_NEAR(p.z, 1.0 + static_cast<double>(ring), 1e-12);
    }
  }
}

TEST_F(CpfgFiles, WarnsOfContourSidesOutsideWhatItDraws) {
  // Clamped to 3 to 256, as before, but no longer without a word.
  write("leaf.l", "Lsystem: 1\nAxiom: F\nendlsystem\n");
  const std::string view = (dir_ / "leaf.v").string();
  for (const auto& [sides, taken] :
       std::vector<std::pair<std::string, int>>{{"1000", 256}, {"1", 3}}) {
    write("leaf.v", "contour sides: " + sides + "\n");
    const Grammar g = read("leaf.l");
    EXPECT_EQ(g.settings.contour_sides, taken);
    EXPECT_NE(std::find(g.warnings.begin(), g.warnings.end(),
                        view + ":1: contour sides: " + sides +
                            " is outside 3 to 256: taken as " +
                            std::to_string(taken)),
              g.warnings.end())
        << sides;
  }
  write("leaf.v", "contour sides: 12\n");
  const Grammar quiet = read("leaf.l");
  EXPECT_EQ(quiet.settings.contour_sides, 12);
  for (const std::string& w : quiet.warnings) {
    EXPECT_EQ(w.find("contour sides"), std::string::npos) << w;
  }
}

TEST_F(CpfgFiles, TwistsAContourSmoothlyOnlyWhenTheViewAsksForIt) {
  write("leaf.l",
        "Lsystem: 1\nAxiom: @#(1) @!(4) @Gs f(3) /(90) @Ge(3)\n"
        "endlsystem\n");
  write("line.con", kLineContour);
  // The angle of each ring's end from its centre, about the heading.
  const auto angles = [&] {
    const Skeleton s = interpret(read("leaf.l"));
    std::vector<double> out;
    for (std::size_t ring = 0; ring < 4; ++ring) {
      const glm::dvec3 d = s.sheets.at(0).points.at(ring * 5 + 4) -
                           s.sheets.at(0).points.at(ring * 5);
      out.push_back(std::atan2(d.x, d.y) * 180.0 / std::numbers::pi);
    }
    return out;
  };
  write("leaf.v", "contour: 1 line.con\ntwist of cylinders: on\n");
  const std::vector<double> smooth = angles();
  write("leaf.v", "contour: 1 line.con\n");
  const std::vector<double> sudden = angles();
  for (std::size_t ring = 0; ring < 4; ++ring) {
    EXPECT_NEAR(std::fabs(smooth[ring]), 30.0 * static_cast<double>(ring),
                1e-9);
    EXPECT_NEAR(std::fabs(sudden[ring]), ring == 3 ? 90.0 : 0.0, 1e-9);
  }
}

TEST_F(CpfgFiles, PlacesErrorsInAContourFileAndNamesAMissingContour) {
  write("leaf.l", "Lsystem: 1\nAxiom: @#(2) @Gs f @Ge(3)\nendlsystem\n");
  write("leaf.v", "contour: 1 line.con\n");
  write("line.con", kLineContour);
  EXPECT_EQ(located_error_of([&] { (void)interpret(read("leaf.l")); }),
            "2:8: no contour: line of the view file names contour 2");
  write("line.con",
        "cver 1 3\nname: line\npoints: 2 7\ntype: or\nsamples: 8\n"
        "-1 0 0 3\n1 0 0 3\n");
  EXPECT_EQ(located_error_of([&] { (void)read("leaf.l"); }),
            "7:8: the control points count 6, not the 7 the header gives");
  write("line.con",
        "cver 1 3\nname: line\npoints: 2 6\ntype: or\nsamples: 8\n"
        "-1 0 1 3\n1 0 0 3\n");
  EXPECT_EQ(located_error_of([&] { (void)read("leaf.l"); }),
            "6:6: a contour out of its plane (a third coordinate other than "
            "0) is not supported");
  write("line.con",
        "cver 1 3\nname: line\npoints: 2 6\ntype: cr\nsamples: 8\n"
        "-1 0 0 3\n1 0 0 3\n");
  write("leaf.l", "Lsystem: 1\nAxiom: @#(1) @Gs f @Ge(3)\nendlsystem\n");
  EXPECT_EQ(located_error_of([&] { (void)interpret(read("leaf.l")); }),
            "2:8: contour 1 is closed; closed contours (a solid "
            "cross-section other than the circle) are not supported yet");
}

TEST_F(CpfgFiles, PlacesErrorsInASurfaceFileAndNamesAMissingOne) {
  write("leaf.l", "Lsystem: 1\nAxiom: ~l\nendlsystem\n");
  write("leaf.v", "surface: l sq.s 1 3 3\n");
  write("sq.s", "0 1 0 1 0 0\nCONTACT POINT X: 0 Y: 0\n");
  EXPECT_EQ(located_error_of([&] { (void)read("leaf.l"); }),
            "2:25: expected 'Z:'");  // at the end of the file
  write("sq.s", std::string(kSurfaceHead));
  EXPECT_EQ(located_error_of([&] { (void)read("leaf.l"); }),
            "6:9: expected a patch");
  std::filesystem::remove(dir_ / "sq.s");
  EXPECT_THROW((void)read("leaf.l"), ParseError);
}

TEST(Cpfg, RefusesAViewFileForAnotherNotation) {
  EXPECT_THROW(
      (void)parse_grammar_text("axiom: F\n", {.view_file = "plant.v"}, "a.ls"),
      ParseError);
}

}  // namespace
}  // namespace lsys
