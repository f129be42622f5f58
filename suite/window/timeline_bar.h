#pragma once
// Play, pause, scrub and speed for the scene's timeline, and the time shown.
#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QSlider;
class QToolButton;

namespace fl::scene {
struct Scene;
}
namespace fl::viewer {
class ScenePlayer;
}

namespace fl::suite {

class TimelineBar : public QWidget {
  public:
    TimelineBar(viewer::ScenePlayer* player, QWidget* parent = nullptr);
    void setSpan(double seconds); // the slider's range: 0 .. seconds
    // Spans the longest cycle among the scene's timed nodes (TimeSensors and
    // function nodes), within 1 .. 120 s; 10 s when none has one.
    void fitTo(const scene::Scene& scene);
    void showTime(double seconds);
    QToolButton* playButton() const { return play_; }
    QSlider* slider() const { return slider_; }

  private:
    viewer::ScenePlayer* player_;
    QToolButton* play_;
    QSlider* slider_;
    QDoubleSpinBox* speed_;
    QLabel* time_;
    double span_ = 10;
};

} // namespace fl::suite
