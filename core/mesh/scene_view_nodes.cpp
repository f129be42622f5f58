#include "scene_view_nodes.h"

#include "animation/animator.h"

#include <cmath>

namespace fl::mesh {

namespace {

using field::Affine;
using scene::Node;
using scene::NodeKind;

std::array<double, 3> placed(const Affine& m, const std::vector<double>& p) {
    return m.point({p[0], p[1], p[2]});
}

// A direction, turned and of unit length.
std::array<double, 3> turned(const Affine& m, const std::array<double, 3>& d) {
    std::array<double, 3> out = m.vector(d);
    const double n = std::sqrt(out[0] * out[0] + out[1] * out[1] + out[2] * out[2]);
    if (n > 0)
        for (double& v : out)
            v /= n;
    return out;
}

struct ViewNodeReader {
    const Node& n;
    const Affine& m;
    const animation::Animator& moment;
    SceneView& view;

    void rgb(const char* field, std::array<float, 3>& out) const {
        const auto v = moment.numbers(n, field);
        if (v.size() >= 3) out = {float(v[0]), float(v[1]), float(v[2])};
    }

    void light(NodeKind kind) const {
        if (!moment.flag(n, "on")) return;
        ViewLight l;
        l.kind = kind == NodeKind::DirectionalLight ? ViewLight::Kind::Directional
                 : kind == NodeKind::PointLight     ? ViewLight::Kind::Point
                                                    : ViewLight::Kind::Spot;
        rgb("color", l.colour);
        l.intensity = float(moment.number(n, "intensity", 0, 1));
        l.ambientIntensity = float(moment.number(n, "ambientIntensity"));
        if (l.kind != ViewLight::Kind::Point) {
            const auto d = moment.numbers(n, "direction");
            if (d.size() == 3) l.direction = turned(m, {d[0], d[1], d[2]});
        }
        if (l.kind != ViewLight::Kind::Directional) {
            const auto p = moment.numbers(n, "location");
            if (p.size() == 3) l.location = placed(m, p);
            const auto a = moment.numbers(n, "attenuation");
            if (a.size() == 3) l.attenuation = {float(a[0]), float(a[1]), float(a[2])};
            l.radius = moment.number(n, "radius", 0, 100);
        }
        if (l.kind == ViewLight::Kind::Spot) {
            l.beamWidth = moment.number(n, "beamWidth", 0, l.beamWidth);
            l.cutOffAngle = moment.number(n, "cutOffAngle", 0, l.cutOffAngle);
        }
        view.lights.push_back(l);
    }

    void viewpoint(NodeKind kind) const {
        ViewPoint v;
        v.name = moment.string(n, "description");
        if (v.name.empty()) v.name = n.defName;
        if (v.name.empty()) v.name = "Viewpoint " + std::to_string(view.viewpoints.size() + 1);
        const auto p = moment.numbers(n, "position");
        if (p.size() == 3) v.position = placed(m, p);
        const Affine frame = m * Affine::rotate(moment.numbers(n, "orientation"));
        v.direction = turned(frame, {0, 0, -1});
        v.up = turned(frame, {0, 1, 0});
        const auto c = moment.numbers(n, "centerOfRotation");
        if (c.size() == 3) v.centerOfRotation = placed(m, c);
        if (kind == NodeKind::Viewpoint)
            v.fieldOfView = moment.number(n, "fieldOfView", 0, v.fieldOfView);
        // The first is bound at load; a set_bind event binds another.
        if (view.viewpoints.empty() || moment.flag(n, "isBound"))
            view.boundViewpoint = int(view.viewpoints.size());
        view.viewpoints.push_back(v);
    }

    // Backgrounds and NavigationInfos: the first, unless an event bound another.
    void background() const {
        if (view.hasBackground && !moment.flag(n, "isBound")) return;
        rgb("skyColor", view.background);
        view.hasBackground = true;
    }

    void navigation() const {
        if (view.hasNavigation && !moment.flag(n, "isBound")) return;
        view.navigation.types = moment.strings(n, "type");
        view.navigation.headlight = moment.flag(n, "headlight");
        view.navigation.speed = moment.number(n, "speed", 0, 1);
        const auto a = moment.numbers(n, "avatarSize");
        for (std::size_t i = 0; i < 3 && i < a.size(); ++i)
            view.navigation.avatarSize[i] = a[i];
        view.hasNavigation = true;
    }
};

} // namespace

bool collectViewNode(const Node& n, const Affine& m, const animation::Animator& moment,
                     SceneView& view) {
    const ViewNodeReader reader{n, m, moment, view};
    const NodeKind kind = n.kind();
    switch (kind) {
    case NodeKind::DirectionalLight:
    case NodeKind::PointLight:
    case NodeKind::SpotLight:
        reader.light(kind);
        return true;
    case NodeKind::Viewpoint:
    case NodeKind::OrthoViewpoint:
        reader.viewpoint(kind);
        return true;
    case NodeKind::Background:
    case NodeKind::TextureBackground:
        reader.background();
        return true;
    case NodeKind::NavigationInfo:
        reader.navigation();
        return true;
    default: // every other kind is what is seen, not how
        return false;
    }
}

} // namespace fl::mesh
