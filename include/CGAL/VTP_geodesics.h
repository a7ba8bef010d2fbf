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

#ifndef CGAL_VTP_GEODESICS_H
#define CGAL_VTP_GEODESICS_H

#include <CGAL/license/VTP_geodesics.h>

#include <CGAL/VTP_geodesics/Invalid_input_error.h>
#include <CGAL/VTP_geodesics/Propagation_statistics.h>
#include <CGAL/VTP_geodesics/parameters.h>
#include <CGAL/VTP_geodesics/Geodesic_traits_3.h>
#include <CGAL/VTP_geodesics/Geodesic_distance_solver.h>
#include <CGAL/VTP_geodesics/Surface_polyline.h>
#include <CGAL/VTP_geodesics/Straightest_geodesic.h>
#include <CGAL/VTP_geodesics/Polar_patches.h>
#include <CGAL/VTP_geodesics/geodesic_distances.h>
#include <CGAL/VTP_geodesics/farthest_point_sampling.h>
#include <CGAL/VTP_geodesics/geodesic_voronoi_cells.h>
#include <CGAL/VTP_geodesics/geodesic_curves.h>

#endif // CGAL_VTP_GEODESICS_H
