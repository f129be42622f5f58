#pragma once
// Triangles the viewer draws, in a bounding-volume hierarchy (boxes split at
// the median of the longest axis, a few triangles per leaf), for the haptic
// god-object: "where does this segment first cross the surface?" in about
// log(n) box tests instead of n triangle tests.
#include "field/box3.h"
#include "mesh/mesh.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace fl::haptics {

struct SegmentHit {
    double s = 0; // along the segment: a + s (b - a), s in [0, 1]
    field::Vec3 point{};
    field::Vec3 normal{};     // the triangle's unit normal, as wound (outward on a closed mesh)
    bool frontFacing = false; // the segment runs against the normal (enters)
    std::uint32_t triangle = 0;
};

class TriangleBvh {
  public:
    explicit TriangleBvh(const mesh::Mesh& mesh);

    // The first crossing of the segment a -> b with a triangle (both sides),
    // ignoring hits closer to `a` than `skip` (s units).
    std::optional<SegmentHit> firstHit(const field::Vec3& a, const field::Vec3& b,
                                       double skip = 0) const;
    // Whether p is inside the closed surface: an odd number of crossings on a
    // ray from p out of the bounds (a skewed direction, so edges are rare).
    bool contains(const field::Vec3& p) const;
    std::size_t triangleCount() const { return triangles_.size(); }
    const field::Box3& bounds() const { return nodes_.empty() ? empty_ : nodes_[0].box; }

  private:
    struct Node {
        field::Box3 box;
        std::uint32_t first = 0, count = 0; // a leaf: triangles [first, first + count)
        std::uint32_t left = 0, right = 0;  // an inner node (count == 0)
    };
    struct Tri {
        field::Vec3 a, b, c;
        std::uint32_t index;
    };
    std::uint32_t build(std::uint32_t first, std::uint32_t count, int depth);
    // Visits the triangles whose boxes the segment a + s d (s in [0, 1]) touches.
    template <class Visit>
    void forEachNear(const field::Vec3& a, const field::Vec3& d, Visit visit) const;

    std::vector<Tri> triangles_;
    std::vector<Node> nodes_;
    field::Box3 empty_{{0, 0, 0}, {0, 0, 0}};
};

} // namespace fl::haptics
