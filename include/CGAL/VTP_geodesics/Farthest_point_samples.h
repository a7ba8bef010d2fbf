// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the VTP_geodesics package for CGAL (www.cgal.org).
//
// $URL$
// $Id$
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors


#ifndef CGAL_VTP_GEODESICS_FARTHEST_POINT_SAMPLES_H
#define CGAL_VTP_GEODESICS_FARTHEST_POINT_SAMPLES_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Propagation_statistics.h>

#include <cstddef>
#include <vector>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// The result of a farthest-point sampling (`Geodesic_distance_solver::farthest_point_sampling()`).
/// \tparam VertexDescriptor the vertex descriptor of the mesh.
template <class VertexDescriptor>
struct Farthest_point_samples
{
  /// the samples, in the order they were taken.
  std::vector<VertexDescriptor> samples;
  /// `radii[i]`: the covering radius once `samples[0..i]` are taken, i.e. the largest distance of a vertex to
  /// its nearest sample (`+infinity` while a connected component has no sample). Non-increasing.
  std::vector<double> radii;
  /// per vertex (indexed by `Geodesic_distance_solver::vertex_id()`): the distance to the nearest sample.
  std::vector<double> distances;
  /// per vertex: the index in `samples` of its nearest sample (the geodesic Voronoi cell of the vertex),
  /// `no_source` for a vertex that no sample reaches.
  std::vector<std::size_t> labels;
  /// the statistics of all the propagations, summed (the peaks are maxima; `max_distance` is the last
  /// covering radius, `reached_vertices` the vertices reached at the end).
  Propagation_statistics statistics;
};

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_FARTHEST_POINT_SAMPLES_H
