// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#include "lsolid/units.hpp"

#include <gtest/gtest.h>

#include <string>

#include "lsys/diagnostic.hpp"

namespace lsolid {
namespace {

// The message parse_length_mm refuses `text` with, or "no error".
std::string length_error(const char* text) {
  try {
    (void)parse_length_mm(text, "--wall");
  } catch (const lsys::ParseError& e) {
    return e.diagnostic().message;
  }
  return "no error";
}

TEST(Units, ReadsMillimetresCentimetresAndInches) {
  EXPECT_EQ(parse_length_mm("0.8mm", "--wall"), 0.8);
  EXPECT_EQ(parse_length_mm("12", "--height"), 12.0);
  EXPECT_EQ(parse_length_mm("2 cm", "--size"), 20.0);
  EXPECT_DOUBLE_EQ(parse_length_mm("1in", "--size"), 25.4);
}

TEST(Units, RejectsBadLengthsWithTheirColumn) {
  try {
    (void)parse_length_mm("0.8 ft", "--wall");
    FAIL() << "no error";
  } catch (const lsys::ParseError& e) {
    EXPECT_EQ(e.diagnostic().file, "--wall");
    EXPECT_EQ(e.diagnostic().column, 5);
    EXPECT_EQ(e.diagnostic().message, "unknown unit 'ft': use mm, cm or in");
  }
  EXPECT_THROW((void)parse_length_mm("mm", "--wall"), lsys::ParseError);
  EXPECT_THROW((void)parse_length_mm("-1mm", "--wall"), lsys::ParseError);
  EXPECT_THROW((void)parse_length_mm("0", "--wall"), lsys::ParseError);
  for (const char* bad : {"inf", "nan", "infmm"}) {
    EXPECT_EQ(length_error(bad), "a length must be a positive, finite number")
        << bad;
  }
}

TEST(Units, RefusesALengthAboveAKilometre) {
  EXPECT_EQ(parse_length_mm("100000cm", "--size"), 1e6);
  // 1e308 inches is not even a finite number of millimetres.
  for (const char* bad : {"1000001", "1e308in", "1e300mm"}) {
    EXPECT_EQ(length_error(bad), "a length must be at most 1000000 mm (1 km)")
        << bad;
  }
}

TEST(Units, ReadsABedAsThreeLengthsWithOneUnit) {
  EXPECT_EQ(parse_bed_mm("220x220x250mm", "--bed"), glm::dvec3(220, 220, 250));
  EXPECT_EQ(parse_bed_mm("25x21x21cm", "--bed"), glm::dvec3(250, 210, 210));
  EXPECT_EQ(parse_bed_mm("180x180x180", "--bed"), glm::dvec3(180, 180, 180));
  EXPECT_EQ(parse_bed_mm("22cmx220mmx25cm", "--bed"),
            glm::dvec3(220, 220, 250));
  EXPECT_EQ(parse_bed_mm("220X220X250", "--bed"), glm::dvec3(220, 220, 250));
  for (const char* bad : {"220x220", "220x220x250x1", "axbxcmm", "1x0x1"}) {
    EXPECT_THROW((void)parse_bed_mm(bad, "--bed"), lsys::ParseError) << bad;
  }
  try {
    (void)parse_bed_mm("220x220", "--bed");
  } catch (const lsys::ParseError& e) {
    EXPECT_EQ(e.diagnostic().message,
              "a bed is WIDTHxDEPTHxHEIGHT, such as 220x220x250mm");
  }
}

}  // namespace
}  // namespace lsolid
