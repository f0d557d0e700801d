// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Umbrella header of the CGAL Quad_remeshing package: includes every public header.

#ifndef CGAL_QUAD_REMESHING_H
#define CGAL_QUAD_REMESHING_H

#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/IO.h>
#include <CGAL/Quad_remeshing/assemble_quad_mesh.h>
#include <CGAL/Quad_remeshing/html_report.h>
#include <CGAL/Quad_remeshing/quad_mesh_quality.h>
#include <CGAL/Quad_remeshing/smooth_quad_mesh.h>

#endif // CGAL_QUAD_REMESHING_H
