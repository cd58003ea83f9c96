// A software rasterizer for the CPU pipeline's clipped polygons: an independent oracle for what the
// GLSL path (OpenGL, Mesa's llvmpipe) draws for the same scene. It follows GL's rules as Mesa applies
// them, translated into DC (docs/conventions.md, stage 5 and "The GLSL path with the same matrices"):
//
// - Coverage: a pixel (x, y) is covered when its centre (x + 0.5, y + 0.5) lies inside the polygon.
//   Convex polygons are fan-triangulated from their first vertex (as mesh.h's triangulated()), and
//   each triangle is tested with edge functions in double precision.
// - Centres exactly on an edge: gallium rasterizes GL with the "top-left" rule measured from GL's
//   window origin, which is bottom-left with y up (gallium's rasterizer.rst, bottom_edge_rule; Mesa's
//   st_atom_rasterizer.c sets it so that window buffers and FBOs agree). GL's window y is
//   y_w = H − y_dc, so in DC (y down) that rule is BOTTOM-left: a centre on a left edge (the
//   polygon lies to its right) or on a horizontal bottom edge (the polygon lies above it, at smaller
//   y_dc) is covered; one on a right or top edge is not. Two triangles sharing an edge therefore
//   cover each centre on it exactly once. (Checked against llvmpipe: the GL-window square
//   [0.5, 3.5]² covers GL rows 0..2 and columns 0..2.)
// - Depth: z_dc (1 at the front plane, 0 at the back) is affine in screen space after the division,
//   like GL's window depth 1 − z_npc, so it is interpolated linearly over the triangle. The nearer
//   fragment wins; GL_LESS on 1 − z with the depth buffer cleared to 1 means "z_dc strictly larger
//   than what is stored, which starts at 0": the first polygon drawn keeps a tie, and a polygon
//   lying exactly on the back plane is not drawn (as in GL).
// - Colour: each object's flat colour, converted to bytes as llvmpipe converts a float colour to an
//   8-bit unorm channel (unorm8 below).
// - No culling: polygons facing either way are filled. Degenerate ones (zero area, fewer than three
//   vertices, non-finite positions) are skipped.
//
// Known differences from llvmpipe that a comparison has to tolerate: llvmpipe computes the vertex
// transform in float and snaps vertices to 1/256 pixel (subpixelBits below imitates the snapping),
// so centres within about 1/256 pixel of an edge may go either way; its depth buffer has 24 bits
// and its depth interpolation is in float, so near-equal depths (where polygons cross) may resolve
// differently. Concave faces differ by construction: GL fans the unclipped face, this fans the
// clipped one, and fans of a concave polygon from different vertices cover different areas.
#pragma once

#include <cstdint>

#include "app/views/image.h"
#include "pipeline/pipeline.h"

namespace vplab {

/// A 0..1 colour channel as an 8-bit unorm value, as OpenGL converts a float colour: round(c · 255)
/// after clamping to [0, 1] (NaN gives 0). Computed as llvmpipe does, in float with the "magic
/// number" trick (c · 255/256 + 2^15, keep the low 8 bits), so values within float precision of a
/// tie round to even: 0.3 → 76 (76.5), 0.7 → 178, 0.9 → 230, 0.5 → 128. Checked against llvmpipe for
/// glClearColor and for a fragment shader's output on 300 000 values.
uint8_t unorm8(double c);

/// An opaque RGBA8 colour from a 0..1 colour, channel by channel as unorm8.
Rgba rgbaFromColor(const Vec3& color);

/// Fills every CPU-clipped polygon of every object of the run (ObjectRun::clippedFace, vertices at
/// ObjectRun::clippedDc) with the object's flat colour on a width × height image cleared to
/// `background` (0..1), with a depth buffer: the rules above. DC positions are used as pixel
/// positions as they are, so width × height is normally run.device's size; parts outside the image
/// are cut off.
///
/// subpixelBits > 0 first rounds each vertex's x and y to multiples of 1 / 2^subpixelBits pixel,
/// as a GL implementation with GL_SUBPIXEL_BITS = subpixelBits does (llvmpipe: 8). The default, 0,
/// rasterizes the exact DC positions. Against llvmpipe, 8 removed most of the silhouette
/// differences in random scenes (from 23 to 4 pixels in 60 scenes of 320 × 240).
Image rasterizeClippedPolygons(const PipelineRun& run, const Vec3& background, int width, int height,
                               int subpixelBits = 0);

}  // namespace vplab
