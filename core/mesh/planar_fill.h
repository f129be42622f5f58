#pragma once
// Triangles that fill the inside of closed 2D contours: glyph outlines of
// Text, the trimmed (u, v) region of a NURBS surface, non-convex polygons.
//
// A scanline decomposition, not ear clipping: the plane is cut into slabs at
// every vertex height (and where two edges cross), each slab's inside spans
// are found by the fill rule from the edges' winding, and each span — a
// trapezoid — is zipped between its bottom and top points. It takes any
// contours (holes, several outlines, self-intersections, touching vertices)
// without special cases, and the points on a slab line are shared by the
// slabs above and below it, so the result has no T-junctions: mapped onto a
// curved surface it stays closed.
#include "mesh.h"

#include <array>
#include <string>
#include <vector>

namespace fl::mesh {

using Point2 = std::array<double, 2>;
using Contour2 = std::vector<Point2>; // closed: the last point joins the first

enum class FillRule { EvenOdd, NonZero };

// Extra lines through the filled region, so its triangles are no larger
// than the cells between them (a NURBS surface needs points inside its
// trimmed region, not only on the trimming curves). Sorted or not.
struct FillGrid {
    std::vector<double> xs; // vertical lines x = c
    std::vector<double> ys; // horizontal lines y = c
};

struct PlanarFill {
    std::vector<Point2> points;
    std::vector<Triangle> triangles; // counter-clockwise with y up
    // Set when the contours would take more than the limits below (nothing
    // is filled then): hostile input must not hang or exhaust memory.
    std::string problem;
};

// Limits of one fill: edge pairs tested for crossings, and points made.
inline constexpr long long kMaxFillPairTests = 20'000'000;
inline constexpr std::size_t kMaxFillPoints = 8'000'000;

// Contours with fewer than three points are ignored, and so are points that
// are not finite or beyond 1e150 (where slopes would overflow).
PlanarFill fillContours(const std::vector<Contour2>& contours, FillRule rule,
                        const FillGrid& grid = {});

// Twice the signed area of a contour: positive when counter-clockwise.
double signedArea2(const Contour2& contour);

} // namespace fl::mesh
