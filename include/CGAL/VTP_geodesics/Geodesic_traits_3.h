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

#ifndef CGAL_VTP_GEODESICS_GEODESIC_TRAITS_3_H
#define CGAL_VTP_GEODESICS_GEODESIC_TRAITS_3_H

#include <CGAL/license/VTP_geodesics.h>

namespace CGAL {
namespace VTP_geodesics {

/// \ingroup PkgVTPGeodesicsTraitsClasses
/// \brief the default model of the concept `VTPGeodesicTraits_3`: any \cgal kernel.
///
/// The algorithm is intrinsic: it only needs the squared length of each edge and the squared area
/// of each face, which it converts to `double` with `CGAL::to_double()`. All arithmetic after that
/// is done in `double`.
///
/// \tparam K a \cgal kernel.
/// \cgalModels `VTPGeodesicTraits_3`
template <class K>
class Geodesic_traits_3 : public K
{
public:
  typedef K Kernel;
  typedef typename K::FT FT;
  typedef typename K::Point_3 Point_3;
  typedef typename K::Compute_squared_distance_3 Compute_squared_distance_3;
  typedef typename K::Compute_squared_area_3 Compute_squared_area_3;

  Geodesic_traits_3(const K& k = K()) : K(k) {}

  Compute_squared_distance_3 compute_squared_distance_3_object() const
  {
    return static_cast<const K&>(*this).compute_squared_distance_3_object();
  }

  Compute_squared_area_3 compute_squared_area_3_object() const
  {
    return static_cast<const K&>(*this).compute_squared_area_3_object();
  }
};

} // namespace VTP_geodesics
} // namespace CGAL

#endif // CGAL_VTP_GEODESICS_GEODESIC_TRAITS_3_H
