#pragma once
// A disk region of a mesh laid flat on the unit disk, then read in polar
// coordinates as a PDE cap's (u, v): u the radius (0 at the cap's pole, 1
// on the region's border), v the angle. The border goes round the circle
// by arc length, the inside by a harmonic map with positive (clamped
// cotangent) weights — a valid embedding by Tutte's theorem — and a Möbius
// map of the disk puts the vertex farthest inside the region at the pole.
#include "mesh_regions.h"

#include <complex>
#include <unordered_map>

namespace fl::pde {

struct DiskMap {
    std::unordered_map<std::uint32_t, std::complex<double>> at; // mesh vertex -> disk point
    std::vector<std::uint32_t> border;                          // the loop, as diskBoundary gave it
};

// Nullopt when the solve fails (it does not for a disk with positive weights).
std::optional<DiskMap> mapToDisk(const FaceGraph& graph, const Faces& region,
                                 const std::vector<std::uint32_t>& border);

// (u, v) of a disk point: u = |z| (at most 1), v = arg z in [0, 2π).
std::pair<double, double> polar(std::complex<double> z);

} // namespace fl::pde
