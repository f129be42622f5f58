#pragma once
// A triangle mesh (or a point cloud) as plain arrays: what the mesher produces and every
// consumer (viewer, exports, haptics' polygonal mode, thumbnails) reads.
// Floats, as GPUs and file formats want them; indices 32-bit.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl::mesh {

using Vec3f = std::array<float, 3>;
using Triangle = std::array<std::uint32_t, 3>; // counter-clockwise seen from outside

// What the positions make: triangles, a cloud of points, or line segments
// (IndexedLineSet, LineSet: in `segments`, drawn unlit).
enum class Primitive : std::uint8_t { Triangles, Points, Lines };
using Segment = std::array<std::uint32_t, 2>;

struct Mesh {
    Primitive primitive = Primitive::Triangles;
    std::vector<Vec3f> positions;
    // Unit and outward, one per position; for points inside a solid or along
    // a curve, which have no surface, zero (drawn unlit).
    std::vector<Vec3f> normals;
    std::vector<std::array<float, 4>> colours; // RGBA per position, or empty
    // Parametric geometry: each vertex's (u, v, w), which colour and texture
    // formulas read; empty for implicit and explicit geometry.
    std::vector<std::array<float, 3>> parameters;
    // Image texture coordinates (s, t) per position, or empty: standard
    // geometry by X3D's default mappings or its TextureCoordinate, NURBS by (u, v).
    std::vector<std::array<float, 2>> texCoords;
    std::vector<Triangle> triangles;
    std::vector<Segment> segments; // Primitive::Lines only

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return triangles.size(); }
    bool isPointCloud() const { return primitive == Primitive::Points; }
    bool isLines() const { return primitive == Primitive::Lines; }
    bool empty() const {
        return isPointCloud() ? positions.empty()
               : isLines()    ? segments.empty()
                              : triangles.empty();
    }
};

} // namespace fl::mesh
