#include "haptics_panel.h"

#include "plain_text.h"
#include "viewer/picking.h"
#include "viewer/render_scene.h"
#include "viewer/scene_player.h"
#include "viewer/scene_widget.h"

#include "haptics/device/device_enumeration.h"
#include "haptics/device/device_limits.h"
#include "haptics/effect_colours.h"
#include "haptics/pointer_device.h"
#include "haptics/servo_loop.h"
#include "haptics/tangible_scene.h"
#include "mesh/scene_meshing.h"
#include "scene/effects_plan.h"

#include <QComboBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QVBoxLayout>

#include <algorithm>

namespace fl::suite {

namespace {

std::shared_ptr<const haptics::TangibleScene> snapshotOf(const scene::Scene& scene,
                                                         double seconds) {
    return std::make_shared<const haptics::TangibleScene>(
        haptics::makeTangibleScene(scene, seconds));
}

QString contactText(haptics::ContactKind c) {
    switch (c) {
    case haptics::ContactKind::Surface:
        return HapticsPanel::tr("on the surface");
    case haptics::ContactKind::Inside:
        return HapticsPanel::tr("inside");
    case haptics::ContactKind::None:
        break;
    }
    return HapticsPanel::tr("free");
}

} // namespace

HapticsPanel::HapticsPanel(QWidget* parent)
    : Panel(tr("Haptics"), QStringLiteral("haptics"), Qt::RightDockWidgetArea, parent),
      feel_(new QPushButton(tr("Feel"))), rescan_(new QPushButton(tr("Find devices"))),
      devices_(new QComboBox), show_(new QComboBox), depth_(new QSlider(Qt::Horizontal)),
      status_(new QLabel), contact_(new QLabel), notes_(plainLabel()), graph_(new ForceGraph),
      worker_(
          this, [](const Request& r) { return snapshotOf(*r.scene, r.seconds); },
          [this](const Request& r, std::shared_ptr<const haptics::TangibleScene> snapshot) {
              if (r.scene != scene_) return; // a scene since replaced
              snapshot_ = snapshot;
              snapshotSeconds_ = r.seconds;
              // Shapes that move, or effects that read t: snapshots follow the timeline.
              geometryVaries_ = snapshot->geometryVaries;
              for (const auto& shape : snapshot->shapes)
                  for (const auto& e : shape.effects)
                      geometryVaries_ = geometryVaries_ || e.readsTime;
              QStringList notes;
              for (const std::string& n : snapshot->notes)
                  notes << QString::fromStdString(n);
              notes_->setText(notes.join(QLatin1Char('\n')));
              if (loop_) loop_->setScene(snapshot, false);
              if (colours()) Q_EMIT showOnSurfaceChanged();
          }),
      colourer_(
          this,
          [](const ColourRequest& r) {
              return haptics::colouredByEffect(*r.frame, *r.tangible, scene::TangibleKind(r.kind));
          },
          [this](const ColourRequest& r, std::shared_ptr<const mesh::SceneMeshes> coloured) {
              if (!colours() || r.tangible != snapshot_) return; // the choice or scene changed
              Q_EMIT frameColoured(coloured);
          }) {
    auto* box = new QWidget;
    auto* layout = new QVBoxLayout(box);
    feel_->setCheckable(true);
    feel_->setToolTip(tr("With the mouse: move it over a tangible shape; the tool follows it, "
                         "pressed into the surface by the depth below"));
    auto* top = new QHBoxLayout;
    top->addWidget(feel_, 1);
    top->addWidget(rescan_);
    layout->addLayout(top);
    auto* form = new QFormLayout;
    form->addRow(tr("Device:"), devices_);
    depth_->setRange(0, 100);
    depth_->setValue(1); // 0.02% of the scene: felt on the watermelon's rind, not through it
    depth_->setToolTip(tr("How far the tool presses into the surface: up to 2% of the scene"));
    form->addRow(tr("Press:"), depth_);
    show_->addItem(tr("nothing"));
    show_->addItem(tr("friction"), int(scene::TangibleKind::Friction));
    show_->addItem(tr("density"), int(scene::TangibleKind::Density));
    show_->setToolTip(tr("Colour the tangible surfaces by their friction or density: blue 0, "
                         "green 0.5, red 1 and more"));
    form->addRow(tr("Show:"), show_);
    connect(show_, &QComboBox::currentIndexChanged, this,
            [this] { Q_EMIT showOnSurfaceChanged(); });
    form->addRow(tr("Loop:"), status_);
    form->addRow(tr("Contact:"), contact_);
    layout->addLayout(form);
    layout->addWidget(graph_, 1);
    notes_->setWordWrap(true);
    layout->addWidget(notes_);
    setWidget(box);
    status_->setText(tr("stopped"));
    connect(rescan_, &QPushButton::clicked, this, &HapticsPanel::findDevices);
    devices_->addItem(tr("the mouse (no haptic device)"));
    // USB is looked at when the panel is first shown, not at every start of the window.
    feel_->setEnabled(false);
    connect(feel_, &QPushButton::toggled, this, [this](bool on) { on ? start() : stop(); });
    refresh_.setInterval(33);
    connect(&refresh_, &QTimer::timeout, this, &HapticsPanel::refresh);
}

HapticsPanel::~HapticsPanel() {
    stop();
}

bool HapticsPanel::feeling() const {
    return loop_ && loop_->running();
}

bool HapticsPanel::colours() const {
    return show_->currentIndex() > 0 && snapshot_ != nullptr;
}

void HapticsPanel::colour(std::shared_ptr<const mesh::SceneMeshes> frame) {
    if (!colours() || !frame) return;
    colourer_.request({std::move(frame), snapshot_, show_->currentData().toInt()});
}

void HapticsPanel::showEvent(QShowEvent* event) {
    Panel::showEvent(event);
    if (!scanned_) findDevices();
}

void HapticsPanel::findDevices() {
    scanned_ = true;
    std::vector<std::string> notes;
    found_ = haptics::listDevices(&notes);
    const QSignalBlocker quiet(devices_);
    devices_->clear();
    devices_->addItem(tr("the mouse (no haptic device)"));
    for (const haptics::DeviceEntry& d : found_) {
        devices_->addItem(
            QString::fromStdString(d.name + (d.accessible ? "" : " — not accessible")));
        const int row = devices_->count() - 1;
        devices_->setItemData(
            row, plainToolTip(QString::fromStdString(d.accessible ? d.path : d.message)),
            Qt::ToolTipRole);
    }
    QString why;
    for (const std::string& n : notes)
        why += QString::fromStdString(n) + QLatin1Char('\n');
    devices_->setToolTip(plainToolTip(why.trimmed()));
    // Said where the student looks, found or not (Find Devices said nothing).
    std::size_t usable = 0;
    for (const haptics::DeviceEntry& d : found_)
        usable += d.accessible ? 1 : 0;
    notes_->setText(
        found_.empty()
            ? tr("No haptic device found: the mouse stands in (click and drag on a tangible "
                 "shape). A SpaceMouse or Falcon plugged in later: Find Devices again.")
        : usable == found_.size()
            ? tr("Found %n device(s): choose one above.", "", int(found_.size()))
            : tr("Found %1 device(s), %2 not accessible: %3")
                  .arg(found_.size())
                  .arg(found_.size() - usable)
                  .arg(visibleText(why.trimmed())));
}

void HapticsPanel::start() {
    if (feeling() || !tangible_) return;
    haptics::ServoOptions o;
    const int choice = devices_->currentIndex();
    if (choice <= 0 || std::size_t(choice) > found_.size()) {
        // The mouse feels like the common desk device: a Novint Falcon's
        // limits; its device frame is the scene's; a short ramp.
        auto pointer = std::make_unique<haptics::PointerDevice>(
            haptics::limitsOf(haptics::DeviceModel::NovintFalcon));
        pointer_ = pointer.get();
        device_ = std::move(pointer);
        o.rampSeconds = 0.5;
    } else {
        std::string error;
        device_ = haptics::openDevice(found_[std::size_t(choice - 1)], {}, &error);
        if (!device_) {
            notes_->setText(QString::fromStdString(error));
            const QSignalBlocker quiet(feel_);
            feel_->setChecked(false);
            return;
        }
        pointer_ = nullptr;
        // The device's workspace onto the tangible shapes' box.
        const double radius = std::max(device_->limits().workspaceRadius, 1e-3);
        o.workspace.centre = field::scaled(field::plus(tangibleBox_.lo, tangibleBox_.hi), 0.5);
        o.workspace.scale = 0.5 * tangibleBox_.diagonal() / radius;
    }
    maxForce_ = std::max(device_->limits().maxForce, 1.0);
    loop_ = std::make_unique<haptics::ServoLoop>(*device_, o);
    if (snapshot_) loop_->setScene(snapshot_, false);
    loop_->start();
    refresh_.start();
    const QSignalBlocker quiet(feel_);
    feel_->setChecked(true);
}

void HapticsPanel::stop() {
    refresh_.stop();
    if (loop_) loop_->stop();
    loop_.reset();
    pointer_ = nullptr;
    device_.reset();
    status_->setText(tr("stopped"));
    contact_->clear();
    const QSignalBlocker quiet(feel_);
    feel_->setChecked(false);
    Q_EMIT touchChanged(std::nullopt);
}

void HapticsPanel::sceneChanged(std::shared_ptr<const scene::Scene> scene) {
    scene_ = std::move(scene);
    snapshot_.reset();
    const scene::EffectsPlan plan = scene::makeEffectsPlan(*scene_);
    tangible_ = plan.needsHaptics;
    feel_->setEnabled(tangible_);
    if (!tangible_) {
        stop();
        notes_->setText(tr("Nothing in this scene is tangible, so the haptic loop does not run. "
                           "Give an FShape an FPhysics with FFriction, FTension, FDensity or "
                           "FForce to feel it."));
        return;
    }
    notes_->clear();
    // The tangible effects' boxes: how far the mouse's tool presses in, and
    // where a device's workspace goes.
    tangibleBox_ = {{1e300, 1e300, 1e300}, {-1e300, -1e300, -1e300}};
    for (const scene::PlanEntry& e : plan.entries)
        for (const scene::TangibleEffect& t : e.tangible)
            for (std::size_t k = 0; k < 3; ++k) {
                tangibleBox_.lo[k] = std::min(tangibleBox_.lo[k], t.domainMin[k]);
                tangibleBox_.hi[k] = std::max(tangibleBox_.hi[k], t.domainMax[k]);
            }
    if (!tangibleBox_.valid()) tangibleBox_ = {{-1, -1, -1}, {1, 1, 1}};
    sceneSize_ = tangibleBox_.longestSide();
    requestSnapshot();
}

void HapticsPanel::setSceneTime(double seconds) {
    seconds_ = seconds;
    // Shapes that move with time are felt where they are now (20 snapshots a
    // second at most); effects that read t follow the loop's own clock.
    if (tangible_ && geometryVaries_ && std::abs(seconds_ - snapshotSeconds_) > 0.05)
        requestSnapshot();
}

void HapticsPanel::requestSnapshot() {
    if (scene_) worker_.request({scene_, seconds_});
}

void HapticsPanel::touchAt(std::optional<field::Vec3> point, field::Vec3 normal) {
    if (!pointer_) return; // a real device moves itself
    if (!point) return;    // off the shapes: the tool stays where it was
    const double depth = sceneSize_ * 0.02 * depth_->value() / 100.0;
    // The first touch comes from outside, along the normal.
    pointer_->moveTo(field::along(*point, normal, -depth),
                     field::along(*point, normal, 0.01 * sceneSize_));
}

void HapticsPanel::refresh() {
    if (!loop_) return;
    const haptics::ServoStatus s = loop_->status();
    const haptics::JitterFigures j = loop_->jitter();
    status_->setText(tr("%1 Hz, period jitter p99 %2 µs")
                         .arg(s.measuredRateHz, 0, 'f', 0)
                         .arg(j.p99, 0, 'f', 0));
    contact_->setText(
        tr("%1, %2 N").arg(contactText(s.contact)).arg(field::length(s.force), 0, 'f', 2));
    const double maxForce = maxForce_;
    graph_->setForces(loop_->recentForces(), maxForce, std::size_t(loop_->rateHz()));
    TouchMarks marks;
    marks.tool = s.tool;
    marks.proxy = s.proxy;
    marks.force = s.force;
    marks.maxForce = maxForce;
    marks.contact = s.contact != haptics::ContactKind::None;
    Q_EMIT touchChanged(marks);
    QStringList reports;
    for (const std::string& r : loop_->reports())
        reports << QString::fromStdString(r);
    if (!reports.isEmpty()) notes_->setText(reports.join(QLatin1Char('\n')));
}

void HapticsPanel::attach(PanelContext& context) {
    context_ = &context;
    viewer::SceneWidget* view = context.view;
    connect(view, &viewer::SceneWidget::hovered, this, [this](QPointF pixel) {
        if (feeling()) touchPixel(pixel);
    });
    connect(this, &HapticsPanel::touchChanged, this, [view, &context](std::optional<TouchMarks> m) {
        if (!m) {
            view->setTouch(std::nullopt);
            return;
        }
        // In contact, the proxy is a point of the scene the student chose
        // (the classroom's tools go there).
        if (m->contact) Q_EMIT context.pointChosen(m->proxy, -1);
        auto q = [](const field::Vec3& v) {
            return QVector3D(float(v[0]), float(v[1]), float(v[2]));
        };
        view->setTouch(
            viewer::RenderScene::Touch{q(m->tool), q(m->proxy), q(m->force), float(m->maxForce)});
    });
    connect(context.player, &viewer::ScenePlayer::timeChanged, this, &HapticsPanel::setSceneTime);
    // Friction or density as colour: each frame coloured on the panel's worker.
    connect(context.player, &viewer::ScenePlayer::meshesReady, this,
            [this](std::shared_ptr<const mesh::SceneMeshes> frame, double) {
                lastFrame_ = frame;
                if (colours()) colour(frame);
            });
    connect(this, &HapticsPanel::showOnSurfaceChanged, this, [this, view] {
        if (!lastFrame_) return;
        if (colours())
            colour(lastFrame_);
        else
            view->setMeshes(lastFrame_);
    });
    connect(this, &HapticsPanel::frameColoured, this,
            [this, view](std::shared_ptr<const mesh::SceneMeshes> coloured) {
                if (lastFrame_ && coloured->source == lastFrame_->source) view->setMeshes(coloured);
            });
}

void HapticsPanel::touchPixel(QPointF pixel) {
    viewer::SceneWidget* view = context_->view;
    const auto meshes = view->meshes();
    if (!meshes || meshes->source != context_->scene()) return;
    const auto p =
        viewer::pick(*meshes, viewer::rayThroughPixel(view->pose(), view->size(), pixel));
    if (p)
        touchAt(p->point, p->normal);
    else
        touchAt(std::nullopt);
}

} // namespace fl::suite
