// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// vlab's contour files, as cpfg's general.c reads them
// (_ReadContour0000 to _ReadContour0103): a header, then per control point
// `x y z m`, the point and how many times it counts (3 at an end makes
// the B-spline reach it).
#include "dialects/cpfg_contour.hpp"

#include <algorithm>
#include <string>

#include "dialects/word_scanner.hpp"

namespace lsys::dialects {
namespace {

// Far more control points than vlab's editor makes (its contours have 4 to
// 15); a bound keeps a corrupt count from allocating without end.
constexpr double kMostPoints = 10000;

class ContourReader : WordScanner {
 public:
  explicit ContourReader(const SourceFile& file) : WordScanner(file) {}

  Contour run() {
    Contour contour;
    if (word_is("cver")) {
      word();
      const double major = number();
      const double minor = number();
      if (major != 1.0 || minor < 1.0 || minor > 3.0) {
        fail("contour file version " + std::to_string(int(major)) + "." +
             std::to_string(int(minor)) +
             " is not one cpfg reads (1.1 to 1.3)");
      }
      skip_line();  // the rest of the version's line
      skip_line();  // name: ...
      expect("points:");
      const int given = count();
      const int total = count();
      expect("type:");
      const std::string_view type = word();
      contour.closed = !type.empty() && type.front() == 'c';
      if (minor >= 2.0 &&
          (type.size() < 2 || (type[0] != 'o' && type[0] != 'c') ||
           (type[1] != 'r' && type[1] != 'e'))) {
        fail("expected the type 'or', 'oe', 'cr' or 'ce'");
      }
      if (minor >= 3.0) {
        expect("samples:");
        (void)number();
        if (word_is("background")) {
          skip_line();
          skip_line();
        }
        if (word_is("markers:")) {
          word();
          const int markers = count();
          skip_line();
          for (int i = 0; i < markers; ++i) skip_line();
        }
      }
      for (int i = 0; i < given; ++i) {
        const glm::dvec2 p = point();
        skip_blanks();
        const std::size_t at = pos_;
        const int times = count();
        if (times < 1) {
          pos_ = at;
          fail("a control point counts at least once");
        }
        contour.control_points.insert(contour.control_points.end(),
                                      static_cast<std::size_t>(times), p);
        if (contour.control_points.size() > static_cast<std::size_t>(total)) {
          pos_ = at;
          fail("the control points count more than the " +
               std::to_string(total) + " the header gives");
        }
      }
      if (contour.control_points.size() != static_cast<std::size_t>(total)) {
        fail("the control points count " +
             std::to_string(contour.control_points.size()) + ", not the " +
             std::to_string(total) + " the header gives");
      }
    } else {
      // The first format: `num dim open|closed`, then the points.
      const int given = count();
      skip_blanks();
      const std::size_t at = pos_;
      const double dim = number();
      if (dim != 2.0 && dim != 3.0) {
        pos_ = at;
        fail("a contour has 2 or 3 dimensions");
      }
      contour.closed = word() == "closed";
      for (int i = 0; i < given; ++i) {
        contour.control_points.push_back(
            dim == 2.0 ? glm::dvec2(number(), number()) : point());
      }
    }
    skip_blanks();
    if (pos_ < text_.size()) fail("unexpected text after the contour's points");
    if (contour.control_points.size() < 4) {
      fail(
          "a contour needs at least 4 control points (counted with their "
          "repetitions) to make a curve");
    }
    const glm::dvec2 first = contour.control_points.front();
    if (std::all_of(contour.control_points.begin(),
                    contour.control_points.end(),
                    [&](const glm::dvec2& p) { return p == first; })) {
      fail("the contour's control points are all in one place");
    }
    return contour;
  }

 private:
  void expect(std::string_view w) {
    skip_blanks();
    const std::size_t at = pos_;
    if (word() != w) {
      pos_ = at;
      fail("expected '" + std::string(w) + "'");
    }
  }

  void skip_line() {
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    if (pos_ < text_.size()) ++pos_;
  }

  int count() {
    skip_blanks();
    const std::size_t at = pos_;
    const double n = number();
    if (n < 0.0 || n > kMostPoints || n != static_cast<int>(n)) {
      pos_ = at;
      fail("expected a count of points");
    }
    return static_cast<int>(n);
  }

  glm::dvec2 point() {
    const double x = number();
    const double y = number();
    skip_blanks();
    const std::size_t at = pos_;
    if (number() != 0.0) {
      pos_ = at;
      fail(
          "a contour out of its plane (a third coordinate other than 0) "
          "is not supported");
    }
    return {x, y};
  }
};

}  // namespace

Contour read_cpfg_contour(const SourceFile& file) {
  return ContourReader(file).run();
}

}  // namespace lsys::dialects
