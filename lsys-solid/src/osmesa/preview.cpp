// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
//
// The preview renderer, the only unit that includes OpenGL. OSMesa renders
// into a buffer in memory with Mesa's software rasteriser, so the same path
// works on a headless CI machine. The fixed-function pipeline is enough for
// a shaded picture: flat normals, a key and a fill light, orthographic
// projection, drawn from client-side vertex arrays.
#include "lsolid/preview.hpp"

#include <GL/gl.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>
#include <memory>
#include <numbers>
#include <stdexcept>

#include "lsolid/errors.hpp"

namespace lsolid {
namespace {

struct ContextDeleter {
  void operator()(osmesa_context* c) const { OSMesaDestroyContext(c); }
};

std::array<GLfloat, 4> rgba(const glm::dvec3& c, double scale = 1.0) {
  return {static_cast<GLfloat>(c.x * scale), static_cast<GLfloat>(c.y * scale),
          static_cast<GLfloat>(c.z * scale), 1.0F};
}

}  // namespace

glm::ivec3 Image::at(int x, int y) const {
  const std::size_t i =
      (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
       static_cast<std::size_t>(x)) *
      3;
  return {rgb[i], rgb[i + 1], rgb[i + 2]};
}

Image render_preview(const TriangleMesh& mesh, const PreviewOptions& options) {
  const int ss = std::max(1, options.supersampling);
  const int w = options.width_px * ss;
  const int h = options.height_px * ss;
  std::unique_ptr<osmesa_context, ContextDeleter> context(
      OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr));
  if (!context) throw IoError("cannot create an OSMesa OpenGL context");
  std::vector<GLubyte> buffer(static_cast<std::size_t>(w) *
                              static_cast<std::size_t>(h) * 4);
  if (!OSMesaMakeCurrent(context.get(), buffer.data(), GL_UNSIGNED_BYTE, w,
                         h)) {
    throw IoError("cannot bind the OSMesa OpenGL context");
  }

  // The camera: looking at the box centre from azimuth/elevation, Z up.
  constexpr double kDeg = std::numbers::pi / 180.0;
  const double az = options.azimuth_deg * kDeg;
  const double el = options.elevation_deg * kDeg;
  const glm::dvec3 toward_eye(std::cos(el) * std::cos(az),
                              std::cos(el) * std::sin(az), std::sin(el));
  // The picture's axes, as glm::lookAt makes them below.
  const glm::dvec3 right =
      glm::normalize(glm::cross(glm::dvec3(0, 0, 1), toward_eye));
  const glm::dvec3 up = glm::cross(toward_eye, right);
  // Fit the projected vertices, keeping the picture's aspect.
  glm::dvec3 lo(0.0);
  glm::dvec3 hi(0.0);
  for (std::size_t i = 0; i < mesh.vertices.size(); ++i) {
    const glm::dvec3& p = mesh.vertices[i];
    const glm::dvec3 q(glm::dot(p, right), glm::dot(p, up),
                       glm::dot(p, toward_eye));
    lo = i == 0 ? q : glm::min(lo, q);
    hi = i == 0 ? q : glm::max(hi, q);
  }
  const glm::dvec3 mid = (lo + hi) / 2.0;
  const glm::dvec3 centre = mid.x * right + mid.y * up + mid.z * toward_eye;
  constexpr double kMargin = 1.06;
  double half_x = std::max((hi.x - lo.x) / 2.0, 1e-9) * kMargin;
  double half_y = std::max((hi.y - lo.y) / 2.0, 1e-9) * kMargin;
  const double depth = std::max((hi.z - lo.z) / 2.0, 1e-9);
  const double aspect = static_cast<double>(w) / h;
  if (half_x / half_y > aspect) {
    half_y = half_x / aspect;
  } else {
    half_x = half_y * aspect;
  }

  glViewport(0, 0, w, h);
  glClearColor(static_cast<GLfloat>(options.background.x),
               static_cast<GLfloat>(options.background.y),
               static_cast<GLfloat>(options.background.z), 1.0F);
  glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
  glEnable(GL_DEPTH_TEST);
  glMatrixMode(GL_PROJECTION);
  const glm::dmat4 projection =
      glm::ortho(-half_x, half_x, -half_y, half_y, -2.0 * depth, 2.0 * depth);
  glLoadMatrixd(glm::value_ptr(projection));
  glMatrixMode(GL_MODELVIEW);
  // The eye at the box centre, looking away from `toward_eye`: the
  // orthographic volume reaches two depths to either side of it.
  const glm::dmat4 view =
      glm::lookAt(centre, centre - toward_eye, glm::dvec3(0.0, 0.0, 1.0));
  glLoadIdentity();

