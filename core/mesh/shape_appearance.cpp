#include "shape_appearance.h"

#include "colouring.h"

namespace fl::mesh {

using scene::Node;

SurfaceLook lookOf(const SceneWalkContext& context, const Node* appearance, bool functionShape) {
    SurfaceLook look;
    const Node* material = context.materialOf(appearance);
    if (!material) {
        look.lit = functionShape;
        return look;
    }
    auto rgb = [&](const char* field, std::array<float, 3>& out) {
        const auto v = context.moment.numbers(*material, field);
        if (v.size() == 3) out = {float(v[0]), float(v[1]), float(v[2])};
    };
    rgb("emissiveColor", look.emissive);
    rgb("specularColor", look.specular);
    look.shininess = float(context.moment.number(*material, "shininess", 0, 0.2));
    look.ambientIntensity = float(context.moment.number(*material, "ambientIntensity", 0, 0.2));
    return look;
}

void colour(const SceneWalkContext& context, const Node* appearance, const Box3& geometryBox,
            ShapeMesh& sm) {
    const Node* material = context.materialOf(appearance);
    if (!material) return;
    const animation::Animator& moment = context.moment;
    ColourField cf;
    cf.geometryBox = geometryBox;
    cf.componentBox = geometryBox;
    const auto diffuse = moment.numbers(*material, "diffuseColor");
    if (diffuse.size() == 3) cf.fallback = {diffuse[0], diffuse[1], diffuse[2]};
    cf.constantTransparency = moment.number(*material, "transparency");
    if (material->kind() == scene::NodeKind::FMaterial) {
        if (const formula::Tape* tape = context.scene.definition(*material, "definition"))
            cf.colour = *tape;
        if (const formula::Tape* tape =
                context.scene.definition(*material, "transparencyDefinition"))
            cf.transparency = *tape;
        cf.key = moment.numbers(*material, "key");
        const auto kv = moment.numbers(*material, "keyValue");
        for (std::size_t i = 0; i + 2 < kv.size(); i += 3)
            cf.keyValue.push_back({kv[i], kv[i + 1], kv[i + 2]});
        cf.componentBox = domainOf(*material);
        cf.t = context.timeOf(*material);
    }
    const auto warnings = applyColour(sm.mesh, cf);
    sm.warnings.insert(sm.warnings.end(), warnings.begin(), warnings.end());
    if (cf.colour) sm.colourField = std::make_shared<const ColourField>(std::move(cf));
}

Box3 colourBoxOf(const Mesh& m) {
    if (m.positions.empty()) return {};
    Box3 b = pointBounds(m.positions);
    for (std::size_t k = 0; k < 3; ++k) // a flat shape still has a box
        if (!(b.hi[k] > b.lo[k])) b.lo[k] -= 0.5, b.hi[k] += 0.5;
    return b;
}

} // namespace fl::mesh
