// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_SOUP_REPAIR_REPORT_H
#define VTP_SUPPORT_SOUP_REPAIR_REPORT_H

#include <cstddef>
#include <string>

namespace vtp_support {

// What `triangle_mesh_from_soup()` did to make a triangle mesh out of a polygon soup.
struct Soup_repair_report
{
  // true when the soup was not a valid polygon mesh and went through the repair
  bool repaired = false;
  // repair_polygon_soup(): coincident points merged, net number of faces removed (fewer than three
  // distinct points, or duplicates) or added (pinched faces split), points left in no face removed
  std::size_t merged_points = 0;
  std::size_t removed_faces = 0;
  std::size_t split_faces = 0;
  std::size_t removed_isolated_points = 0;
  // orient_polygon_soup(): faces reversed, non-manifold edges cut, vertices duplicated (and copies added)
  std::size_t reversed_faces = 0;
  std::size_t non_manifold_edges = 0;
  std::size_t duplicated_vertices = 0;
  std::size_t vertex_copies = 0;
  // triangulate_faces(): faces with more than three vertices, split into triangles
  std::size_t triangulated_faces = 0;

  // "triangulated 12 faces; duplicated 3 non-manifold vertices", or an empty string if nothing was done.
  std::string summary() const
  {
    std::string s;
    auto add = [&s](std::size_t n, const std::string& verb, const char* singular, const char* plural) {
      if(n == 0)
        return;
      if(!s.empty())
        s += "; ";
      s += verb + " " + std::to_string(n) + " " + (n == 1 ? singular : plural);
    };
    add(merged_points, "merged", "duplicate point", "duplicate points");
    add(removed_faces, "removed", "degenerate or duplicate face", "degenerate or duplicate faces");
    add(split_faces, "split", "pinched face", "pinched faces");
    add(removed_isolated_points, "removed", "isolated point", "isolated points");
    add(reversed_faces, "reoriented", "face", "faces");
    add(non_manifold_edges, "cut", "non-manifold edge", "non-manifold edges");
    add(duplicated_vertices, "duplicated", "non-manifold vertex", "non-manifold vertices");
    if(vertex_copies > duplicated_vertices)
      s += " (" + std::to_string(vertex_copies) + " copies)";
    add(triangulated_faces, "triangulated", "face", "faces");
    return s;
  }
};

} // namespace vtp_support

#endif // VTP_SUPPORT_SOUP_REPAIR_REPORT_H
