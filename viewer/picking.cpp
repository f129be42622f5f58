#include "picking.h"

#include "field/ray_march.h"

#include <QMatrix4x4>

#include <cmath>
#include <numbers>

namespace fl::viewer {
namespace {

using field::Affine;
using field::length;
using field::Vec3;

Vec3 unit(const Vec3& v) {
    return field::unitOr(v, {0, 0, 0});
}

// On an implicit/explicit shape: the field it was meshed from, marched along
// the ray in the shape's own coordinates (field/ray_march.h).
std::optional<Pick> onFunction(const mesh::ShapeMesh& s, const Ray& ray) {
    if (!s.field) return std::nullopt;
    const Affine place = Affine::fromMatrix(s.placement);
    const auto back = place.inverse();
    if (!back) return std::nullopt;
    const Vec3 origin = back->point({ray.origin.x(), ray.origin.y(), ray.origin.z()});
    const Vec3 along = back->vector({ray.direction.x(), ray.direction.y(), ray.direction.z()});
    field::FieldSampler sampler(*s.field);
    const auto hit = field::marchToSurface(sampler, origin, along);
    if (!hit) return std::nullopt;
    // Normals by the inverse transpose.
    const Vec3& n = hit->normal;
    Vec3 world{};
    for (int r = 0; r < 3; ++r)
        world[std::size_t(r)] = back->m[0][r] * n[0] + back->m[1][r] * n[1] + back->m[2][r] * n[2];
    Pick p;
    p.point = place.point(hit->point);
    p.normal = unit(world);
    p.distance = length(
        {p.point[0] - ray.origin.x(), p.point[1] - ray.origin.y(), p.point[2] - ray.origin.z()});
    p.shape = s.name;
    p.onFunction = true;
    return p;
}

// On the nearest triangle of a mesh (Möller–Trumbore).
std::optional<Pick> onTriangles(const mesh::ShapeMesh& s, const Ray& ray) {
    if (s.mesh.isPointCloud()) return std::nullopt;
    const Affine place = Affine::fromMatrix(s.placement);
    const Vec3 o{ray.origin.x(), ray.origin.y(), ray.origin.z()};
    const Vec3 d{ray.direction.x(), ray.direction.y(), ray.direction.z()};
    std::optional<Pick> best;
    auto P = [&](std::uint32_t i) {
        const auto& v = s.mesh.positions[i];
        return place.point({v[0], v[1], v[2]});
    };
    for (const mesh::Triangle& tri : s.mesh.triangles) {
        if (!mesh::isDrawnTriangle(s.mesh, tri)) continue;
        const Vec3 a = P(tri[0]), b = P(tri[1]), c = P(tri[2]);
        const Vec3 e1{b[0] - a[0], b[1] - a[1], b[2] - a[2]},
            e2{c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const Vec3 h{d[1] * e2[2] - d[2] * e2[1], d[2] * e2[0] - d[0] * e2[2],
                     d[0] * e2[1] - d[1] * e2[0]};
        const double det = e1[0] * h[0] + e1[1] * h[1] + e1[2] * h[2];
        if (std::abs(det) < 1e-300) continue;
        const Vec3 sv{o[0] - a[0], o[1] - a[1], o[2] - a[2]};
        const double u = (sv[0] * h[0] + sv[1] * h[1] + sv[2] * h[2]) / det;
        if (!(u >= 0 && u <= 1)) continue; // NaN fails too
        const Vec3 q{sv[1] * e1[2] - sv[2] * e1[1], sv[2] * e1[0] - sv[0] * e1[2],
                     sv[0] * e1[1] - sv[1] * e1[0]};
        const double v = (d[0] * q[0] + d[1] * q[1] + d[2] * q[2]) / det;
        if (!(v >= 0 && u + v <= 1)) continue;
        const double t = (e2[0] * q[0] + e2[1] * q[1] + e2[2] * q[2]) / det;
        if (!(t > 0) || !std::isfinite(t) || (best && t >= best->distance)) continue;
        Pick p;
        p.point = {o[0] + t * d[0], o[1] + t * d[1], o[2] + t * d[2]};
        p.normal = unit({e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2],
                         e1[0] * e2[1] - e1[1] * e2[0]});
        p.distance = t;
        p.shape = s.name;
        best = p;
    }
    return best;
}

} // namespace

Ray rayThroughPixel(const CameraPose& pose, QSize viewport, QPointF pixel) {
    QMatrix4x4 projection, view;
    const float aspect =
        float(std::max(viewport.width(), 1)) / float(std::max(viewport.height(), 1));
    projection.perspective(pose.verticalFieldOfView, aspect, pose.nearPlane, pose.farPlane);
    view.lookAt(pose.position, pose.viewCenter, pose.up);
    const QMatrix4x4 back = (projection * view).inverted();
    const float x = float(2 * pixel.x() / std::max(viewport.width(), 1) - 1);
    const float y = float(1 - 2 * pixel.y() / std::max(viewport.height(), 1));
    const QVector3D nearPoint = back.map(QVector3D(x, y, -1));
    const QVector3D farPoint = back.map(QVector3D(x, y, 1));
    return {pose.position, (farPoint - nearPoint).normalized()};
}

std::optional<Pick> pick(const mesh::SceneMeshes& meshes, const Ray& ray) {
    std::optional<Pick> best;
    for (int k = 0; k < 3; ++k)
        if (!std::isfinite(ray.origin[k]) || !std::isfinite(ray.direction[k])) return best;
    // An eye so far away that its coordinates' last digit is larger than a
    // thousandth of the scene cannot say where on the scene it points
    // (origin + t * direction rounds to that digit): nothing is picked,
    // rather than a point the rounding made up.
    double reach = 0;
    for (const mesh::ShapeMesh& s : meshes.shapes) {
        const Affine place = Affine::fromMatrix(s.placement);
        for (const auto& v : s.mesh.positions) {
            const Vec3 p = place.point({v[0], v[1], v[2]});
            reach = std::max({reach, std::abs(p[0]), std::abs(p[1]), std::abs(p[2])});
        }
    }
    const double far = std::max({std::abs(double(ray.origin.x())), std::abs(double(ray.origin.y())),
                                 std::abs(double(ray.origin.z()))});
    if (far * 2.3e-16 > 1e-3 * std::max(reach, 1e-6)) return best;
    for (std::size_t i = 0; i < meshes.shapes.size(); ++i) {
        const mesh::ShapeMesh& s = meshes.shapes[i];
        if (!s.error.empty() || !mesh::isDrawn(s)) continue; // what is not seen is not hit
        std::optional<Pick> p = onFunction(s, ray);
        if (!p) p = onTriangles(s, ray);
        if (p && (!best || p->distance < best->distance)) {
            best = p;
            best->shapeIndex = i;
            best->touchSensors = s.touchSensors;
        }
    }
    return best;
}

} // namespace fl::viewer
