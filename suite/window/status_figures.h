#pragma once
// The figures at the right of the status bar: triangles on screen, the time
// spent meshing them, the measured max error of what is shown (the error
// meter's), frames per second and the scene's time t.
#include <QObject>
#include <QString>
#include <QTimer>

class QLabel;
class QStatusBar;

namespace fl::mesh {
struct SceneMeshes;
}
namespace fl::viewer {
class SceneWidget;
class ScenePlayer;
} // namespace fl::viewer

namespace fl::suite {

class ScreenErrorMeter;

class StatusFigures : public QObject {
    Q_OBJECT
  public:
    StatusFigures(QStatusBar* bar, viewer::SceneWidget* view, viewer::ScenePlayer* player,
                  ScreenErrorMeter* meter, QObject* parent = nullptr);

    // A frame is on screen: its triangles and meshing time.
    void frameShown(const mesh::SceneMeshes& meshes);
    QString screenErrorText() const;

  private:
    viewer::SceneWidget* view_;
    viewer::ScenePlayer* player_;
    QLabel *triangles_, *meshTime_, *screenError_, *frameRate_, *timeLabel_;
    QTimer rate_;
    std::size_t framesAtLastRate_ = 0;
};

} // namespace fl::suite
