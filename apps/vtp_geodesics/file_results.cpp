// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

// The results of the run in the file's terms (see file_results.h).

#include "file_results.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace vtp_geodesics_app {

File_results file_results(const Arguments& args, const vtp_support::Input_mesh& input, Request& request,
                          Run_result& result)
{
  File_results r;
  for(vtp_support::Vertex_index v : result.samples)
    r.samples.push_back(input.file_vertex_of(v));
  r.paths = std::move(request.paths);
  for(std::size_t k = 0; k < r.paths.size(); ++k)
    if(request.traced[k] >= 0)
      r.paths[k] = std::move(result.paths[static_cast<std::size_t>(request.traced[k])]);
  for(std::vector<std::array<double, 3> >& t : result.traces)  // --trace, after the paths
    r.paths.push_back(std::move(t));

  // Per vertex of the file; a file vertex at a source is at 0, labelled by the first source there.
  r.log_map = log_map_on_file_vertices(args, input, result);  // (before the distances are moved)
  if(!args.picture.empty() && !input.direct)
    r.mesh_distances = result.distances;
  if(args.signed_distance && !input.direct)
  {
    // signed (--signed) on a repaired mesh: each file vertex gets the value of its copy of the least absolute value
    // (the first such), and that copy's label
    std::vector<double> magnitude(result.distances.size());
    for(std::size_t i = 0; i < magnitude.size(); ++i)
      magnitude[i] = std::abs(result.distances[i]);
    if(request.run.want_labels)
      r.labels = input.labels_on_file_vertices(result.labels, magnitude, -1);
    r.distances.assign(input.file_vertices, std::numeric_limits<double>::infinity());
    for(std::size_t i = 0; i < input.file_vertices; ++i)
      for(vtp_support::Vertex_index c : input.mesh_vertices_of(i))
        if(magnitude[std::size_t(c)] < std::abs(r.distances[i]))
          r.distances[i] = result.distances[std::size_t(c)];
  }
  else
  {
    if(request.run.want_labels)
      r.labels = input.labels_on_file_vertices(result.labels, result.distances, -1);
    r.distances = input.on_file_vertices(std::move(result.distances));
  }
  for(std::size_t i = args.sources.size(); i-- > 0;)
  {
    r.distances[args.sources[i]] = 0.;
    if(request.run.want_labels)
      r.labels[args.sources[i]] = static_cast<int>(i);
  }
  for(std::size_t v : args.targets)
    r.target_distances.push_back(r.distances[v]);
  r.target_distances.insert(r.target_distances.end(), result.target_location_distances.begin(),
                            result.target_location_distances.end());
  for(double d : r.distances)
    if(std::isfinite(d))
    {
      ++r.reached_vertices;
      r.max_distance = (std::max)(r.max_distance, d);
    }

  if(args.check_cgal)
  {
    // Compared where the result is defined: within the distance limit, and (with targets) where it is final.
    std::vector<double> reference = input.on_file_vertices(std::move(result.reference));
    for(std::size_t v : args.sources)
      reference[v] = 0.;
    for(std::size_t i = 0; i < reference.size(); ++i)
      if(reference[i] > args.max_distance || (args.has_targets() && !std::isfinite(r.distances[i])))
        reference[i] = std::numeric_limits<double>::infinity();
    r.comparison = vtp_support::compare_distances(r.distances, reference);
    r.checked = true;
  }
  return r;
}

} // namespace vtp_geodesics_app
