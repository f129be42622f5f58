#pragma once
// NURBS curves and surfaces (X3D 19775-1, 27 NURBS component) evaluated and
// tessellated: NurbsCurve as line segments, NurbsPatchSurface as a grid of
// triangles with normals from the surface's own derivatives, and
// NurbsTrimmedSurface through its (u, v) trimming contours (planar_fill.h).
//
// Inputs are checked the way X3D asks: an order below 2 or above the number
// of control points, a knot vector of the wrong length or decreasing, or
// weights of the wrong count or not positive, fall back to the specified
// defaults (a uniform open knot vector, unit weights) with a warning.
#include "field_names.h"
#include "mesh.h"
#include "planar_fill.h"

#include <array>
#include <string>
#include <vector>

namespace fl::mesh {

// Orders above this are lowered (with a warning): evaluation costs order^2.
inline constexpr int kMaxNurbsOrder = 32;
// Tessellations above this many cells are coarsened (with a warning): a
// 200-byte file must not ask for 16 million triangles.
inline constexpr long long kMaxNurbsCells = 1LL << 20;

// One B-spline direction: order (degree + 1), knots, its control count.
struct NurbsBasis {
    int order = 3;
    std::vector<double> knots; // count + order values, non-decreasing
    int count = 0;

    double first() const { return knots[std::size_t(order - 1)]; }
    double last() const { return knots[std::size_t(count)]; }
};

// A valid basis from what a file gave; a warning (with `what`, "u", "v" or
// "") for anything replaced. Empty (count 0) when there are too few points.
NurbsBasis makeNurbsBasis(int order, int count, const std::vector<double>& knots,
                          const std::string& what, std::vector<std::string>& warnings);

// X3D tessellation hints: > 0 that many segments, < 0 that many per
// control point, 0 twice the control points; kept within [1, 4096].
int nurbsSegments(int tessellation, int controlPoints);
// Both directions scaled down together when their product exceeds kMaxNurbsCells.
void limitNurbsCells(int& uSegments, int& vSegments, std::vector<std::string>& warnings);

struct NurbsCurve {
    NurbsBasis basis;
    std::vector<Vec3> points;    // basis.count of them
    std::vector<double> weights; // one per point, all > 0
};

struct NurbsSurface {
    NurbsBasis u, v;
    std::vector<Vec3> points; // u.count * v.count, u fastest (X3D order)
    std::vector<double> weights;
};

// Weights from a file: one positive weight per point, or all ones (warned).
std::vector<double> nurbsWeights(const std::vector<double>& given, std::size_t points,
                                 std::vector<std::string>& warnings);

Vec3 evaluate(const NurbsCurve& curve, double t);
// The point and its partial derivatives along u and v.
struct SurfacePoint {
    Vec3 position, du, dv;
};
SurfacePoint evaluate(const NurbsSurface& surface, double u, double v);

// The curve as `segments` line segments over its parameter range.
Mesh nurbsCurveMesh(const NurbsCurve& curve, int segments);

// A 2D curve in (u, v), for trimming contours: its points along the range.
std::vector<Point2> nurbsCurve2DPoints(int order, const std::vector<Point2>& points,
                                       const std::vector<double>& weights,
                                       const std::vector<double>& knots, int segments,
                                       std::vector<std::string>& warnings);

// The surface over its parameter range as uSegments x vSegments cells, front
// faces along du x dv. `trim`: contours in (u, v) whose inside (even-odd)
// is kept, clipped to the parameter range; none keeps the whole patch.
// Where the range's edges meet (a closed direction's seam, a pole) their
// vertices are shared.
Mesh nurbsSurfaceMesh(const NurbsSurface& surface, int uSegments, int vSegments,
                      const std::vector<Contour2>& trim = {},
                      std::vector<std::string>* warnings = nullptr);

} // namespace fl::mesh
