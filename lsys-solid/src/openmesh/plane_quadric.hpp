// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <OpenMesh/Core/Geometry/QuadricT.hh>
#include <OpenMesh/Tools/Decimater/ModBaseT.hh>
#include <cfloat>

namespace lsolid {

/// The quadric error of Garland and Heckbert (SIGGRAPH 1997) with every
/// plane counted once, not weighted by its triangle's area as in OpenMesh's
/// ModQuadricT. The error is then a sum of squared distances in mm², so a
/// bound of tol² keeps the kept vertex within tol of every original plane
/// it has absorbed. With ModQuadricT's weights a 0.05 mm bound let the
/// surface move 0.76 mm on the bush, whose triangles are far smaller than
/// 1 mm² (measured with CGAL's Hausdorff distance).
template <typename MeshT>
class ModPlaneQuadricT : public OpenMesh::Decimater::ModBaseT<MeshT> {
 public:
  DECIMATING_MODULE(ModPlaneQuadricT, MeshT, PlaneQuadric);

  /// A priority module, unbounded until set_max_error.
  explicit ModPlaneQuadricT(MeshT& mesh) : Base(mesh, false) {
    mesh.add_property(quadrics_);
  }
  ~ModPlaneQuadricT() override { Base::mesh().remove_property(quadrics_); }

  /// Collapses whose error exceeds this many mm² are illegal.
  void set_max_error(double mm2) { max_error_mm2_ = mm2; }

  /// Sums the planes of each vertex's triangles.
  void initialize() override {
    MeshT& m = Base::mesh();
    for (const auto v : m.vertices()) m.property(quadrics_, v).clear();
    for (const auto f : m.faces()) {
      auto n = m.calc_face_normal(f);
      const double length = n.norm();
      if (length <= 0.0) continue;
      n /= length;
      const auto p = m.point(*m.cfv_begin(f));
      const Quadric q(n[0], n[1], n[2], -(p | n));
      for (const auto v : m.fv_range(f)) m.property(quadrics_, v) += q;
    }
  }

  /// The summed squared distance of the kept vertex to the planes of both
  /// vertices, or illegal above the bound.
  float collapse_priority(const CollapseInfo& ci) override {
    Quadric q = Base::mesh().property(quadrics_, ci.v0);
    q += Base::mesh().property(quadrics_, ci.v1);
    const double error = q(ci.p1);
    return error <= max_error_mm2_ ? float(error)
                                   : float(Base::ILLEGAL_COLLAPSE);
  }

  /// The kept vertex inherits the removed one's planes.
  void postprocess_collapse(const CollapseInfo& ci) override {
    Base::mesh().property(quadrics_, ci.v1) +=
        Base::mesh().property(quadrics_, ci.v0);
  }

 private:
  using Quadric = OpenMesh::Geometry::QuadricT<double>;
  double max_error_mm2_ = DBL_MAX;
  OpenMesh::VPropHandleT<Quadric> quadrics_;
};

}  // namespace lsolid
