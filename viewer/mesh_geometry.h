#pragma once
// A mesh as Qt3D geometry: one interleaved buffer of position, normal and
// RGBA colour per vertex, and a 32-bit index buffer (none for point clouds).
#include "mesh/mesh.h"

#include <Qt3DRender/QGeometryRenderer>

#include <array>

namespace fl::viewer {

// How a triangle mesh is drawn: its faces, its edges (wireframe) or its vertices.
enum class DrawAs { Faces, Edges, Vertices };

// `colour` fills in for a mesh without per-vertex colours. A point cloud is
// drawn as points whatever `as` says.
Qt3DRender::QGeometryRenderer* makeGeometryRenderer(const mesh::Mesh& mesh,
                                                    std::array<float, 4> colour,
                                                    Qt3DCore::QNode* parent = nullptr,
                                                    DrawAs as = DrawAs::Faces);

// The twelve edges of a box, as lines of one colour (unlit).
Qt3DRender::QGeometryRenderer* makeBoxOutline(const std::array<double, 3>& lo,
                                              const std::array<double, 3>& hi,
                                              std::array<float, 4> colour,
                                              Qt3DCore::QNode* parent = nullptr);

// Whether any vertex is see-through (drawn in the transparent pass).
bool hasTransparency(const mesh::Mesh& mesh, std::array<float, 4> colour);

} // namespace fl::viewer
