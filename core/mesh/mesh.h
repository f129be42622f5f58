#pragma once
// A triangle mesh as plain arrays: what the mesher produces and every
// consumer (viewer, exports, haptics' polygonal mode, thumbnails) reads.
// Floats, as GPUs and file formats want them; indices 32-bit.
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace fl::mesh {

using Vec3f = std::array<float, 3>;
using Triangle = std::array<std::uint32_t, 3>; // counter-clockwise seen from outside

struct Mesh {
    std::vector<Vec3f> positions;
    std::vector<Vec3f> normals;                // unit, outward; one per position
    std::vector<std::array<float, 4>> colours; // RGBA per position, or empty
    // Parametric geometry: each vertex's (u, v, w), which colour and texture
    // formulas read; empty for implicit and explicit geometry.
    std::vector<std::array<float, 3>> parameters;
    std::vector<Triangle> triangles;

    std::size_t vertexCount() const { return positions.size(); }
    std::size_t triangleCount() const { return triangles.size(); }
    bool empty() const { return triangles.empty(); }
};

} // namespace fl::mesh
