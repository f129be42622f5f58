#include "standard_geometry.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <optional>
#include <unordered_map>

namespace fl::mesh {
namespace {

Vec3f toFloat(const Vec3& v) {
    return {float(v[0]), float(v[1]), float(v[2])};
}

// X3D 13.3.6 (Sphere), 13.3.2/3 (Cone, Cylinder sides): the image wraps
// counter-clockwise seen from above, starting (s = 0) at the back (-z); one
// more column of vertices than segments carries the seam's s = 1.
double wrapAngle(int column, int segments) {
    // The seam column repeats column 0 exactly, so welding by position closes it.
    return std::numbers::pi + 2 * std::numbers::pi * (column % segments) / segments;
}

struct Builder {
    Mesh mesh;
    std::uint32_t vertex(const Vec3& p, const Vec3& n, std::array<double, 2> st) {
        mesh.positions.push_back(toFloat(p));
        mesh.normals.push_back(toFloat(n));
        mesh.texCoords.push_back({float(st[0]), float(st[1])});
        return std::uint32_t(mesh.positions.size() - 1);
    }
    void triangle(std::uint32_t a, std::uint32_t b, std::uint32_t c) {
        mesh.triangles.push_back({a, b, c});
    }
    void quad(std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        triangle(a, b, c);
        triangle(a, c, d);
    }
    // A flat disc at height y facing up (+y) or down, `segments` around.
    // X3D textures a top cap as seen from above with -z up, a bottom cap as
    // seen from below with +z up.
    void disc(double radius, double y, bool up, int segments) {
        const Vec3 n{0, up ? 1.0 : -1.0, 0};
        const std::uint32_t centre = vertex({0, y, 0}, n, {0.5, 0.5});
        const std::uint32_t first = std::uint32_t(mesh.positions.size());
        for (int i = 0; i < segments; ++i) {
            const double a = wrapAngle(i, segments); // the sides' angles: rims weld exactly
            const double x = std::sin(a), z = std::cos(a);
            vertex({radius * x, y, radius * z}, n, {0.5 + x / 2, 0.5 + (up ? -z : z) / 2});
        }
        for (int i = 0; i < segments; ++i) {
            const std::uint32_t p = first + std::uint32_t(i),
                                q = first + std::uint32_t((i + 1) % segments);
            // Angles run counter-clockwise seen from +y: (sin a, cos a) turns from +z to +x.
            if (up)
                triangle(centre, p, q);
            else
                triangle(centre, q, p);
        }
    }
};

// X3D 13.3.1: each face shows the image upright as seen from outside with
// +y up; the top with -z up, the bottom with +z up.
std::array<double, 2> boxTexCoord(const Vec3& p, int axis, int side, const Vec3& half) {
    // The face's right and up directions as (axis, sign).
    int right = 0, rightSign = 1, up = 1, upSign = 1;
    if (axis == 2)
        right = 0, rightSign = side; // front +x, back -x
    else if (axis == 0)
        right = 2, rightSign = -side; // right face -z, left face +z
    else
        right = 0, rightSign = 1, up = 2, upSign = -side; // top -z up, bottom +z up
    auto along = [&](int k, int sign) {
        const double h = half[std::size_t(k)];
        return h > 0 ? 0.5 + sign * p[std::size_t(k)] / (2 * h) : 0.5;
    };
    return {along(right, rightSign), along(up, upSign)};
}

} // namespace

Mesh boxMesh(std::array<double, 3> size) {
    Builder b;
    const Vec3 h{size[0] / 2, size[1] / 2, size[2] / 2};
    for (int axis = 0; axis < 3; ++axis)
        for (int side : {-1, 1}) {
            const int u = (axis + 1) % 3, v = (axis + 2) % 3;
            Vec3 n{0, 0, 0};
            n[std::size_t(axis)] = side;
            std::uint32_t corner[4];
            static const int uv[4][2] = {{-1, -1}, {1, -1}, {1, 1}, {-1, 1}};
            for (int c = 0; c < 4; ++c) {
                Vec3 p{};
                p[std::size_t(axis)] = side * h[std::size_t(axis)];
                p[std::size_t(u)] = uv[c][0] * h[std::size_t(u)];
                p[std::size_t(v)] = uv[c][1] * h[std::size_t(v)];
                corner[c] = b.vertex(p, n, boxTexCoord(p, axis, side, h));
            }
            // u x v = axis: counter-clockwise from outside on the + side.
            if (side > 0)
                b.quad(corner[0], corner[1], corner[2], corner[3]);
            else
                b.quad(corner[0], corner[3], corner[2], corner[1]);
        }
    return b.mesh;
}

Mesh sphereMesh(double radius, int segments) {
    segments = std::max(3, segments);
    const int rings = std::max(2, segments / 2);
    Builder b;
    // A pole vertex per column, at the middle of its s range.
    for (int s = 0; s < segments; ++s)
        b.vertex({0, radius, 0}, {0, 1, 0}, {(s + 0.5) / segments, 1});
    for (int r = 1; r < rings; ++r) {
        const double polar = std::numbers::pi * r / rings;
        for (int s = 0; s <= segments; ++s) {
            const double a = wrapAngle(s, segments);
            const Vec3 n{std::sin(polar) * std::sin(a), std::cos(polar),
                         std::sin(polar) * std::cos(a)};
            b.vertex({radius * n[0], radius * n[1], radius * n[2]}, n,
                     {double(s) / segments, 1 - double(r) / rings});
        }
    }
    const std::uint32_t bottom = std::uint32_t(b.mesh.positions.size());
    for (int s = 0; s < segments; ++s)
        b.vertex({0, -radius, 0}, {0, -1, 0}, {(s + 0.5) / segments, 0});
    auto at = [&](int ring, int s) { // ring 1 .. rings-1, s 0 .. segments
        return std::uint32_t(segments + (ring - 1) * (segments + 1) + s);
    };
    for (int s = 0; s < segments; ++s) {
        b.triangle(std::uint32_t(s), at(1, s), at(1, s + 1));
        b.triangle(bottom + std::uint32_t(s), at(rings - 1, s + 1), at(rings - 1, s));
        for (int r = 1; r + 1 < rings; ++r)
            b.quad(at(r, s), at(r + 1, s), at(r + 1, s + 1), at(r, s + 1));
    }
    return b.mesh;
}

Mesh coneMesh(double bottomRadius, double height, bool side, bool bottom, int segments) {
    segments = std::max(3, segments);
    Builder b;
    const double y0 = -height / 2, y1 = height / 2;
    if (side) {
        // One apex vertex per segment, with the normal of the middle of its
        // face: the apex has no single normal.
        const std::uint32_t first = std::uint32_t(b.mesh.positions.size());
        for (int s = 0; s <= segments; ++s) {
            const double a = wrapAngle(s, segments);
            const Vec3 n = field::unitOr({height * std::sin(a), bottomRadius, height * std::cos(a)},
                                         {0, 1, 0});
            b.vertex({bottomRadius * std::sin(a), y0, bottomRadius * std::cos(a)}, n,
                     {double(s) / segments, 0});
        }
        for (int s = 0; s < segments; ++s) {
            const double a = wrapAngle(s, segments) + std::numbers::pi / segments;
            const Vec3 n = field::unitOr({height * std::sin(a), bottomRadius, height * std::cos(a)},
                                         {0, 1, 0});
            const std::uint32_t apex = b.vertex({0, y1, 0}, n, {(s + 0.5) / segments, 1});
            b.triangle(apex, first + std::uint32_t(s), first + std::uint32_t(s + 1));
        }
    }
    if (bottom) b.disc(bottomRadius, y0, false, segments);
    return b.mesh;
}

Mesh cylinderMesh(double radius, double height, bool side, bool top, bool bottom, int segments) {
    segments = std::max(3, segments);
    Builder b;
    const double y0 = -height / 2, y1 = height / 2;
    if (side) {
        const std::uint32_t first = std::uint32_t(b.mesh.positions.size());
        for (int s = 0; s <= segments; ++s) {
            const double a = wrapAngle(s, segments);
            const Vec3 n{std::sin(a), 0, std::cos(a)};
            b.vertex({radius * n[0], y0, radius * n[2]}, n, {double(s) / segments, 0});
            b.vertex({radius * n[0], y1, radius * n[2]}, n, {double(s) / segments, 1});
        }
        for (int s = 0; s < segments; ++s) {
            const std::uint32_t lo0 = first + std::uint32_t(2 * s), hi0 = lo0 + 1;
            const std::uint32_t lo1 = first + std::uint32_t(2 * (s + 1)), hi1 = lo1 + 1;
            b.quad(lo0, lo1, hi1, hi0);
        }
    }
    if (top) b.disc(radius, y1, true, segments);
    if (bottom) b.disc(radius, y0, false, segments);
    return b.mesh;
}

FaceSetResult faceSetMesh(const FaceSet& f) {
    FaceSetResult out;
    Mesh& m = out.mesh;
    bool badIndex = false, degenerate = false;
    // Polygons as runs of coordIndex.
    struct Polygon {
        std::size_t first, count; // into coordIndex
    };
    std::vector<Polygon> polygons;
    for (std::size_t i = 0, start = 0; i <= f.coordIndex.size(); ++i) {
        if (i == f.coordIndex.size() || f.coordIndex[i] < 0) {
            if (i > start) polygons.push_back({start, i - start});
            start = i + 1;
        }
    }
    auto point = [&](std::int64_t index) -> const Vec3* {
        if (index < 0 || std::size_t(index) >= f.points.size()) return nullptr;
        return &f.points[std::size_t(index)];
    };
    // Newell's normal of each polygon (robust for non-planar ones), as
    // written (before ccw is applied).
    std::vector<Vec3> faceNormal(polygons.size());
    std::vector<bool> usable(polygons.size(), true);
    for (std::size_t p = 0; p < polygons.size(); ++p) {
        const Polygon& poly = polygons[p];
        Vec3 n{0, 0, 0};
        for (std::size_t k = 0; k < poly.count; ++k) {
            const Vec3* a = point(f.coordIndex[poly.first + k]);
            const Vec3* c = point(f.coordIndex[poly.first + (k + 1) % poly.count]);
            if (!a || !c) {
                usable[p] = false;
                badIndex = true;
                break;
            }
            n[0] += ((*a)[1] - (*c)[1]) * ((*a)[2] + (*c)[2]);
            n[1] += ((*a)[2] - (*c)[2]) * ((*a)[0] + (*c)[0]);
            n[2] += ((*a)[0] - (*c)[0]) * ((*a)[1] + (*c)[1]);
        }
        if (usable[p] && poly.count < 3) {
            usable[p] = false;
            degenerate = true;
        }
        const double sign = f.ccw ? 1.0 : -1.0;
        faceNormal[p] = field::unitOr({sign * n[0], sign * n[1], sign * n[2]}, {0, 0, 0});
    }
    // Smooth normals: the faces around each point, for the crease test.
    std::unordered_map<std::int64_t, std::vector<std::size_t>> facesAt;
    const bool smooth = f.normals.empty() && f.creaseAngle > 0;
    if (smooth)
        for (std::size_t p = 0; p < polygons.size(); ++p)
            if (usable[p])
                for (std::size_t k = 0; k < polygons[p].count; ++k)
                    facesAt[f.coordIndex[polygons[p].first + k]].push_back(p);
    const double cosCrease = std::cos(std::min(f.creaseAngle, std::numbers::pi));

    // X3D's rule for colours and normals alike: per vertex through their own
    // index (parallel to coordIndex) or else coordIndex; per face through
    // their index or else the face's number. -1 when an index is missing.
    auto attributeIndex = [&](bool perVertex, const std::vector<std::int64_t>& own,
                              std::size_t face, std::size_t corner) -> std::int64_t {
        const std::size_t at = perVertex ? corner : face;
        if (!own.empty()) return at < own.size() ? own[at] : -1;
        return perVertex ? f.coordIndex[corner] : std::int64_t(face);
    };
    auto colourAt = [&](std::size_t p, std::size_t corner) -> const std::array<float, 4>* {
        if (f.colours.empty()) return nullptr;
        const std::int64_t index = attributeIndex(f.colourPerVertex, f.colourIndex, p, corner);
        if (index < 0 || std::size_t(index) >= f.colours.size()) {
            badIndex = true;
            return nullptr;
        }
        return &f.colours[std::size_t(index)];
    };
    auto givenNormal = [&](std::size_t p, std::size_t corner) -> std::optional<Vec3> {
        if (f.normals.empty()) return std::nullopt;
        const std::int64_t index = attributeIndex(f.normalPerVertex, f.normalIndex, p, corner);
        if (index < 0 || std::size_t(index) >= f.normals.size()) {
            badIndex = true;
            return std::nullopt;
        }
        const Vec3& n = f.normals[std::size_t(index)];
        const double sign = f.ccw ? 1.0 : -1.0;
        return field::unitOr({sign * n[0], sign * n[1], sign * n[2]}, faceNormal[p]);
    };
    // Texture coordinates: given, or X3D's default from the bounding box.
    std::size_t sAxis = 0, tAxis = 1;
    Vec3 lo{0, 0, 0};
    double side = 1;
    if (f.texCoords.empty() && !f.points.empty()) {
        Vec3 hi = f.points[0];
        lo = hi;
        for (const Vec3& p : f.points)
            for (std::size_t k = 0; k < 3; ++k) {
                lo[k] = std::min(lo[k], p[k]);
                hi[k] = std::max(hi[k], p[k]);
            }
        std::array<std::size_t, 3> order{0, 1, 2}; // longest first; x before y before z on ties
        std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) {
            return hi[a] - lo[a] > hi[b] - lo[b];
        });
        sAxis = order[0];
        tAxis = order[1];
        side = hi[sAxis] - lo[sAxis];
        if (!(side > 0) || !std::isfinite(side)) side = 1;
    }
    auto texCoordAt = [&](std::size_t corner) -> std::array<float, 2> {
        if (f.texCoords.empty()) {
            const Vec3& p = *point(f.coordIndex[corner]);
            return {float((p[sAxis] - lo[sAxis]) / side), float((p[tAxis] - lo[tAxis]) / side)};
        }
        const std::int64_t index =
            f.texCoordIndex.empty()
                ? f.coordIndex[corner]
                : (corner < f.texCoordIndex.size() ? f.texCoordIndex[corner] : -1);
        if (index < 0 || std::size_t(index) >= f.texCoords.size()) {
            badIndex = true;
            return {0, 0};
        }
        const auto& st = f.texCoords[std::size_t(index)];
        return {float(st[0]), float(st[1])};
    };
    const bool anyColour = !f.colours.empty();
    for (std::size_t p = 0; p < polygons.size(); ++p) {
        if (!usable[p]) continue;
        const Polygon& poly = polygons[p];
        const std::uint32_t base = std::uint32_t(m.positions.size());
        for (std::size_t k = 0; k < poly.count; ++k) {
            const std::size_t corner = poly.first + k;
            const std::int64_t index = f.coordIndex[corner];
            m.positions.push_back(toFloat(*point(index)));
            Vec3 n = faceNormal[p];
            if (auto given = givenNormal(p, corner)) {
                n = *given;
            } else if (smooth) {
                Vec3 sum{0, 0, 0};
                for (std::size_t q : facesAt[index]) {
                    const Vec3& fq = faceNormal[q];
                    const double c = fq[0] * faceNormal[p][0] + fq[1] * faceNormal[p][1] +
                                     fq[2] * faceNormal[p][2];
                    if (q == p || c >= cosCrease)
                        for (std::size_t a = 0; a < 3; ++a)
                            sum[a] += fq[a];
                }
                n = field::unitOr(sum, faceNormal[p]);
            }
            m.normals.push_back(toFloat(n));
            m.texCoords.push_back(texCoordAt(corner));
            if (anyColour) {
                const auto* c = colourAt(p, corner);
                m.colours.push_back(c ? *c : std::array<float, 4>{0.8f, 0.8f, 0.8f, 1.0f});
            }
        }
        // A fan from the first corner, turned round when the file is clockwise.
        for (std::size_t k = 1; k + 1 < poly.count; ++k) {
            const std::uint32_t a = base, b = base + std::uint32_t(k),
                                c = base + std::uint32_t(k + 1);
            if (f.ccw)
                m.triangles.push_back({a, b, c});
            else
                m.triangles.push_back({a, c, b});
        }
    }
    if (badIndex)
        out.warnings.push_back("an index points past the end of its list (coord, color, normal "
                               "or texCoord); the polygons that use it are left out or shown grey");
    if (degenerate)
        out.warnings.push_back("a polygon has fewer than three vertices and is left out");
    return out;
}

