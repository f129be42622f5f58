#include "scene_walk.h"

#include "formula/eval_scalar.h"
#include "scene/field_access.h"

#include <cmath>

namespace fl::mesh {

using scene::Node;

std::string SceneWalkContext::nameOf(const Node& n) const {
    return n.type + (n.defName.empty() ? "" : " " + n.defName) + " (" + scene.locationOf(n) + ")";
}

scene::GeometryType SceneWalkContext::geometryTypeOf(const Node& geometry) const {
    return scene::geometryTypeNamed(moment.string(geometry, "type"))
        .value_or(scene::GeometryType::Explicit);
}

std::optional<scene::SetOperation> SceneWalkContext::operationOf(const Node& ft) const {
    return scene::setOperationNamed(moment.string(ft, "operation"));
}

Affine SceneWalkContext::transformOf(const Node& n) const {
    const auto t = moment.numbers(n, "translation"), c = moment.numbers(n, "center"),
               s = moment.numbers(n, "scale");
    const auto r = moment.numbers(n, "rotation"), sr = moment.numbers(n, "scaleOrientation");
    Affine srInverse = Affine::rotate(sr);
    if (sr.size() == 4) srInverse = Affine::rotate(sr[0], sr[1], sr[2], -sr[3]);
    return Affine::translate(t[0], t[1], t[2]) * Affine::translate(c[0], c[1], c[2]) *
           Affine::rotate(r) * Affine::rotate(sr) * Affine::scale(s[0], s[1], s[2]) * srInverse *
           Affine::translate(-c[0], -c[1], -c[2]);
}

Affine SceneWalkContext::functionTransform(const Node& n) const {
    const double t = timeOf(n);
    auto outputs = [&](const char* field, std::vector<double> fallback) {
        const formula::Tape* tape = scene.definition(n, field);
        if (!tape) return fallback;
        formula::ScalarEvaluator e(*tape);
        std::vector<double> values(tape->outputs.size());
        e.evaluateAll({0, 0, 0, t, 0, 0, 0}, values.data());
        return values;
    };
    const auto tr = outputs("translation", {0, 0, 0});
    const auto angle = outputs("rotationAngle", {0});
    const auto sc = outputs("scale", {1, 1, 1});
    const auto axis = moment.numbers(n, "rotationAxis"), c = moment.numbers(n, "center");
    if (tr.size() < 3 || sc.size() < 3 || angle.empty()) return {};
    return Affine::translate(tr[0], tr[1], tr[2]) * Affine::translate(c[0], c[1], c[2]) *
           Affine::rotate(axis[0], axis[1], axis[2], angle[0]) *
           Affine::scale(sc[0], sc[1], sc[2]) * Affine::translate(-c[0], -c[1], -c[2]);
}

const Node* SceneWalkContext::appearanceOf(const Node& shape) const {
    return scene::effectiveNode(moment.node(shape, "appearance"));
}

const Node* SceneWalkContext::materialOf(const Node* appearance) const {
    return appearance ? scene::effectiveNode(moment.node(*appearance, "material")) : nullptr;
}

MeshResult SceneWalkContext::cached(const std::string& key,
                                    const std::function<MeshResult()>& make) const {
    if (!options.cache) return make();
    return *options.cache->get(key, make);
}

bool WalkGuard::refused(const scene::WalkPath::Step& step) {
    if (step.entered()) return false;
    if (!noted_)
        notes_.push_back("a node contains itself, or nodes nest more than " +
                         std::to_string(scene::kMaxWalkDepth) +
                         " deep; the walk stops there and what is below is not meshed");
    noted_ = true;
    return true;
}

namespace {

void placeMesh(ShapeMesh& sm, const Affine& m) {
    // Normals by the inverse transpose: the cofactors, with det's sign
    // (the length is normalised away), once per shape.
    const double det = m.determinant();
    const auto c = m.cofactors();
    const double sign = det < 0 ? -1 : 1;
    for (std::size_t i = 0; i < sm.mesh.positions.size(); ++i) {
        Vec3f& p = sm.mesh.positions[i];
        const double x = p[0], y = p[1], z = p[2];
        for (int k = 0; k < 3; ++k)
            p[std::size_t(k)] = float(m.m[k][0] * x + m.m[k][1] * y + m.m[k][2] * z + m.t[k]);
        const Vec3f& n = sm.mesh.normals[i];
        std::array<double, 3> r{};
        for (std::size_t k = 0; k < 3; ++k)
            r[k] = sign * (c[k][0] * n[0] + c[k][1] * n[1] + c[k][2] * n[2]);
        const double len = std::sqrt(r[0] * r[0] + r[1] * r[1] + r[2] * r[2]);
        if (len > 0) sm.mesh.normals[i] = {float(r[0] / len), float(r[1] / len), float(r[2] / len)};
    }
    // A mirroring transform turns the triangles inside out: turn them back.
    if (det < 0)
        for (Triangle& t : sm.mesh.triangles)
            std::swap(t[1], t[2]);
}

} // namespace

void place(ShapeMesh& sm, const Affine& m, const SceneMeshOptions& options) {
    if (!options.placeInScene) {
        sm.placement = m.matrix();
        return;
    }
    placeMesh(sm, m);
}

} // namespace fl::mesh
