#include "picking.h"

#include "formula/eval_gradient.h"
#include "formula/eval_scalar.h"
#include "scene/field_access.h"

#include <QMatrix4x4>

#include <cmath>
#include <numbers>

namespace fl::viewer {
namespace {

using Vec3 = std::array<double, 3>;

using mesh::Affine;

Vec3 unit(const Vec3& v) {
    const double n = std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
    return n > 0 ? Vec3{v[0] / n, v[1] / n, v[2] / n} : Vec3{0, 0, 0};
}

double length(const Vec3& v) {
    return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]);
}

// The ray's parameter interval inside the box (slabs), or none.
bool clip(const Vec3& o, const Vec3& d, const mesh::Box3& box, double& t0, double& t1) {
    t0 = 0;
    t1 = 1e300;
    for (std::size_t k = 0; k < 3; ++k) {
        if (std::abs(d[k]) < 1e-300) {
            if (o[k] < box.lo[k] || o[k] > box.hi[k]) return false;
            continue;
        }
        double a = (box.lo[k] - o[k]) / d[k], b = (box.hi[k] - o[k]) / d[k];
        if (a > b) std::swap(a, b);
        t0 = std::max(t0, a);
        t1 = std::min(t1, b);
    }
    return t0 <= t1;
}

// On an implicit/explicit shape: march f along the ray in its box, then bisect.
std::optional<Pick> onFunction(const scene::Scene& scene, const mesh::ShapeMesh& s,
                               const Ray& ray) {
    if (!s.geometry || scene::stringField(*s.geometry, "type") == "parametric") return std::nullopt;
    const formula::Tape* tape = scene.definition(*s.geometry, "definition");
    if (!tape) return std::nullopt;
    const Affine place = Affine::fromMatrix(s.placement);
    const auto back = place.inverse();
    if (!back) return std::nullopt;
    const Vec3 origin = back->point({ray.origin.x(), ray.origin.y(), ray.origin.z()});
    const Vec3 along = back->vector({ray.direction.x(), ray.direction.y(), ray.direction.z()});
    for (std::size_t k = 0; k < 3; ++k)
        if (!std::isfinite(origin[k]) || !std::isfinite(along[k])) return std::nullopt;
    double t0, t1;
    if (!clip(origin, along, s.domain, t0, t1) || !std::isfinite(t0) || !std::isfinite(t1))
        return std::nullopt;
    formula::ScalarEvaluator f(*tape);
    for (const auto& [name, v] : s.parameters)
        f.parameters().set(name, v);
    auto at = [&](double t) {
        return Vec3{origin[0] + t * along[0], origin[1] + t * along[1], origin[2] + t * along[2]};
    };
    auto value = [&](double t) {
        const Vec3 p = at(t);
        return f.evaluate(formula::pointXYZ(p[0], p[1], p[2], s.t));
    };
    // Steps of at most 1/512 of the box's diagonal: thin features are not skipped over.
    const double span = t1 - t0;
    const double step =
        std::max(s.domain.diagonal() / 512 / std::max(length(along), 1e-300), span / 100000);
    if (!std::isfinite(step) || !(step > 0)) return std::nullopt;
    double a = t0, fa = value(a);
    // An explicit solid is cut by its box: a ray that enters the box inside
    // the solid (f > 0 there) hits the box face that closes it.
    if (t0 > 0 && fa > 0 && scene::stringField(*s.geometry, "type") == "explicit") {
        const Vec3 local = at(t0);
        std::size_t axis = 0;
        double nearest = 1e300, side = 1;
        for (std::size_t k = 0; k < 3; ++k)
            for (const double face : {s.domain.lo[k], s.domain.hi[k]})
                if (std::abs(local[k] - face) < nearest) {
                    nearest = std::abs(local[k] - face);
                    axis = k;
                    side = face == s.domain.lo[k] ? -1 : 1;
                }
        Vec3 world{};
        for (int r = 0; r < 3; ++r)
            world[std::size_t(r)] = back->m[axis][r] * side;
        Pick p;
        p.point = place.point(local);
        p.normal = unit(world);
        p.distance = length({p.point[0] - ray.origin.x(), p.point[1] - ray.origin.y(),
                             p.point[2] - ray.origin.z()});
        p.shape = s.name;
        p.onFunction = true;
        return p;
    }
    int steps = 0;
    for (double b = std::min(t0 + step, t1);; b = std::min(b + step, t1)) {
        // A step lost to rounding (a camera very far away) or a march too
        // long ends the search rather than the interface.
        if (!(b > a) || ++steps > 200000) break;
        const double fb = value(b);
        if (std::isfinite(fa) && std::isfinite(fb) && (fa > 0) != (fb > 0)) {
            for (int i = 0; i < 100 && b - a > 1e-15 * std::max(1.0, std::abs(b)); ++i) {
                const double m = 0.5 * (a + b), fm = value(m);
                if (!std::isfinite(fm)) break;
                ((fm > 0) == (fa > 0) ? a : b) = m;
                if ((fm > 0) == (fa > 0)) fa = fm;
            }
            const double t = 0.5 * (a + b);
            const Vec3 local = at(t);
            formula::GradientEvaluator g(*tape);
            for (const auto& [name, v] : s.parameters)
                g.parameters().set(name, v);
            const formula::Dual d =
                g.evaluate(formula::pointXYZ(local[0], local[1], local[2], s.t));
            // Normals by the inverse transpose; f > 0 inside, so outward is -grad f.
            const Vec3 n{-d.d[0], -d.d[1], -d.d[2]};
            Vec3 world{};
            for (int r = 0; r < 3; ++r)
                world[std::size_t(r)] =
                    back->m[0][r] * n[0] + back->m[1][r] * n[1] + back->m[2][r] * n[2];
            Pick p;
            p.point = place.point(local);
            p.normal = unit(world);
            // An implicit surface f = 0 has no outside: its normal faces the eye.
            if (scene::stringField(*s.geometry, "type") == "implicit" &&
                p.normal[0] * ray.direction.x() + p.normal[1] * ray.direction.y() +
                        p.normal[2] * ray.direction.z() >
                    0)
                for (double& c : p.normal)
                    c = -c;
            p.distance = length({p.point[0] - ray.origin.x(), p.point[1] - ray.origin.y(),
                                 p.point[2] - ray.origin.z()});
            p.shape = s.name;
            p.onFunction = true;
            return p;
        }
        if (b >= t1) break;
        a = b;
        fa = fb;
    }
    return std::nullopt;
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

std::optional<Pick> pick(const scene::Scene& scene, const mesh::SceneMeshes& meshes,
                         const Ray& ray) {
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
    for (const mesh::ShapeMesh& s : meshes.shapes) {
        if (!s.error.empty()) continue;
        std::optional<Pick> p = onFunction(scene, s, ray);
        if (!p) p = onTriangles(s, ray);
        if (p && (!best || p->distance < best->distance)) {
            best = p;
            best->touchSensors = s.touchSensors;
        }
    }
    return best;
}

} // namespace fl::viewer
