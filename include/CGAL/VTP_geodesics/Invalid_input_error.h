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

#ifndef CGAL_VTP_GEODESICS_INVALID_INPUT_ERROR_H
#define CGAL_VTP_GEODESICS_INVALID_INPUT_ERROR_H

#include <CGAL/license/VTP_geodesics.h>

#include <stdexcept>
#include <string>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsRef
/// \brief exception thrown by the entry points of the package when the input cannot be processed:
/// a mesh that is not a triangle mesh, a source that is not a vertex or a point of the mesh,
/// non-finite coordinates, or invalid parameters.
///
/// The message is one line that says what is wrong.
class Invalid_input_error : public std::invalid_argument
{
public:
  explicit Invalid_input_error(const std::string& what)
    : std::invalid_argument(what)
  {}
};

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_INVALID_INPUT_ERROR_H