FaceSetResult lineSetMesh(const FaceSet& f) {
    FaceSetResult out;
    Mesh& m = out.mesh;
    m.primitive = Primitive::Lines;
    bool bad = false;
    std::size_t polyline = 0;
    std::int64_t previous = -1;
    std::uint32_t previousVertex = 0;
    for (std::size_t corner = 0; corner < f.coordIndex.size(); ++corner) {
        const std::int64_t index = f.coordIndex[corner];
        if (index < 0) { // the end of a polyline
            ++polyline;
            previous = -1;
            continue;
        }
        if (std::size_t(index) >= f.points.size()) {
            bad = true;
            previous = -1;
            continue;
        }
        const auto& p = f.points[std::size_t(index)];
        m.positions.push_back({float(p[0]), float(p[1]), float(p[2])});
        m.normals.push_back({0, 0, 0});
        if (!f.colours.empty()) {
            const std::size_t at = f.colourPerVertex ? corner : polyline;
            std::int64_t c = f.colourIndex.empty()
                                 ? (f.colourPerVertex ? index : std::int64_t(polyline))
                             : at < f.colourIndex.size() ? f.colourIndex[at]
                                                         : -1;
            if (c < 0 || std::size_t(c) >= f.colours.size()) {
                bad = true;
                m.colours.push_back({1, 1, 1, 1});
            } else {
                m.colours.push_back(f.colours[std::size_t(c)]);
            }
        }
        const auto vertex = std::uint32_t(m.positions.size() - 1);
        if (previous >= 0) m.segments.push_back({previousVertex, vertex});
        previous = index;
        previousVertex = vertex;
    }
    if (bad)
        out.warnings.push_back("an index points past the end of its list (coord or color); "
                               "those points are left out or shown white");
    return out;
}

