#pragma once
// Writing meshes for other programs: binary STL, OBJ, binary PLY, glTF 2.0
// binary (.glb, with vertex colours) and plain X3D (an IndexedFaceSet any X3D
// viewer shows). The format follows the file name's extension.
#include "mesh.h"

#include <filesystem>
#include <optional>
#include <string>
#include <string_view>

namespace fl::mesh {

enum class MeshFormat { Stl, Obj, Ply, Glb, X3d };

std::optional<MeshFormat> meshFormatForPath(const std::filesystem::path& path);
std::string_view meshFormatName(MeshFormat format);
// The file's bytes.
std::string encodeMesh(const Mesh& mesh, MeshFormat format);
// False with `error` set when the file cannot be written.
bool writeMesh(const Mesh& mesh, const std::filesystem::path& path, std::string& error);

// `bytes` to `path`, written beside it first and then renamed over it: a
// failed write never leaves half a file where a good one was. Every file
// the meshers and `pde fit` write goes through here.
bool writeFileReplacing(const std::filesystem::path& path, std::string_view bytes,
                        std::string& error);

} // namespace fl::mesh
