#include "level_of_detail_control.h"

#include "mesh/level_of_detail.h"
#include "scene/field_access.h"

#include <QMatrix4x4>

#include <algorithm>
#include <cmath>
#include <numbers>

namespace fl::viewer {
namespace {

// The shape's domain box in the scene, as the box round its eight corners.
field::Box3 sceneBox(const mesh::ShapeMesh& s) {
    return field::boundsOf(s.domain, field::Affine::fromMatrix(s.placement));
}

double distanceTo(const field::Box3& box, const QVector3D& eye) {
    double d2 = 0;
    for (std::size_t k = 0; k < 3; ++k) {
        const double e = eye[int(k)];
        const double d = e < box.lo[k] ? box.lo[k] - e : e > box.hi[k] ? e - box.hi[k] : 0;
        d2 += d * d;
    }
    return std::sqrt(d2);
}

} // namespace

bool LevelOfDetail::update(const mesh::SceneMeshes& meshes, const CameraPose& pose,
                           QSize viewport) {
    bool changed = false;
    for (const mesh::ShapeMesh& s : meshes.shapes) {
        // A combined shape (an FTransform's set operation) takes its first
        // lod child's range, and its resolution is keyed by the FTransform.
        if (!s.levelOfDetail || !s.error.empty()) continue;
        const scene::Node* key = s.geometry ? s.geometry : s.shape;
        if (!key) continue;
        const auto range = scene::numbersField(*s.levelOfDetail, "lodRange");
        const double lo = range.size() == 2 ? range[0] : 8, hi = range.size() == 2 ? range[1] : 256;
        const field::Box3 box = sceneBox(s);
        mesh::ViewForLod view;
        view.distance = distanceTo(box, pose.position);
        view.fieldOfViewY = double(pose.verticalFieldOfView) * std::numbers::pi / 180;
        view.viewportHeight = std::max(viewport.height(), 1);
        view.pixelError = pixelError;
        const double wanted = mesh::resolutionForView(box, view, lo, hi);
        auto it = resolutions_.find(key);
        const double current = it != resolutions_.end() ? it->second : s.resolution;
        // At the ends of lodRange a clamped wish is always taken.
        const bool atLimit = (wanted == lo || wanted == hi) && wanted != current;
        if (atLimit || mesh::lodChangeWorthIt(current, wanted, hysteresis)) {
            resolutions_[key] = wanted;
            changed = true;
        }
    }
    return changed;
}

} // namespace fl::viewer
