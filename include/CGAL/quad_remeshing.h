// Copyright (c) 2026 The CGAL Quad_remeshing authors.
// SPDX-License-Identifier: GPL-3.0-or-later
//
// Umbrella header of the CGAL Quad_remeshing package: includes every public header.

#ifndef CGAL_QUAD_REMESHING_H
#define CGAL_QUAD_REMESHING_H

#include <CGAL/Quad_remeshing/parameters.h>
#include <CGAL/Quad_remeshing/Report.h>
#include <CGAL/Quad_remeshing/IO.h>
#include <CGAL/Quad_remeshing/Patch_layout.h>
#include <CGAL/Quad_remeshing/assemble_quad_mesh.h>
#include <CGAL/Quad_remeshing/cross_field.h>
#include <CGAL/Quad_remeshing/detect_feature_edges.h>
#include <CGAL/Quad_remeshing/html_report.h>
#include <CGAL/Quad_remeshing/quad_mesh_quality.h>
#include <CGAL/Quad_remeshing/quad_remesh.h>
#include <CGAL/Quad_remeshing/quadrangulate_polygon.h>
#include <CGAL/Quad_remeshing/quantize_patch_sides.h>
#include <CGAL/Quad_remeshing/remesh_for_quadrangulation.h>
#include <CGAL/Quad_remeshing/smooth_quad_mesh.h>
#include <CGAL/Quad_remeshing/trace_patch_layout.h>

#endif // CGAL_QUAD_REMESHING_H
