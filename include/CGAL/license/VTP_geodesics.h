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
//
// Warning: this file follows CGAL's generated license headers (include/CGAL/license/README.md).


#ifndef CGAL_LICENSE_VTP_GEODESICS_H
#define CGAL_LICENSE_VTP_GEODESICS_H

#include <CGAL/config.h>
#include <CGAL/license.h>




#ifdef CGAL_VTP_GEODESICS_COMMERCIAL_LICENSE

#  if CGAL_VTP_GEODESICS_COMMERCIAL_LICENSE < CGAL_RELEASE_DATE

#    if defined(CGAL_LICENSE_WARNING)

       CGAL_pragma_warning("Your commercial license for CGAL does not cover "
                           "this release of the VTP Geodesics package.")
#    endif

#    ifdef CGAL_LICENSE_ERROR
#      error "Your commercial license for CGAL does not cover this release \
of the VTP Geodesics package. \
You get this error, as you defined CGAL_LICENSE_ERROR."
#    endif // CGAL_LICENSE_ERROR

#  endif // CGAL_VTP_GEODESICS_COMMERCIAL_LICENSE < CGAL_RELEASE_DATE

#else // no CGAL_VTP_GEODESICS_COMMERCIAL_LICENSE

#  if defined(CGAL_LICENSE_WARNING)
     CGAL_pragma_warning("\nThe macro CGAL_VTP_GEODESICS_COMMERCIAL_LICENSE is not defined."
                          "\nYou use the CGAL VTP Geodesics package under "
                          "the terms of the GPLv3+.")
#  endif // CGAL_LICENSE_WARNING

#  ifdef CGAL_LICENSE_ERROR
#    error "The macro CGAL_VTP_GEODESICS_COMMERCIAL_LICENSE is not defined.\
 You use the CGAL VTP Geodesics package under the terms of \
the GPLv3+. You get this error, as you defined CGAL_LICENSE_ERROR."
#  endif // CGAL_LICENSE_ERROR

#endif // no CGAL_VTP_GEODESICS_COMMERCIAL_LICENSE

#endif // CGAL_LICENSE_VTP_GEODESICS_H
