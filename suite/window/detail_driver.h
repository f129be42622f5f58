#pragma once
// The level of detail at work in the window: a moment after the camera
// moves (and after a scene's first frame, meshed at the file's
// resolutions), shapes whose wanted resolution left its band are meshed
// again in the background; a resolution chosen in the Accuracy panel
// outlives it for that shape.
#include <QObject>
#include <QTimer>

#include <functional>
#include <memory>
#include <unordered_map>

namespace fl::scene {
struct Node;
struct Scene;
} // namespace fl::scene
namespace fl::mesh {
struct SceneMeshes;
}
namespace fl::viewer {
class LevelOfDetail;
class SceneWidget;
class ScenePlayer;
} // namespace fl::viewer

namespace fl::suite {

class DetailDriver : public QObject {
    Q_OBJECT
  public:
    // `played`: the scene the player plays (only its frames' nodes are the
    // player's keys).
    DetailDriver(viewer::SceneWidget* view, viewer::ScenePlayer* player,
                 std::function<std::shared_ptr<const scene::Scene>()> played,
                 QObject* parent = nullptr);
    ~DetailDriver() override;

    const viewer::LevelOfDetail& levelOfDetail() const { return *lod_; }
    void sceneChanged(); // the old scene's choices name its nodes: forgotten
    // A frame is on screen (called after the view has it).
    void frameShown(const std::shared_ptr<const mesh::SceneMeshes>& meshes);
    void choose(const scene::Node* geometry, double resolution);
    bool busy() const { return timer_.isActive(); }

  private:
    void play(); // the level of detail's resolutions, with the chosen ones

    viewer::SceneWidget* view_;
    viewer::ScenePlayer* player_;
    std::function<std::shared_ptr<const scene::Scene>()> played_;
    std::unique_ptr<viewer::LevelOfDetail> lod_;
    std::unordered_map<const scene::Node*, double> chosen_;
    QTimer timer_;
    bool pending_ = false;
    std::shared_ptr<const scene::Scene> seen_; // the scene whose first frame it saw
};

} // namespace fl::suite
