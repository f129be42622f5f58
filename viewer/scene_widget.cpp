#include "scene_widget.h"

#include "navigation.h"

#include <QEventLoop>
#include <QKeyEvent>
#include <QMouseEvent>
#include <QTimer>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <Qt3DExtras/Qt3DWindow>
#include <Qt3DRender/QRenderSettings>

namespace fl::viewer {

namespace {
// Qt3DWindow picks Qt3D's RHI renderer unless told otherwise; the surface
// shader is GLSL 3.30 for the OpenGL renderer (as the off-screen path uses).
Qt3DExtras::Qt3DWindow* makeOpenGLWindow() {
    if (qEnvironmentVariableIsEmpty("QT3D_RENDERER")) qputenv("QT3D_RENDERER", "opengl");
    return new Qt3DExtras::Qt3DWindow(nullptr, Qt3DRender::API::OpenGL);
}
} // namespace

SceneWidget::SceneWidget(QWidget* parent)
    : QWidget(parent), window_(makeOpenGLWindow()), root_(new Qt3DCore::QEntity) {
    container_ = QWidget::createWindowContainer(window_, this);
    container_->setMinimumSize(160, 120);
    container_->setFocusPolicy(Qt::StrongFocus);
    auto* layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(container_);

    scene_ = std::make_unique<RenderScene>(root_);
    frameGraph_ = buildFrameGraph(window_, QSize(), Qt::black, scene_->frameParameters(), root_);
    window_->setActiveFrameGraph(frameGraph_.root);
    window_->renderSettings()->setRenderPolicy(Qt3DRender::QRenderSettings::OnDemand);
    window_->setRootEntity(root_);
    window_->installEventFilter(this);
    applyPose();
}

SceneWidget::~SceneWidget() = default;

namespace {

bool samePose(const std::optional<mesh::ViewPoint>& a, const std::optional<mesh::ViewPoint>& b) {
    if (!a || !b) return a.has_value() == b.has_value();
    return a->position == b->position && a->direction == b->direction && a->up == b->up &&
           a->fieldOfView == b->fieldOfView && a->centerOfRotation == b->centerOfRotation;
}

} // namespace

QWindow* SceneWidget::renderWindow() const {
    return window_;
}

float SceneWidget::aspect() const {
    const QSize s = window_->size();
    return s.height() > 0 ? float(s.width()) / float(s.height()) : 4.0f / 3.0f;
}

void SceneWidget::setMeshes(std::shared_ptr<const mesh::SceneMeshes> meshes) {
    meshes_ = std::move(meshes);
    if (!meshes_) return;
    scene_->setMeshes(meshes_);
    triangles_ = 0;
    for (const auto& s : meshes_->shapes)
        triangles_ += s.mesh.triangleCount();
    const auto& sky = meshes_->view.background;
    frameGraph_.clear->setClearColor(QColor::fromRgbF(sky[0], sky[1], sky[2]));
    const auto& view = meshes_->view;
    const int bound = view.boundViewpoint;
    const std::optional<mesh::ViewPoint> boundPose =
        bound >= 0 ? std::optional(view.viewpoints[std::size_t(bound)]) : std::nullopt;
    if (!cameraPlaced_) {
        cameraPlaced_ = true;
        bindViewpoint(bound);
    } else if (bound != sceneBound_) {
        bindViewpoint(bound); // a set_bind event
    } else if (bound >= 0 && boundViewpoint_ == bound && !samePose(boundPose, sceneBoundPose_)) {
        bindViewpoint(bound); // an animated viewpoint carries the camera
    }
    sceneBound_ = bound;
    sceneBoundPose_ = boundPose;
    // NavigationInfo: its first type says how one moves (WALK and FLY walk).
    const std::vector<std::string> types =
        view.hasNavigation ? view.navigation.types : std::vector<std::string>{};
    if (types != sceneNavigationTypes_ && !types.empty()) {
        const Navigation n = types.front() == "WALK" || types.front() == "FLY"
                                 ? Navigation::Walk
                                 : Navigation::Examine;
        if (n != navigation_) {
            setNavigation(n);
            Q_EMIT navigationBound(n);
        }
    }
    sceneNavigationTypes_ = types;
}

QStringList SceneWidget::viewpointNames() const {
    QStringList names;
    if (meshes_)
        for (const auto& v : meshes_->view.viewpoints)
            names << QString::fromStdString(v.name);
    return names;
}

void SceneWidget::bindViewpoint(int index) {
    boundViewpoint_ = index;
    const Bounds& b = scene_->bounds();
    if (meshes_ && index >= 0 && index < int(meshes_->view.viewpoints.size()))
        pose_ = poseForViewpoint(meshes_->view.viewpoints[std::size_t(index)], b, aspect());
    else
        pose_ = poseToFit(b, aspect());
    applyPose();
}

void SceneWidget::resetView() {
    bindViewpoint(boundViewpoint_);
}

void SceneWidget::setNavigation(Navigation n) {
    navigation_ = n;
}

void SceneWidget::setPose(const CameraPose& pose) {
    pose_ = pose;
    applyPose();
}

void SceneWidget::setClipPlane(std::optional<QVector4D> plane) {
    scene_->setClipPlane(plane);
}

void SceneWidget::applyPose() {
    viewer::applyPose(frameGraph_.camera, pose_, aspect());
    Q_EMIT poseChanged();
}

QImage SceneWidget::grabFrame(int timeoutMs) {
    QImage image;
    QEventLoop loop;
    Qt3DRender::QRenderCaptureReply* reply = frameGraph_.capture->requestCapture();
    connect(reply, &Qt3DRender::QRenderCaptureReply::completed, &loop, [&] {
        image = reply->image();
        loop.quit();
    });
    QTimer::singleShot(timeoutMs, &loop, &QEventLoop::quit);
    loop.exec();
    reply->deleteLater();
    return image;
}

bool SceneWidget::eventFilter(QObject* watched, QEvent* event) {
    if (watched != window_) return QWidget::eventFilter(watched, event);
    switch (event->type()) {
    case QEvent::Resize:
        applyPose(); // the aspect changed
        break;
    case QEvent::MouseButtonPress: {
        auto* e = static_cast<QMouseEvent*>(event);
        lastMouse_ = pressedAt_ = e->position().toPoint();
        buttons_ = e->buttons();
        container_->setFocus();
        return true;
    }
    case QEvent::MouseButtonRelease: {
        auto* e = static_cast<QMouseEvent*>(event);
        buttons_ = e->buttons();
        if (e->button() == Qt::LeftButton &&
            (e->position().toPoint() - pressedAt_).manhattanLength() < 4)
            Q_EMIT clicked(e->position());
        return true;
    }
    case QEvent::MouseMove: {
        auto* e = static_cast<QMouseEvent*>(event);
        const QPoint p = e->position().toPoint();
        const QPoint d = p - lastMouse_;
        lastMouse_ = p;
        if (!e->buttons()) {
            Q_EMIT hovered(e->position());
            return false;
        }
        if (navigation_ == Navigation::Walk)
            pose_ = look(pose_, float(d.x()) * 0.005f, -float(d.y()) * 0.005f);
        else if (e->buttons() & Qt::LeftButton)
            pose_ = orbit(pose_, float(d.x()), float(d.y()), window_->size());
        else
            pose_ = pan(pose_, float(d.x()), float(d.y()), window_->size());
        applyPose();
        return true;
    }
    case QEvent::Wheel: {
        auto* e = static_cast<QWheelEvent*>(event);
        const float steps = float(e->angleDelta().y()) / 120.0f;
        if (navigation_ == Navigation::Walk)
            pose_ = walk(pose_, steps * 0.5f * std::max(scene_->bounds().radius() * 0.1f, 0.1f), 0);
        else
            pose_ = zoom(pose_, steps);
        applyPose();
        return true;
    }
    case QEvent::KeyPress: {
        auto* e = static_cast<QKeyEvent*>(event);
        const float step = std::max(scene_->bounds().radius() * 0.05f, 0.05f);
        float forward = 0, right = 0, yaw = 0;
        switch (e->key()) {
        case Qt::Key_W:
        case Qt::Key_Up:
            forward = step;
            break;
        case Qt::Key_S:
        case Qt::Key_Down:
            forward = -step;
            break;
        case Qt::Key_A:
            right = -step;
            break;
        case Qt::Key_D:
            right = step;
            break;
        case Qt::Key_Left:
            yaw = -0.05f;
            break;
        case Qt::Key_Right:
            yaw = 0.05f;
            break;
        default:
            return false;
        }
        if (navigation_ == Navigation::Walk)
            pose_ = look(walk(pose_, forward, right), yaw, 0);
        else
            pose_ = zoom(orbit(pose_, yaw * 400, 0, QSize(800, 600)), forward / step);
        applyPose();
        return true;
    }
    default:
        break;
    }
    return QWidget::eventFilter(watched, event);
}

} // namespace fl::viewer