Mesh pointSetMesh(const std::vector<std::array<double, 3>>& points,
                  const std::vector<std::array<float, 4>>& colours) {
    Mesh m;
    m.primitive = Primitive::Points;
    for (const Vec3& p : points) {
        m.positions.push_back(toFloat(p));
        m.normals.push_back({0, 0, 0});
    }
    if (colours.size() >= points.size())
        m.colours.assign(colours.begin(), colours.begin() + long(points.size()));
    return m;
}

FaceSetResult elevationGridMesh(const ElevationGrid& g) {
    FaceSetResult out;
    const long nx = g.xDimension, nz = g.zDimension;
    if (nx < 2 || nz < 2) return out; // no face
    if (long(g.height.size()) < nx * nz) {
        out.warnings.push_back("ElevationGrid has fewer heights than xDimension x zDimension; "
                               "the missing ones are 0");
    }
    FaceSet f;
    f.ccw = g.ccw;
    f.creaseAngle = g.creaseAngle;
    f.colours = g.colours;
    f.colourPerVertex = g.colourPerVertex;
    // X3D 13.3.4: s from 0 to 1 along x, t along z, unless given.
    const bool given = g.texCoords.size() >= std::size_t(nx * nz);
    for (long j = 0; j < nz; ++j)
        for (long i = 0; i < nx; ++i) {
            const std::size_t k = std::size_t(i + j * nx);
            f.points.push_back({double(i) * g.xSpacing, k < g.height.size() ? g.height[k] : 0.0,
                                double(j) * g.zSpacing});
            f.texCoords.push_back(given ? g.texCoords[k]
                                        : std::array<double, 2>{double(i) / double(nx - 1),
                                                                double(j) / double(nz - 1)});
        }
    // Seen from above: (i, j) -> (i, j+1) -> (i+1, j+1) -> (i+1, j) is counter-clockwise.
    for (long j = 0; j + 1 < nz; ++j)
        for (long i = 0; i + 1 < nx; ++i)
            f.coordIndex.insert(f.coordIndex.end(), {i + j * nx, i + (j + 1) * nx,
                                                     i + 1 + (j + 1) * nx, i + 1 + j * nx, -1});
    FaceSetResult r = faceSetMesh(f);
    r.warnings.insert(r.warnings.begin(), out.warnings.begin(), out.warnings.end());
    return r;
}