  // Lights in eye space: a key light from the upper left, a dimmer fill
  // from the right, and some ambient light so nothing is black.
  glEnable(GL_LIGHTING);
  const std::array<GLfloat, 4> key_at = {-0.5F, 0.7F, 1.0F, 0.0F};
  const std::array<GLfloat, 4> fill_at = {0.8F, -0.2F, 0.6F, 0.0F};
  const std::array<GLfloat, 4> key = {0.75F, 0.75F, 0.75F, 1.0F};
  const std::array<GLfloat, 4> fill = {0.30F, 0.30F, 0.32F, 1.0F};
  const std::array<GLfloat, 4> ambient = {0.25F, 0.25F, 0.25F, 1.0F};
  glEnable(GL_LIGHT0);
  glLightfv(GL_LIGHT0, GL_POSITION, key_at.data());
  glLightfv(GL_LIGHT0, GL_DIFFUSE, key.data());
  glLightfv(GL_LIGHT0, GL_SPECULAR, fill.data());
  glEnable(GL_LIGHT1);
  glLightfv(GL_LIGHT1, GL_POSITION, fill_at.data());
  glLightfv(GL_LIGHT1, GL_DIFFUSE, fill.data());
  glLightModelfv(GL_LIGHT_MODEL_AMBIENT, ambient.data());
  const auto diffuse = rgba(options.color);
  const auto shadow = rgba(options.color, 0.6);
  const std::array<GLfloat, 4> shine = {0.15F, 0.15F, 0.15F, 1.0F};
  glMaterialfv(GL_FRONT_AND_BACK, GL_DIFFUSE, diffuse.data());
  glMaterialfv(GL_FRONT_AND_BACK, GL_AMBIENT, shadow.data());
  glMaterialfv(GL_FRONT_AND_BACK, GL_SPECULAR, shine.data());
  glMaterialf(GL_FRONT_AND_BACK, GL_SHININESS, 24.0F);
  glShadeModel(GL_FLAT);
  glLoadMatrixd(glm::value_ptr(view));

  // Each triangle with its own normal (flat shading), as vertex arrays;
  // its colour, if it has one, as the material's ambient and diffuse
  // colour.
  const bool colored = !options.triangle_colors.empty();
  if (colored && options.triangle_colors.size() != mesh.triangles.size()) {
    throw std::logic_error("render_preview: one colour per triangle expected");
  }
  std::vector<GLfloat> positions;
  std::vector<GLfloat> normals;
  std::vector<GLfloat> colors;
  positions.reserve(mesh.triangles.size() * 9);
  normals.reserve(mesh.triangles.size() * 9);
  if (colored) colors.reserve(mesh.triangles.size() * 12);
  for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
    const auto& t = mesh.triangles[i];
    const glm::dvec3& a = mesh.vertices[t[0]];
    const glm::dvec3& b = mesh.vertices[t[1]];
    const glm::dvec3& c = mesh.vertices[t[2]];
    const glm::dvec3 n = glm::cross(b - a, c - a);
    const double length = glm::length(n);
    const glm::dvec3 unit = length > 0.0 ? n / length : glm::dvec3(0, 0, 1);
    for (const glm::dvec3* p : {&a, &b, &c}) {
      positions.insert(positions.end(),
                       {static_cast<GLfloat>(p->x), static_cast<GLfloat>(p->y),
                        static_cast<GLfloat>(p->z)});
      normals.insert(normals.end(), {static_cast<GLfloat>(unit.x),
                                     static_cast<GLfloat>(unit.y),
                                     static_cast<GLfloat>(unit.z)});
      if (colored) {
        const auto color = rgba(options.triangle_colors[i]);
        colors.insert(colors.end(), color.begin(), color.end());
      }
    }
  }
  glEnableClientState(GL_VERTEX_ARRAY);
  glEnableClientState(GL_NORMAL_ARRAY);
  glVertexPointer(3, GL_FLOAT, 0, positions.data());
  glNormalPointer(GL_FLOAT, 0, normals.data());
  if (colored) {
    glEnable(GL_COLOR_MATERIAL);
    glColorMaterial(GL_FRONT_AND_BACK, GL_AMBIENT_AND_DIFFUSE);
    glEnableClientState(GL_COLOR_ARRAY);
    glColorPointer(4, GL_FLOAT, 0, colors.data());
  }
  glDrawArrays(GL_TRIANGLES, 0, static_cast<GLsizei>(positions.size() / 3));
  glFinish();

  // Average ss × ss blocks; OpenGL's rows run from the bottom.
  Image image{options.width_px, options.height_px, {}};
  image.rgb.resize(static_cast<std::size_t>(image.width) *
                   static_cast<std::size_t>(image.height) * 3);
  for (int y = 0; y < image.height; ++y) {
    for (int x = 0; x < image.width; ++x) {
      for (int channel = 0; channel < 3; ++channel) {
        int sum = 0;
        for (int dy = 0; dy < ss; ++dy) {
          for (int dx = 0; dx < ss; ++dx) {
            const int row = h - 1 - (y * ss + dy);
            const std::size_t i =
                (static_cast<std::size_t>(row) * static_cast<std::size_t>(w) +
                 static_cast<std::size_t>(x * ss + dx)) *
                    4 +
                static_cast<std::size_t>(channel);
            sum += buffer[i];
          }
        }
        image.rgb[(static_cast<std::size_t>(y) *
                       static_cast<std::size_t>(image.width) +
                   static_cast<std::size_t>(x)) *
                      3 +
                  static_cast<std::size_t>(channel)] =
            static_cast<std::uint8_t>((sum + ss * ss / 2) / (ss * ss));
      }
    }
  }
  return image;
}

}  // namespace lsolid
