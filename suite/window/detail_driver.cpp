#include "detail_driver.h"

#include "mesh/scene_meshing.h"
#include "viewer/level_of_detail_control.h"
#include "viewer/scene_player.h"
#include "viewer/scene_widget.h"

namespace fl::suite {

DetailDriver::DetailDriver(viewer::SceneWidget* view, viewer::ScenePlayer* player,
                           std::function<std::shared_ptr<const scene::Scene>()> played,
                           QObject* parent)
    : QObject(parent), view_(view), player_(player), played_(std::move(played)),
      lod_(std::make_unique<viewer::LevelOfDetail>()) {
    timer_.setSingleShot(true);
    timer_.setInterval(150);
    connect(view_, &viewer::SceneWidget::poseChanged, this, [this] { timer_.start(); });
    connect(&timer_, &QTimer::timeout, this, [this] {
        const auto meshes = view_->meshes();
        if (meshes && meshes->source == played_() &&
            lod_->update(*meshes, view_->pose(), view_->size()))
            play();
    });
}

DetailDriver::~DetailDriver() = default;

void DetailDriver::sceneChanged() {
    lod_->clear();
    chosen_.clear();
}

void DetailDriver::frameShown(const std::shared_ptr<const mesh::SceneMeshes>& meshes) {
    // The first frame of a scene is at the file's resolutions: the level of
    // detail looks at it once it is on screen.
    if (meshes->source == played_() && meshes->source != seen_) {
        seen_ = meshes->source;
        pending_ = true;
    }
    if (pending_) {
        pending_ = false;
        timer_.start();
    }
}

void DetailDriver::choose(const scene::Node* geometry, double resolution) {
    chosen_[geometry] = resolution;
    play();
}

void DetailDriver::play() {
    auto resolutions = lod_->resolutions();
    for (const auto& [geometry, resolution] : chosen_)
        resolutions[geometry] = resolution;
    player_->setResolutions(std::move(resolutions));
}

} // namespace fl::suite
