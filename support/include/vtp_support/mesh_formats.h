// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_MESH_FORMATS_H
#define VTP_SUPPORT_MESH_FORMATS_H

// The mesh file formats the tools read, by file extension.

#include <cctype>
#include <filesystem>
#include <string>
#include <vector>

namespace vtp_support {

inline std::string lower_extension(const std::string& file)
{
  // not std::filesystem::path::extension(), which gives none for a name such as ".off"
  const std::string name = std::filesystem::path(file).filename().string();
  const std::string::size_type dot = name.find_last_of('.');
  if(dot == std::string::npos)
    return std::string();
  std::string ext = name.substr(dot + 1);
  for(char& c : ext)
    c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return ext;
}

// The file extensions `read_input_mesh()` reads: those of CGAL::IO::read_polygon_soup in CGAL 5.5 (VTP files
// need CGAL built with VTK, which Debian's is not).
inline const std::vector<std::string>& readable_extensions()
{
  static const std::vector<std::string> e = { "off", "obj", "ply", "stl", "ts" };
  return e;
}

// ".off, .obj, .ply, .stl or .ts"
inline std::string readable_extensions_text()
{
  std::string s;
  const std::vector<std::string>& e = readable_extensions();
  for(std::size_t i = 0; i < e.size(); ++i)
    s += (i == 0 ? "" : (i + 1 == e.size() ? " or " : ", ")) + ("." + e[i]);
  return s;
}

} // namespace vtp_support

#endif // VTP_SUPPORT_MESH_FORMATS_H
