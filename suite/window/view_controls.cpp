#include "view_controls.h"

#include "mesh/scene_meshing.h"
#include "timeline_bar.h"
#include "viewer/scene_widget.h"
#include "viewpoint_box.h"

#include <QAction>
#include <QActionGroup>
#include <QCheckBox>
#include <QComboBox>
#include <QLabel>
#include <QMenu>
#include <QPushButton>
#include <QSlider>
#include <QToolBar>
#include <QToolButton>
#include <QVector4D>

namespace fl::suite {

ViewControls::ViewControls(viewer::SceneWidget* view, TimelineBar* timeline,
                           ViewpointBox* viewpoints, QObject* parent)
    : QObject(parent), view_(view), timeline_(timeline), viewpoints_(viewpoints) {}

void ViewControls::fillMenu(QMenu* menu) {
    auto* group = new QActionGroup(this);
    QAction* examine = menu->addAction(tr("&Examine (orbit, pan, zoom)"), this, [this] {
        view_->setNavigation(viewer::SceneWidget::Navigation::Examine);
    });
    QAction* walkMode = menu->addAction(tr("&Walk (first person)"), this, [this] {
        view_->setNavigation(viewer::SceneWidget::Navigation::Walk);
    });
    examine_ = examine;
    walk_ = walkMode;
    for (QAction* a : {examine, walkMode}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    examine->setChecked(true);
    menu->addAction(tr("&Reset View"), QKeySequence(Qt::Key_Home), view_,
                    &viewer::SceneWidget::resetView);
    menu->addSeparator();
    auto* drawGroup = new QActionGroup(this);
    const std::pair<QString, viewer::DrawAs> modes[] = {{tr("&Shaded"), viewer::DrawAs::Faces},
                                                        {tr("&Wireframe"), viewer::DrawAs::Edges},
                                                        {tr("&Points"), viewer::DrawAs::Vertices}};
    for (const auto& [name, mode] : modes) {
        QAction* a = menu->addAction(name, this, [this, mode = mode] { view_->setDrawAs(mode); });
        a->setCheckable(true);
        a->setChecked(mode == viewer::DrawAs::Faces);
        drawGroup->addAction(a);
    }
    QAction* domains = menu->addAction(tr("Show &Domain Boxes"), this,
                                       [this](bool on) { view_->setShowDomains(on); });
    domains->setCheckable(true);
    menu->addAction(tr("&Play / Pause"), QKeySequence(Qt::CTRL | Qt::Key_Space), this,
                    [this] { timeline_->playButton()->toggle(); });
}

void ViewControls::fillToolBar(QToolBar* bar) {
    bar->addWidget(new QLabel(tr(" Viewpoint ")));
    bar->addWidget(viewpoints_);
    // A cross-section: everything beyond a plane across x, y or z is cut away.
    bar->addSeparator();
    auto* cut = new QCheckBox(tr("Cut"));
    cut->setObjectName(QStringLiteral("cut"));
    auto* cutAxis = new QComboBox;
    cutAxis->addItems({QStringLiteral("x"), QStringLiteral("y"), QStringLiteral("z")});
    cutAxis->setCurrentIndex(2);
    auto* cutAt = new QSlider(Qt::Horizontal);
    cutAt->setObjectName(QStringLiteral("cut-position"));
    cutAt->setRange(0, 1000);
    cutAt->setValue(500);
    cutAt->setMaximumWidth(200);
    cutAt->setToolTip(tr("Where the cut goes, across the scene's bounds"));
    bar->addWidget(cut);
    bar->addWidget(cutAxis);
    bar->addWidget(cutAt);
    auto applyCut = [this, cut, cutAxis, cutAt] {
        if (!cut->isChecked()) {
            view_->setClipPlane(std::nullopt);
            return;
        }
        const int axis = cutAxis->currentIndex();
        const viewer::Bounds& b = view_->bounds();
        const float lo = b.empty() ? -1 : b.lo[axis], hi = b.empty() ? 1 : b.hi[axis];
        const float at = lo + (hi - lo) * float(cutAt->value()) / 1000.0f;
        QVector4D plane(0, 0, 0, at);
        plane[axis] = -1; // keep where the coordinate is below `at`
        view_->setClipPlane(plane);
    };
    connect(cut, &QCheckBox::toggled, this, applyCut);
    connect(cutAxis, &QComboBox::currentIndexChanged, this, applyCut);
    connect(cutAt, &QSlider::valueChanged, this, applyCut);
    connect(viewpoints_, &ViewpointBox::viewpointChosen, view_,
            [this](int index) { view_->bindViewpoint(index); });
}

void ViewControls::navigateAsTheSceneSays(const mesh::SceneMeshes& meshes) {
    const auto& types = meshes.view.navigation.types;
    const bool walk = meshes.view.hasNavigation && !types.empty() &&
                      (types.front() == "WALK" || types.front() == "FLY");
    (walk ? walk_ : examine_)->trigger();
}

} // namespace fl::suite
