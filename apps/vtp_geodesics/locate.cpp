// Copyright (c) 2026  VTP_geodesics contributors.
// All rights reserved.
//
// This file is part of the applications of the VTP_geodesics package (not installed with the library).
//
// SPDX-License-Identifier: GPL-3.0-or-later OR LicenseRef-Commercial
//
// Author(s) : VTP_geodesics contributors

#include "locate.h"
#include "arguments.h"

#include <vtp_support/number_format.h>

namespace vtp_geodesics_app {

Located_point Point_locator::locate(const std::array<double, 3>& p, const std::string& option) const
{
  Located_point r;
  if(!m_locator.locate(vtp_support::Point_3(p[0], p[1], p[2]), r.location))
    throw Tool_error("cannot locate the point " + vtp_support::double_to_string(p[0]) + ","
                     + vtp_support::double_to_string(p[1]) + "," + vtp_support::double_to_string(p[2]) + " of " + option
                     + " on the surface (its nearest face is degenerate)");
  r.point = m_locator.point_of(r.location);
  return r;
}

} // namespace vtp_geodesics_app
