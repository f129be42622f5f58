#include "effect_colours.h"

#include "field/domain_mapping.h"
#include "formula/eval_scalar.h"

#include <algorithm>
#include <cmath>

namespace fl::haptics {

std::array<float, 4> effectColour(double value) {
    if (!std::isfinite(value)) return {0.5f, 0.5f, 0.5f, 1};
    const float v = float(std::clamp(value, 0.0, 1.0));
    // Blue -> green -> red: two straight pieces through the middle.
    if (v < 0.5f) return {0, 2 * v, 1 - 2 * v, 1};
    return {2 * v - 1, 2 - 2 * v, 0, 1};
}

std::shared_ptr<const mesh::SceneMeshes> colouredByEffect(const mesh::SceneMeshes& frame,
                                                          const TangibleScene& tangible,
                                                          scene::TangibleKind kind) {
    auto out = std::make_shared<mesh::SceneMeshes>(frame);
    for (mesh::ShapeMesh& s : out->shapes) {
        const TangibleShape* t = nullptr;
        for (const TangibleShape& candidate : tangible.shapes)
            if (candidate.shape == s.shape) t = &candidate;
        if (!t || s.mesh.isLines()) continue;
        const EffectField* e = t->effect(kind);
        if (!e) continue;
        formula::ScalarEvaluator evaluate(e->tape);
        // A borrowed effect reads the lender's coordinates: the snapshot's
        // frame is for its own mesh, and a USE'd shape has other placements,
        // so the lender's frame is taken back out and this mesh's put in.
        const bool borrowed = t->triangles && !t->field;
        field::Affine frameOf = t->effectFrame;
        if (borrowed)
            if (const auto back = t->toScene.inverse())
                frameOf = t->effectFrame * *back * field::Affine::fromMatrix(s.placement);
        const double time = e->timing.at(tangible.moment);
        s.mesh.colours.resize(s.mesh.positions.size());
        for (std::size_t i = 0; i < s.mesh.positions.size(); ++i) {
            const auto& v = s.mesh.positions[i];
            const field::Vec3 p = frameOf.point({v[0], v[1], v[2]});
            const auto c = field::componentView(p, t->geometryBox, e->componentBox);
            const double value = evaluate.evaluate({c[0], c[1], c[2], time, c[3], c[4], c[5]});
            s.mesh.colours[i] = effectColour(value);
        }
        s.look.texture.reset(); // the colours are what is shown now
    }
    return out;
}

} // namespace fl::haptics