namespace {

// Rodrigues: v turned by `angle` about the unit `axis`.
Vec3 turned(const Vec3& v, const std::array<double, 4>& r) {
    const Vec3 axis = field::unitOr({r[0], r[1], r[2]}, {0, 0, 1});
    const double c = std::cos(r[3]), s = std::sin(r[3]);
    const Vec3 k = field::cross(axis, v);
    const double d = axis[0] * v[0] + axis[1] * v[1] + axis[2] * v[2];
    return {v[0] * c + k[0] * s + axis[0] * d * (1 - c),
            v[1] * c + k[1] * s + axis[1] * d * (1 - c),
            v[2] * c + k[2] * s + axis[2] * d * (1 - c)};
}

} // namespace

FaceSetResult extrusionMesh(const Extrusion& e) {
    FaceSetResult out;
    const std::size_t ns = e.spine.size(), nc = e.crossSection.size();
    if (ns < 2 || nc < 2) return out;
    const bool closedSpine = e.spine.front() == e.spine.back();
    // The spine-aligned cross-section plane at each spine point: y along the
    // spine, z across its bend (kept from the last bend where it is straight).
    std::vector<Vec3> X(ns), Y(ns), Z(ns);
    for (std::size_t i = 0; i < ns; ++i) {
        const Vec3 next = i + 1 < ns ? e.spine[i + 1] : closedSpine ? e.spine[1] : e.spine[i];
        const Vec3 prev = i > 0 ? e.spine[i - 1] : closedSpine ? e.spine[ns - 2] : e.spine[i];
        Y[i] = field::unitOr(field::minus(next, prev), i ? Y[i - 1] : Vec3{0, 1, 0});
        Z[i] = field::unitOr(
            field::cross(field::minus(next, e.spine[i]), field::minus(prev, e.spine[i])),
            {0, 0, 0});
    }
    // Straight stretches take the first bend's z (or +z turned onto the spine).
    Vec3 firstZ{0, 0, 0};
    for (const Vec3& z : Z)
        if (z != Vec3{0, 0, 0}) {
            firstZ = z;
            break;
        }
    if (firstZ == Vec3{0, 0, 0}) {
        const Vec3 y = Y[0];
        const Vec3 helper = std::abs(y[1]) < 0.9 ? Vec3{0, 1, 0} : Vec3{0, 0, 1};
        firstZ = std::abs(y[1]) > 0.999
                     ? Vec3{0, 0, y[1] > 0 ? 1.0 : -1.0}
                     : field::unitOr(field::cross(field::cross(y, helper), y), {0, 0, 1});
    }
    for (std::size_t i = 0; i < ns; ++i) {
        if (Z[i] == Vec3{0, 0, 0}) Z[i] = i ? Z[i - 1] : firstZ;
        if (i && Z[i][0] * Z[i - 1][0] + Z[i][1] * Z[i - 1][1] + Z[i][2] * Z[i - 1][2] < 0)
            Z[i] = {-Z[i][0], -Z[i][1], -Z[i][2]}; // no sudden flip
        X[i] = field::unitOr(field::cross(Y[i], Z[i]), {1, 0, 0});
    }
    FaceSet f;
    f.creaseAngle = e.creaseAngle;
    for (std::size_t i = 0; i < ns; ++i) {
        const auto& sc = e.scale[std::min(i, e.scale.size() - 1)];
        const auto& turn = e.orientation[std::min(i, e.orientation.size() - 1)];
        for (const auto& c : e.crossSection) {
            const Vec3 local = turned({sc[0] * c[0], 0, sc[1] * c[1]}, turn);
            Vec3 p = e.spine[i];
            for (std::size_t k = 0; k < 3; ++k)
                p[k] += X[i][k] * local[0] + Y[i][k] * local[1] + Z[i][k] * local[2];
            f.points.push_back(p);
        }
    }
    auto at = [&](std::size_t spine, std::size_t c) { return std::int64_t(spine * nc + c); };
    for (std::size_t i = 0; i + 1 < ns; ++i)
        for (std::size_t c = 0; c + 1 < nc; ++c)
            f.coordIndex.insert(f.coordIndex.end(),
                                {at(i, c), at(i, c + 1), at(i + 1, c + 1), at(i + 1, c), -1});
    // X3D 13.3.5 texture: s along the cross-section, t along the spine, each
    // by its length; the caps show the cross-section's box, longer side = 1.
    auto cumulative = [](auto distance, std::size_t n) {
        std::vector<double> out(n, 0);
        for (std::size_t k = 1; k < n; ++k)
            out[k] = out[k - 1] + distance(k);
        for (double& v : out)
            v = out.back() > 0 ? v / out.back() : 0;
        return out;
    };
    const auto sAlong = cumulative(
        [&](std::size_t k) {
            return std::hypot(e.crossSection[k][0] - e.crossSection[k - 1][0],
                              e.crossSection[k][1] - e.crossSection[k - 1][1]);
        },
        nc);
    const auto tAlong = cumulative(
        [&](std::size_t k) {
            const Vec3 d = field::minus(e.spine[k], e.spine[k - 1]);
            return std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        },
        ns);
    for (std::size_t i = 0; i < ns; ++i)
        for (std::size_t c = 0; c < nc; ++c)
            f.texCoords.push_back({sAlong[c], tAlong[i]});
    f.texCoordIndex = f.coordIndex;
    double x0 = INFINITY, x1 = -INFINITY, z0 = INFINITY, z1 = -INFINITY;
    for (const auto& c : e.crossSection) {
        x0 = std::min(x0, c[0]), x1 = std::max(x1, c[0]);
        z0 = std::min(z0, c[1]), z1 = std::max(z1, c[1]);
    }
    const double capSide = std::max({x1 - x0, z1 - z0, 1e-300});
    const std::int64_t capBase = std::int64_t(f.texCoords.size());
    for (const auto& c : e.crossSection)
        f.texCoords.push_back({(c[0] - x0) / capSide, (c[1] - z0) / capSide});
    const bool closedSection = e.crossSection.front() == e.crossSection.back();
    const std::size_t capCorners = closedSection ? nc - 1 : nc;
    // Caps wind against the side quads that share their edges (the first
    // quads walk (0, c) -> (0, c+1), the last (n, c+1) -> (n, c)), so the
    // whole surface is oriented one way; the flip below then makes it outward.
    if (e.beginCap && capCorners >= 3) {
        for (std::size_t c = capCorners; c-- > 0;) {
            f.coordIndex.push_back(at(0, c));
            f.texCoordIndex.push_back(capBase + std::int64_t(c));
        }
        f.coordIndex.push_back(-1);
        f.texCoordIndex.push_back(-1);
    }
    if (e.endCap && capCorners >= 3) {
        for (std::size_t c = 0; c < capCorners; ++c) {
            f.coordIndex.push_back(at(ns - 1, c));
            f.texCoordIndex.push_back(capBase + std::int64_t(c));
        }
        f.coordIndex.push_back(-1);
        f.texCoordIndex.push_back(-1);
    }
    out = faceSetMesh(f);
    // Outward: by the volume when closed, else the sides away from the spine.
    double volume = 0;
    for (const Triangle& t : out.mesh.triangles) {
        const auto& a = out.mesh.positions[t[0]];
        const auto& b = out.mesh.positions[t[1]];
        const auto& c = out.mesh.positions[t[2]];
        volume += (double(a[0]) * (double(b[1]) * c[2] - double(b[2]) * c[1]) -
                   double(a[1]) * (double(b[0]) * c[2] - double(b[2]) * c[0]) +
                   double(a[2]) * (double(b[0]) * c[1] - double(b[1]) * c[0])) /
                  6;
    }
    bool inward = volume < 0;
    const bool closed = closedSection && (closedSpine || (e.beginCap && e.endCap));
    if (!closed && !out.mesh.triangles.empty()) {
        const Triangle& t = out.mesh.triangles.front();
        const auto& n = out.mesh.normals[t[0]];
        const auto& p = out.mesh.positions[t[0]];
        const Vec3 away = field::minus({p[0], p[1], p[2]}, e.spine[0]);
        inward = n[0] * away[0] + n[1] * away[1] + n[2] * away[2] < 0;
    }
    if (inward) {
        for (Triangle& t : out.mesh.triangles)
            std::swap(t[1], t[2]);
        for (Vec3f& n : out.mesh.normals)
            n = {-n[0], -n[1], -n[2]};
    }
    return out;
}

} // namespace fl::mesh
