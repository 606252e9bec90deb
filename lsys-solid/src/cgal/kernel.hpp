// Copyright 2026 the lsolid authors
// SPDX-License-Identifier: MIT
#pragma once

#include <CGAL/Exact_predicates_exact_constructions_kernel.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

namespace CGAL::Polygon_mesh_processing {}

namespace lsolid {

/// Exact predicates on double coordinates (EPICK): tests of meshes whose
/// points are given, which construct nothing new.
using Inexact = CGAL::Exact_predicates_inexact_constructions_kernel;
using InexactPoint = Inexact::Point_3;
using InexactMesh = CGAL::Surface_mesh<InexactPoint>;

/// Exact predicates and exact constructions (EPECK): the booleans and cuts,
/// whose new points must not be rounded before the result is finished
/// (docs/design.md, "Union").
using Exact = CGAL::Exact_predicates_exact_constructions_kernel;
using ExactPoint = Exact::Point_3;
using ExactMesh = CGAL::Surface_mesh<ExactPoint>;

namespace PMP = CGAL::Polygon_mesh_processing;

}  // namespace lsolid
