// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#ifndef VTP_SUPPORT_PATHS_H
#define VTP_SUPPORT_PATHS_H

// Parts of file names, with std::filesystem (no access to the file system).

#include <filesystem>
#include <string>

namespace vtp_support {

// The folder of `path`, as dirname(1) gives it: "." for a bare name, "/" for a name in the root folder.
inline std::string folder_of(const std::string& path)
{
  const std::filesystem::path parent = std::filesystem::path(path).parent_path();
  return parent.empty() ? std::string(".") : parent.string();
}

// The last part of `path` (empty if `path` ends with '/').
inline std::string file_name_of(const std::string& path)
{
  return std::filesystem::path(path).filename().string();
}

} // namespace vtp_support

#endif // VTP_SUPPORT_PATHS_H
