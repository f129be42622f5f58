#include "triangle_bvh.h"

#include <algorithm>
#include <cmath>

namespace fl::haptics {

using field::Vec3;

namespace {

field::Box3 boxOf(const Vec3& a, const Vec3& b, const Vec3& c) {
    field::Box3 box;
    for (std::size_t k = 0; k < 3; ++k) {
        box.lo[k] = std::min({a[k], b[k], c[k]});
        box.hi[k] = std::max({a[k], b[k], c[k]});
    }
    return box;
}

void grow(field::Box3& box, const field::Box3& o) {
    for (std::size_t k = 0; k < 3; ++k) {
        box.lo[k] = std::min(box.lo[k], o.lo[k]);
        box.hi[k] = std::max(box.hi[k], o.hi[k]);
    }
}

// Does the segment a + s d, s in [0, 1], touch the box? (slabs, inclusive)
bool touches(const field::Box3& box, const Vec3& a, const Vec3& d) {
    double lo = 0, hi = 1;
    for (std::size_t k = 0; k < 3; ++k) {
        if (d[k] == 0) {
            if (a[k] < box.lo[k] || a[k] > box.hi[k]) return false;
            continue;
        }
        double t0 = (box.lo[k] - a[k]) / d[k], t1 = (box.hi[k] - a[k]) / d[k];
        if (t0 > t1) std::swap(t0, t1);
        lo = std::max(lo, t0);
        hi = std::min(hi, t1);
        if (lo > hi) return false;
    }
    return true;
}

} // namespace

TriangleBvh::TriangleBvh(const mesh::Mesh& mesh) {
    if (mesh.primitive != mesh::Primitive::Triangles) return;
    triangles_.reserve(mesh.triangles.size());
    auto at = [&](std::uint32_t i) {
        const auto& p = mesh.positions[i];
        return Vec3{p[0], p[1], p[2]};
    };
    for (std::size_t i = 0; i < mesh.triangles.size(); ++i) {
        const auto& t = mesh.triangles[i];
        if (t[0] >= mesh.positions.size() || t[1] >= mesh.positions.size() ||
            t[2] >= mesh.positions.size())
            continue;
        triangles_.push_back({at(t[0]), at(t[1]), at(t[2]), std::uint32_t(i)});
    }
    if (triangles_.empty()) return;
    nodes_.reserve(2 * triangles_.size() / 4 + 1);
    build(0, std::uint32_t(triangles_.size()), 0);
}

std::uint32_t TriangleBvh::build(std::uint32_t first, std::uint32_t count, int depth) {
    const std::uint32_t index = std::uint32_t(nodes_.size());
    nodes_.push_back({});
    field::Box3 box = boxOf(triangles_[first].a, triangles_[first].b, triangles_[first].c);
    for (std::uint32_t i = first + 1; i < first + count; ++i)
        grow(box, boxOf(triangles_[i].a, triangles_[i].b, triangles_[i].c));
    nodes_[index].box = box;
    if (count <= 4 || depth > 40) {
        nodes_[index].first = first;
        nodes_[index].count = count;
        return index;
    }
    std::size_t axis = 0;
    for (std::size_t k = 1; k < 3; ++k)
        if (box.hi[k] - box.lo[k] > box.hi[axis] - box.lo[axis]) axis = k;
    const auto centre = [axis](const Tri& t) { return t.a[axis] + t.b[axis] + t.c[axis]; };
    const std::uint32_t half = count / 2;
    std::nth_element(triangles_.begin() + first, triangles_.begin() + first + half,
                     triangles_.begin() + first + count,
                     [&](const Tri& x, const Tri& y) { return centre(x) < centre(y); });
    const std::uint32_t left = build(first, half, depth + 1);
    const std::uint32_t right = build(first + half, count - half, depth + 1);
    nodes_[index].left = left;
    nodes_[index].right = right;
    return index;
}

template <class Visit>
void TriangleBvh::forEachNear(const Vec3& a, const Vec3& d, Visit visit) const {
    if (nodes_.empty()) return;
    std::uint32_t stack[96];
    int top = 0;
    stack[top++] = 0;
    while (top > 0) {
        const Node& n = nodes_[stack[--top]];
        if (!touches(n.box, a, d)) continue;
        if (n.count == 0) {
            if (top + 2 > 96) continue; // deeper than any tree of ours (depth <= 40)
            stack[top++] = n.left;
            stack[top++] = n.right;
            continue;
        }
        for (std::uint32_t i = n.first; i < n.first + n.count; ++i)
            visit(triangles_[i]);
    }
}

namespace {

// Möller–Trumbore, both sides: s along a + s d, or none.
template <class Tri>
std::optional<double> crossing(const Tri& t, const Vec3& a, const Vec3& d) {
    const Vec3 e1 = field::minus(t.b, t.a), e2 = field::minus(t.c, t.a);
    const Vec3 h = field::cross(d, e2);
    const double det = field::dot(e1, h);
    if (std::abs(det) < 1e-300) return std::nullopt;
    const Vec3 sv = field::minus(a, t.a);
    const double u = field::dot(sv, h) / det;
    if (!(u >= 0 && u <= 1)) return std::nullopt;
    const Vec3 q = field::cross(sv, e1);
    const double v = field::dot(d, q) / det;
    if (!(v >= 0 && u + v <= 1)) return std::nullopt;
    const double s = field::dot(e2, q) / det;
    if (!(s >= 0 && s <= 1)) return std::nullopt;
    return s;
}

} // namespace

std::optional<SegmentHit> TriangleBvh::firstHit(const Vec3& a, const Vec3& b, double skip) const {
    std::optional<SegmentHit> best;
    const Vec3 d = field::minus(b, a);
    forEachNear(a, d, [&](const Tri& t) {
        const auto s = crossing(t, a, d);
        if (!s || *s < skip || (best && *s >= best->s)) return;
        const Vec3 n3 = field::cross(field::minus(t.b, t.a), field::minus(t.c, t.a));
        const double len = field::length(n3);
        if (!(len > 0)) return;
        SegmentHit hit;
        hit.s = *s;
        hit.point = field::along(a, d, *s);
        hit.normal = field::scaled(n3, 1 / len);
        hit.frontFacing = field::dot(d, hit.normal) < 0;
        hit.triangle = t.index;
        best = hit;
    });
    return best;
}

bool TriangleBvh::contains(const Vec3& p) const {
    if (nodes_.empty() || !nodes_[0].box.contains(p)) return false;
    const Vec3 direction{0.5773, 0.5779, 0.5768};
    const Vec3 d = field::scaled(direction, 2 * nodes_[0].box.diagonal() + 1);
    std::size_t count = 0;
    forEachNear(p, d, [&](const Tri& t) { count += crossing(t, p, d).has_value(); });
    return count % 2 == 1;
}

} // namespace fl::haptics
