#pragma once
// A mesh as Qt3D geometry: one interleaved buffer of position, normal and
// RGBA colour per vertex, and a 32-bit index buffer (none for point clouds).
#include "mesh/mesh.h"

#include <Qt3DRender/QGeometryRenderer>

#include <array>

namespace fl::viewer {

// `colour` fills in for a mesh without per-vertex colours.
Qt3DRender::QGeometryRenderer* makeGeometryRenderer(const mesh::Mesh& mesh,
                                                    std::array<float, 4> colour,
                                                    Qt3DCore::QNode* parent = nullptr);

// Whether any vertex is see-through (drawn in the transparent pass).
bool hasTransparency(const mesh::Mesh& mesh, std::array<float, 4> colour);

} // namespace fl::viewer
