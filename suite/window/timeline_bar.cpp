#include "timeline_bar.h"

#include "scene/field_access.h"
#include "scene/scene.h"
#include "viewer/scene_player.h"

#include <QDoubleSpinBox>
#include <QHBoxLayout>
#include <QLabel>
#include <QSignalBlocker>
#include <QSlider>
#include <QStyle>
#include <QToolButton>

#include <algorithm>

namespace fl::suite {

TimelineBar::TimelineBar(viewer::ScenePlayer* player, QWidget* parent)
    : QWidget(parent), player_(player), play_(new QToolButton),
      slider_(new QSlider(Qt::Horizontal)), speed_(new QDoubleSpinBox), time_(new QLabel) {
    auto* row = new QHBoxLayout(this);
    row->setContentsMargins(4, 2, 4, 2);
    play_->setIcon(style()->standardIcon(QStyle::SP_MediaPlay));
    play_->setToolTip(tr("Play / pause (Space)"));
    play_->setCheckable(true);
    slider_->setRange(0, 1000);
    slider_->setToolTip(tr("Scrub through time"));
    speed_->setRange(0.05, 20);
    speed_->setValue(1);
    speed_->setSingleStep(0.25);
    speed_->setSuffix(QStringLiteral("×"));
    speed_->setToolTip(tr("Playback speed"));
    time_->setMinimumWidth(90);
    row->addWidget(play_);
    row->addWidget(slider_, 1);
    row->addWidget(new QLabel(tr("speed")));
    row->addWidget(speed_);
    row->addWidget(time_);
    QObject::connect(play_, &QToolButton::toggled, this, [this](bool on) {
        on ? player_->play() : player_->pause();
        play_->setIcon(style()->standardIcon(on ? QStyle::SP_MediaPause : QStyle::SP_MediaPlay));
    });
    QObject::connect(slider_, &QSlider::sliderMoved, this,
                     [this](int v) { player_->seek(span_ * v / 1000.0); });
    QObject::connect(speed_, &QDoubleSpinBox::valueChanged, this,
                     [this](double s) { player_->setSpeed(s); });
    showTime(0);
}

void TimelineBar::fitTo(const scene::Scene& scene) {
    double span = 0;
    scene.forEachNode([&](const scene::Node& n) {
        if (n.inProtoBody || !n.spec || !scene::findFieldSpec(*n.spec, "cycleInterval")) return;
        span = std::max(span, scene::numberField(n, "cycleInterval", 0, 1));
    });
    setSpan(span > 0 ? std::clamp(span, 1.0, 120.0) : 10.0);
}

void TimelineBar::setSpan(double seconds) {
    span_ = seconds > 0 ? seconds : 10;
}

void TimelineBar::showTime(double seconds) {
    time_->setText(QStringLiteral("t = %1 s").arg(seconds, 0, 'f', 2));
    if (!slider_->isSliderDown()) {
        const QSignalBlocker block(slider_);
        slider_->setValue(int(std::fmod(std::max(seconds, 0.0), span_) / span_ * 1000));
    }
}

} // namespace fl::suite
