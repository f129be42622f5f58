#pragma once
// A polygon mesh cut into regions a PDE cap can stand for: each region a
// topological disk (edge-connected faces, one boundary loop that visits no
// vertex twice, Euler characteristic 1). Regions are made by splitting:
// a region is cut in two by growing both halves from its two mutually far
// faces (Dijkstra over face adjacency), which keeps each half connected.
#include "mesh/mesh.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace fl::pde {

using Faces = std::vector<std::uint32_t>;

struct FaceGraph {
    const mesh::Mesh* mesh = nullptr;
    // The face across edge k (t[k] -> t[k+1]) of each triangle, or -1 at a border.
    std::vector<std::array<std::int32_t, 3>> across;
    std::vector<double> area;
    std::vector<std::array<double, 3>> centroid;
};

// Nullopt, with `why`, when an edge has more than two faces or two faces
// wind oppositely across an edge (lines from `triangleLines` when given).
// Triangles with a repeated vertex are left out of every region.
std::optional<FaceGraph> buildFaceGraph(const mesh::Mesh& mesh, std::string* why,
                                        const std::vector<std::uint32_t>* triangleLines = nullptr);

std::vector<Faces> connectedRegions(const FaceGraph& graph);

// The vertices of a region's faces, each once, in increasing order.
std::vector<std::uint32_t> verticesOf(const mesh::Mesh& mesh, const Faces& region);

// About `count` compact regions (at least one a connected part): seeds
// spread by farthest-point sampling over each part (as many as its share
// of the area), regions grown from them by Dijkstra, and `relaxations`
// Lloyd steps moving each seed to the face nearest its region's centre.
// The regions are not yet checked to be disks.
std::vector<Faces> partition(const FaceGraph& graph, std::size_t count, int relaxations = 4);

// The two halves of `region` (at least two faces).
std::array<Faces, 2> splitRegion(const FaceGraph& graph, const Faces& region);

// The region's boundary loop, in the direction its faces wind (the region
// on the left), when the region is a disk; nullopt otherwise.
std::optional<std::vector<std::uint32_t>> diskBoundary(const FaceGraph& graph, const Faces& region);

// The two boundary loops of `region` (each in the direction its faces wind)
// when the region is an annulus — a tube open at both ends: edge-connected,
// Euler characteristic 0, two loops that visit no vertex twice; nullopt
// otherwise.
std::optional<std::array<std::vector<std::uint32_t>, 2>> annulusBoundaries(const FaceGraph& graph,
                                                                           const Faces& region);

// A part of a mesh cut into `count` bands across its long axis (the
// principal axis of its vertices, along which they spread most): faces go
// by where their lowest corners lie along the axis. A closed part's first and last
// bands are its ends (caps); the bands between, and every band of a part
// open at both ends (an annulus), are tubes. A closed part's cuts fall at
// equal angles of a sphere round the axis (its ends are round, so its caps
// stay small), an open part's at equal steps. The bands are in order along
// the axis; they are not checked to be disks or annuli. The axis and each
// face's place along it are found once, for every count tried.
class Bands {
  public:
    Bands(const FaceGraph& graph, const Faces& part);
    // None when the part has no length along its axis.
    std::vector<Faces> cut(std::size_t count) const;

  private:
    Faces part_;
    std::vector<double> height_; // per face of part_: its lowest corner, 0..1 along the axis
    bool closed_ = false;
};

} // namespace fl::pde
