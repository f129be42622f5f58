#pragma once
// Wavefront OBJ polygon meshes, as others write them (scanners, Blender,
// the Stanford repository): `v` positions and `f` faces (any of i, i/t,
// i//n, i/t/n, negative indices counting back), polygons split into fans;
// normals, texture coordinates, groups and materials are read past. Every
// mistake is located (NAME:LINE:COLUMN), the file's size is bounded before
// it is read, and each vertex and face remembers its line for messages
// about the mesh as a whole (a non-manifold edge, say).
#include "mesh.h"

#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::mesh {

inline constexpr std::size_t kMaxObjBytes = 256u << 20; // 256 MiB

struct ObjReadResult {
    std::optional<Mesh> mesh;                 // positions and triangles
    std::vector<std::uint32_t> vertexLines;   // the line of each position
    std::vector<std::uint32_t> triangleLines; // the line of the face each triangle came from
    std::string error;
    bool ok() const { return mesh.has_value(); }
};

ObjReadResult readObj(std::string_view bytes, std::string_view name);
ObjReadResult readObjFile(const std::string& path);

} // namespace fl::mesh
