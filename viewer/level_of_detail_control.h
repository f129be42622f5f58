#pragma once
// Continuous level of detail in the view: every function shape whose
// FGeometry has `lod TRUE` is meshed at the resolution its distance from the
// camera asks for (one cell about `pixelError` pixels on screen, within the
// geometry's lodRange), and only changes when the wanted resolution leaves a
// band around the current one, so a camera moving a little never re-meshes
// and a camera approaching refines in a few steps, not at every frame.
#include "camera_pose.h"
#include "mesh/scene_meshing.h"

#include <QSize>

#include <unordered_map>

namespace fl::viewer {

class LevelOfDetail {
  public:
    double pixelError = 4;    // pixels one cell may span (the view's default)
    double hysteresis = 0.35; // the band: a change under 35% is not worth a re-mesh

    // Returns true when a shape's resolution changed (the scene should be meshed again).
    bool update(const mesh::SceneMeshes& meshes, const CameraPose& pose, QSize viewport);
    const std::unordered_map<const scene::Node*, double>& resolutions() const {
        return resolutions_;
    }
    void clear() { resolutions_.clear(); }

  private:
    std::unordered_map<const scene::Node*, double> resolutions_;
};

} // namespace fl::viewer
