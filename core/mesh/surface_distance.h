#pragma once
// How far one triangle mesh is from another: exact point-to-triangle
// distances (an AABB tree over the triangles), at area-weighted random
// samples on each surface plus every vertex. The figures PDE models,
// Draco and simplification are compared by (bench pde, pde fit --json):
// RMS and the symmetric Hausdorff distance, both ways.
#include "mesh.h"

#include <array>
#include <cstddef>
#include <vector>

namespace fl::mesh {

using Point3 = std::array<double, 3>;

class TriangleTree {
  public:
    explicit TriangleTree(const Mesh& mesh);
    // The squared distance from p to the nearest triangle (infinity for no triangles).
    double squaredDistance(const Point3& p) const;

  private:
    struct Node {
        Point3 lo, hi;
        std::uint32_t first, count; // leaf: triangles [first, first + count); else children
        std::uint32_t left = 0, right = 0;
    };
    std::uint32_t build(std::uint32_t first, std::uint32_t count);
    const Mesh& mesh_;
    std::vector<std::uint32_t> order_; // triangle indices, leaves contiguous
    std::vector<Point3> centroids_;
    std::vector<Node> nodes_;
};

// The squared distance from p to the triangle (a, b, c), exact for every
// shape of triangle, degenerate ones included.
double squaredDistanceToTriangle(const Point3& p, const Point3& a, const Point3& b,
                                 const Point3& c);

struct OneWayDistance {
    double rms = 0, max = 0; // in the meshes' units
    std::size_t samples = 0;
};
// `samples` area-weighted random points on `from` (a fixed seed: the same
// figures every run), each at its distance to `to`, make the RMS; every
// vertex of `from` counts towards the largest too.
OneWayDistance distanceFrom(const Mesh& from, const TriangleTree& to, std::size_t samples,
                            unsigned seed = 1);

// Each vertex of `from` at its distance to `to` (the import dialog colours
// a reconstruction by it).
std::vector<double> vertexDistances(const Mesh& from, const TriangleTree& to);

struct SurfaceDistance {
    double rms = 0;       // over the samples of both ways together
    double hausdorff = 0; // the larger of the two ways' largest
    std::size_t samples = 0;
};
SurfaceDistance compareSurfaces(const Mesh& a, const Mesh& b, std::size_t samplesEachWay);
// The same with `a`'s tree built by the caller (who measures many meshes
// against one: the import dialog's fits of one original).
SurfaceDistance compareSurfaces(const Mesh& a, const TriangleTree& aTree, const Mesh& b,
                                std::size_t samplesEachWay);

} // namespace fl::mesh
