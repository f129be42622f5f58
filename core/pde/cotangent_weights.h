#pragma once
// The weights of the discrete Laplacian that the disk and annulus maps solve
// (disk_map.h, annulus_map.h): per undirected edge of a region, keyed
// smaller vertex id first, half the cotangent of each angle opposite it in
// the region's faces, summed in the faces' order. Not clamped: each map
// clamps them positive, which keeps its embedding free of fold-overs.
#include "mesh_regions.h"

#include <cstdint>
#include <map>
#include <utility>

namespace fl::pde {

using EdgeWeights = std::map<std::pair<std::uint32_t, std::uint32_t>, double>;

EdgeWeights cotangentWeights(const mesh::Mesh& mesh, const Faces& region);

} // namespace fl::pde
