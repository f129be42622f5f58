#pragma once
// Play, pause, scrub and speed for the scene's timeline, and the time shown.
#include <QWidget>

class QDoubleSpinBox;
class QLabel;
class QSlider;
class QToolButton;

namespace fl::viewer {
class ScenePlayer;
}

namespace fl::suite {

class TimelineBar : public QWidget {
  public:
    TimelineBar(viewer::ScenePlayer* player, QWidget* parent = nullptr);
    void setSpan(double seconds); // the slider's range: 0 .. seconds
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
