// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// vlab's function files (VLAB Tools Manual §8.4, and cpfg's splinefun.cpp
// for how cpfg evaluates them): a curve (X(u), Y(u)) that is a clamped
// cubic B-spline over its control points, and func(x) = Y(u) where
// X(u) = x, found by bisection. The curve is evaluated with de Boor's
// algorithm (Piegl and Tiller, The NURBS Book, A2.2); a dozen lines, so
// no spline library is pulled in for it.
#include "dialects/cpfg_functions.hpp"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string>
#include <string_view>

#include "dialects/word_scanner.hpp"
#include "lsys/diagnostic.hpp"

namespace lsys::dialects {
namespace {

struct Point {
  double x;
  double y;
};

// The point at u in [0, 1] of the clamped uniform cubic B-spline over
// `points` (at least 4).
Point evaluate(const std::vector<Point>& points, double u) {
  const int n = static_cast<int>(points.size()) - 1;  // last index
  constexpr int kDegree = 3;
  const int spans = n - kDegree + 1;
  const auto knot = [&](int i) {
    if (i <= kDegree) return 0.0;
    if (i > n) return 1.0;
    return static_cast<double>(i - kDegree) / spans;
  };
  int span = kDegree + std::min(spans - 1, static_cast<int>(u * spans));
  std::vector<Point> d(points.begin() + span - kDegree,
                       points.begin() + span + 1);
  for (int r = 1; r <= kDegree; ++r) {
    for (int j = kDegree; j >= r; --j) {
      const int i = span - kDegree + j;
      const double left = knot(i);
      const double right = knot(i + kDegree - r + 1);
      const double a = right > left ? (u - left) / (right - left) : 0.0;
      const auto k = static_cast<std::size_t>(j);
      d[k] = Point{(1.0 - a) * d[k - 1].x + a * d[k].x,
                   (1.0 - a) * d[k - 1].y + a * d[k].y};
    }
  }
  return d[kDegree];
}

// y where the curve's x is x: bisection on u, as cpfg does.
double value_at(const std::vector<Point>& points, double x) {
  double lo = 0.0;
  double hi = 1.0;
  for (int i = 0; i < 60; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (evaluate(points, mid).x < x) {
      lo = mid;
    } else {
      hi = mid;
    }
  }
  return evaluate(points, 0.5 * (lo + hi)).y;
}

class FunctionReader : WordScanner {
 public:
  explicit FunctionReader(const SourceFile& file) : WordScanner(file) {}

  std::vector<CpfgFunction> run() {
    std::vector<CpfgFunction> out;
    skip_blanks();
    if (word_is("funcgalleryver")) {
      word();
      number();
      number();
      expect("items:");
      const int items = count(1, 1000, "items");
      for (int i = 0; i < items; ++i) out.push_back(function());
    } else {
      out.push_back(function());
    }
    return out;
  }

 private:
  void expect(std::string_view w) {
    if (word() != w) fail("expected '" + std::string(w) + "'");
  }

  // A count in [least, most], refused otherwise (a huge `samples:` would
  // take hours, and a cast of it is undefined).
  int count(int least, int most, const char* what) {
    const std::size_t at = pos_;
    const double value = number();
    if (!(value >= least && value <= most) || value != std::floor(value)) {
      pos_ = at;
      skip_blanks();
      fail(std::string(what) + " must be a whole number from " +
           std::to_string(least) + " to " + std::to_string(most));
    }
    return static_cast<int>(value);
  }

  // The rest of the line, after `name:`.
  std::string line_rest() {
    while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t'))
      ++pos_;
    const std::size_t at = pos_;
    while (pos_ < text_.size() && text_[pos_] != '\n') ++pos_;
    std::string_view v = text_.substr(at, pos_ - at);
    while (!v.empty() && std::isspace(static_cast<unsigned char>(v.back())))
      v.remove_suffix(1);
    return std::string(v);
  }

  CpfgFunction function() {
    CpfgFunction f;
    int samples = 0;
    skip_blanks();
    if (word_is("fver")) {
      word();
      number();
      number();
      expect("name:");
      f.name = line_rest();
      expect("samples:");
      samples = count(0, 100000, "samples");
      expect("flip:");
      word();
      if (word_is("background:")) {
        word();
        line_rest();
      }
    } else if (word_is("range:")) {
      word();
      number();
      number();
    } else {
      fail("expected a function file: 'fver 1 1' or 'range:'");
    }
    expect("points:");
    const int points_given = count(4, 10000, "points");
    std::vector<Point> points;
    for (int i = 0; i < points_given; ++i) {
      const double x = number();
      const double y = number();
      int multiplicity = 1;
      // A third number on the line is the point's multiplicity.
      std::size_t k = pos_;
      while (k < text_.size() && (text_[k] == ' ' || text_[k] == '\t')) ++k;
      if (k < text_.size() &&
          std::isdigit(static_cast<unsigned char>(text_[k])) != 0) {
        multiplicity = count(1, 3, "a multiplicity");
      }
      for (int m = 0; m < multiplicity; ++m) points.push_back(Point{x, y});
    }
    const int n = samples > 2 ? samples : 1001;
    f.samples.reserve(static_cast<std::size_t>(n));
    for (int i = 0; i < n; ++i) {
      f.samples.push_back(value_at(points, static_cast<double>(i) / (n - 1)));
    }
    return f;
  }
};

}  // namespace

std::vector<CpfgFunction> read_cpfg_functions(const SourceFile& file) {
  return FunctionReader(file).run();
}

}  // namespace lsys::dialects
