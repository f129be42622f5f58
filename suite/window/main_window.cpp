#include "main_window.h"

#include "accuracy_panel.h"
#include "assignment_panel.h"
#include "checker.h"
#include "classroom_panel.h"
#include "client.h"
#include "code_editor.h"
#include "examples.h"
#include "examples_dock.h"
#include "field/affine.h"
#include "find_bar.h"
#include "grading_panel.h"
#include "hand_in.h"
#include "haptics_panel.h"
#include "issues_dock.h"
#include "level_of_detail_control.h"
#include "live_parser.h"
#include "mesh/mesh_export.h"
#include "mesh/scene_meshing.h"
#include "mesh_geometry.h"
#include "parameters_dock.h"
#include "picking.h"
#include "plain_text.h"
#include "render_scene.h"
#include "scene/field_access.h"
#include "scene/gzip.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"
#include "scene_player.h"
#include "scene_policy.h"
#include "scene_text_dock.h"
#include "scene_tree_dock.h"
#include "scene_widget.h"
#include "screen_error_meter.h"
#include "text_outliner.h"
#include "timeline_bar.h"
#include "viewpoint_box.h"

#include <QAction>
#include <QActionGroup>
#include <QApplication>
#include <QCheckBox>
#include <QCloseEvent>
#include <QComboBox>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFileDialog>
#include <QFileInfo>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QMenuBar>
#include <QMessageBox>
#include <QSaveFile>
#include <QScreen>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTabBar>
#include <QTextCursor>
#include <QToolBar>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>

#include <cmath>

namespace fl::suite {
namespace {

constexpr int kMaxRecent = 8;
constexpr qint64 kMaxFileBytes = 64ll << 20;

const char* kNewScene = R"(<?xml version="1.0" encoding="UTF-8"?>
<X3D profile='Immersive' version='3.3'>
  <Scene>
    <Viewpoint description='Front' position='0 0 4'/>
    <FShape>
      <FGeometry definition='"1 - x^2 - y^2 - z^2"'/>
      <FAppearance>
        <FMaterial type='parametric' definition='"r = 0.5 + 0.5*x;" "g = 0.6;" "b = 0.5 - 0.5*x;"'/>
      </FAppearance>
    </FShape>
  </Scene>
</X3D>
)";

// The longest cycle among the scene's timed nodes (TimeSensors and function
// nodes), within 1 .. 120 s: what the time slider spans.
double timelineSpan(const scene::Scene& scene) {
    double span = 0;
    scene.forEachNode([&](const scene::Node& n) {
        if (n.inProtoBody || !n.spec || !scene::findFieldSpec(*n.spec, "cycleInterval")) return;
        span = std::max(span, scene::numberField(n, "cycleInterval", 0, 1));
    });
    return span > 0 ? std::clamp(span, 1.0, 120.0) : 10.0;
}

} // namespace

MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), editor_(new editor::CodeEditor), find_(new editor::FindBar(editor_)),
      parser_(new editor::LiveParser(this)), view_(new viewer::SceneWidget),
      player_(new viewer::ScenePlayer(nullptr, this)), timeline_(new TimelineBar(player_)),
      viewpoints_(new ViewpointBox), recentMenu_(nullptr), triangles_(new QLabel),
      meshTime_(new QLabel), frameRate_(new QLabel), timeLabel_(new QLabel),
      screenError_(plainLabel()), errorMeter_(new ScreenErrorMeter(this)) {
    setWindowTitle(QStringLiteral("FunctionLab[*]"));
    setCentralWidget(view_);
    buildContext();
    buildMenus();
    buildDocks();
    context_.fileMenu->addSeparator();
    context_.fileMenu->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    auto* timeBar = new QToolBar(tr("Timeline"));
    timeBar->setObjectName(QStringLiteral("timeline"));
    timeBar->addWidget(timeline_);
    addToolBar(Qt::BottomToolBarArea, timeBar);

    for (QLabel* l : {triangles_, meshTime_, screenError_, frameRate_, timeLabel_})
        statusBar()->addPermanentWidget(l);
    connect(errorMeter_, &ScreenErrorMeter::measured, screenError_,
            [this](const QString& text) { screenError_->setText(visibleText(text)); });

    connect(editor_, &QPlainTextEdit::textChanged, this, [this] {
        parser_->setText(editor_->toPlainText(), path_);
        recoveryTimer_.start();
        setWindowModified(isModified());
    });
    connect(parser_, &editor::LiveParser::parsed, this, &MainWindow::parsed);
    connect(parser_, &editor::LiveParser::sceneChanged, this, &MainWindow::sceneChanged);
    connect(player_, &viewer::ScenePlayer::meshesReady, this, &MainWindow::meshesReady);
    connect(player_, &viewer::ScenePlayer::timeChanged, this, [this](double s) {
        timeline_->showTime(s);
        timeLabel_->setText(QStringLiteral("t = %1 s").arg(s, 0, 'f', 2));
    });

    recoveryTimer_.setSingleShot(true);
    recoveryTimer_.setInterval(2000);
    connect(&recoveryTimer_, &QTimer::timeout, this, &MainWindow::writeRecovery);
    rateTimer_.setInterval(1000);
    connect(&rateTimer_, &QTimer::timeout, this, [this] {
        const std::size_t frames = player_->framesDelivered();
        frameRate_->setText(tr("%1 frames/s").arg(frames - framesAtLastRate_));
        framesAtLastRate_ = frames;
    });
    rateTimer_.start();

    // Level of detail: a moment after the camera moves, shapes whose wanted
    // resolution left its band are meshed again (in the background).
    lod_ = std::make_unique<viewer::LevelOfDetail>();
    lodTimer_.setSingleShot(true);
    lodTimer_.setInterval(150);
    connect(view_, &viewer::SceneWidget::poseChanged, this, [this] { lodTimer_.start(); });
    // A click names the point under the cursor: on the function itself where
    // the shape is implicit or explicit.
    connect(view_, &viewer::SceneWidget::clicked, this, [this](QPointF pixel) {
        const auto meshes = view_->meshes();
        if (!meshes) return;
        const auto p =
            viewer::pick(*meshes, viewer::rayThroughPixel(view_->pose(), view_->size(), pixel));
        if (!p) {
            view_->setMarker(std::nullopt);
            statusBar()->showMessage(tr("Nothing there"), 3000);
            return;
        }
        view_->setMarker(QVector3D(float(p->point[0]), float(p->point[1]), float(p->point[2])));
        Q_EMIT context_.pointChosen(p->point, int(p->shapeIndex)); // the classroom's tools
        // A TouchSensor over the shape hears the click (the fan starts).
        if (meshes->source == scene_)
            for (const scene::Node* sensor : p->touchSensors)
                player_->touch(*sensor);
        statusBar()->showMessage(tr("(%1, %2, %3) on %4%5")
                                     .arg(p->point[0], 0, 'g', 6)
                                     .arg(p->point[1], 0, 'g', 6)
                                     .arg(p->point[2], 0, 'g', 6)
                                     .arg(visibleText(QString::fromStdString(p->shape)))
                                     .arg(p->onFunction ? tr(", on f = 0") : QString()));
    });
    connect(&lodTimer_, &QTimer::timeout, this, [this] {
        // Only meshes of the scene being played: their nodes are the player's keys.
        const auto meshes = view_->meshes();
        if (meshes && meshes->source == scene_ &&
            lod_->update(*meshes, view_->pose(), view_->size()))
            playResolutions();
    });
    // The status bar's error figure follows the shape under the resting cursor.
    hoverTimer_.setSingleShot(true);
    hoverTimer_.setInterval(200);
    connect(view_, &viewer::SceneWidget::hovered, this, [this](QPointF pixel) {
        hoverPixel_ = pixel;
        hoverTimer_.start();
    });
    connect(&hoverTimer_, &QTimer::timeout, this, [this] {
        const auto meshes = view_->meshes();
        if (!meshes || meshes->source != scene_) return;
        const auto p = viewer::pick(
            *meshes, viewer::rayThroughPixel(view_->pose(), view_->size(), hoverPixel_));
        errorMeter_->focusOn(p ? meshes->shapes[p->shapeIndex].shape : nullptr);
    });

    QSettings settings;
    restoreGeometry(settings.value(QStringLiteral("window/geometry")).toByteArray());
    restoreState(settings.value(QStringLiteral("window/state")).toByteArray());
    fillRecentMenu();
    // Never taller or wider than the screen: on a 1366×768 laptop the status
    // bar with its error figure stays in sight (room left for the title bar).
    QSize wanted = settings.contains(QStringLiteral("window/geometry")) ? size() : QSize(1280, 800);
    if (const QScreen* s = screen())
        wanted = wanted.boundedTo(s->availableGeometry().size() - QSize(0, 32));
    resize(wanted);
}

MainWindow::~MainWindow() {
    // The panels go first, while what they were handed (context_, the
    // editor, the parser) is still there: one leaving a class on its way
    // out still talks to the parser.
    qDeleteAll(panels_);
    panels_.clear();
}

void MainWindow::dockPanel(Panel* panel, bool tabbed) {
    panel->setParent(this);
    Panel* beside = nullptr; // the last panel added on that side
    for (Panel* p : panels_)
        if (p->area() == panel->area()) beside = p;
    addDockWidget(panel->area(), panel);
    if (tabbed && beside) tabifyDockWidget(beside, panel);
    panels_.push_back(panel);
    panel->attach(context_);
}

void MainWindow::buildContext() {
    context_.window = this;
    context_.editor = editor_;
    context_.parser = parser_;
    context_.view = view_;
    context_.player = player_;
    context_.status = statusBar();
    context_.keepChanges = [this] { return maybeKeepChanges(); };
    context_.open = [this](const QString& path) { return openFile(path); };
    context_.goTo = [this](int line, int column) { editor_->goTo(line, column); };
    context_.problem = [this](const QString& text) { problem(text); };
    context_.path = [this] { return path_; };
    context_.forgetPath = [this] { setPath(QString()); };
    context_.scene = [this] { return scene_; };
    context_.textParses = [this] { return textParses_; };
    context_.showScene = [this](std::shared_ptr<const scene::Scene> scene) { sceneChanged(scene); };
    context_.chooseResolution = [this](const scene::Node* geometry, double resolution) {
        chosenResolutions_[geometry] = resolution;
        playResolutions();
    };
    context_.prompts = [this] { return prompts_; };
}

QListWidget* MainWindow::issues() const {
    return issues_->list();
}

QTreeWidget* MainWindow::sceneTree() const {
    return tree_->tree();
}

QWidget* MainWindow::parametersPanel() const {
    return parameters_;
}

QListWidget* MainWindow::examples() const {
    return examples_->list();
}

void MainWindow::buildDocks() {
    // The layout: the scene's text and its tree on the left, the 3D view in
    // the middle and the largest thing on screen, the other panels on the
    // right as one bar whose tabs run down its edge, so that every panel's
    // name reads in full (seven tabs across a dock read "Sce…", "Ex…"); the
    // issues strip only while there are issues. It fits 1366×768.
    setTabPosition(Qt::RightDockWidgetArea, QTabWidget::East);
    // The sides run the full height, so the issues strip lies under the view
    // alone and never shortens the panel bar.
    setCorner(Qt::BottomLeftCorner, Qt::LeftDockWidgetArea);
    setCorner(Qt::BottomRightCorner, Qt::RightDockWidgetArea);
    auto* text = addPanel(new SceneTextDock(editor_, find_));
    tree_ = addPanel(new SceneTreeDock, true);
    text->raise();
    issues_ = addPanel(new IssuesDock);
    issues_->hide(); // IssuesDock::showDiagnostics shows it when there are some
    // Sized once the window has its layout (a saved state wins): the sides
    // take about a quarter and a fifth of the width, the view the rest.
    QTimer::singleShot(0, this, [this, text] {
        if (!QSettings().contains(QStringLiteral("window/state"))) {
            resizeDocks({issues_}, {110}, Qt::Vertical);
            resizeDocks({text, examples_},
                        {std::clamp(width() * 27 / 100, 330, 520),
                         std::clamp(width() * 21 / 100, 290, 420)},
                        Qt::Horizontal);
        }
    });
    examples_ = addPanel(new ExamplesDock);
    parameters_ = addPanel(new ParametersDock, true);
    assignment_ = addPanel(new AssignmentPanel, true);
    accuracy_ = addPanel(new AccuracyPanel, true);
    haptics_ = addPanel(new HapticsPanel, true);
    classroom_ = addPanel(new ClassroomPanel, true);
    grading_ = addPanel(new GradingPanel);
    examples_->raise();
    // Tab titles are never cut short; should a screen be too short for the
    // bar, it scrolls rather than squeezing the view.
    QTimer::singleShot(0, this, [this] {
        for (QTabBar* bar : findChildren<QTabBar*>()) {
            bar->setUsesScrollButtons(true);
            bar->setElideMode(Qt::ElideNone);
        }
    });
}

void MainWindow::buildMenus() {
    QMenu* file = menuBar()->addMenu(tr("&File"));
    file->addAction(tr("&New"), QKeySequence::New, this, [this] {
        if (maybeKeepChanges()) newScene();
    });
    file->addAction(tr("&Open…"), QKeySequence::Open, this, &MainWindow::openDialog);
    recentMenu_ = file->addMenu(tr("Open &Recent"));
    file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save);
    file->addAction(tr("Save &As…"), QKeySequence::SaveAs, this, &MainWindow::saveAs);
    file->addSeparator();
    file->addAction(tr("Export &Mesh…"), this, &MainWindow::exportMesh);
    file->addAction(tr("Export &Image…"), this, &MainWindow::exportImage);
    file->addSeparator(); // the panels' actions (Hand In, Join Class), then Quit
    context_.fileMenu = file;
    context_.courseMenu = menuBar()->addMenu(tr("&Course"));

    QMenu* edit = menuBar()->addMenu(tr("&Edit"));
    edit->addAction(tr("&Undo"), QKeySequence::Undo, editor_, &QPlainTextEdit::undo);
    edit->addAction(tr("&Redo"), QKeySequence::Redo, editor_, &QPlainTextEdit::redo);
    edit->addSeparator();
    edit->addAction(tr("&Find…"), QKeySequence::Find, this, [this] { find_->open(false); });
    edit->addAction(tr("&Replace…"), QKeySequence::Replace, this, [this] { find_->open(true); });

    QMenu* view = menuBar()->addMenu(tr("&View"));
    auto* group = new QActionGroup(this);
    QAction* examine = view->addAction(tr("&Examine (orbit, pan, zoom)"), this, [this] {
        view_->setNavigation(viewer::SceneWidget::Navigation::Examine);
    });
    QAction* walkMode = view->addAction(tr("&Walk (first person)"), this, [this] {
        view_->setNavigation(viewer::SceneWidget::Navigation::Walk);
    });
    examineAction_ = examine;
    walkAction_ = walkMode;
    for (QAction* a : {examine, walkMode}) {
        a->setCheckable(true);
        group->addAction(a);
    }
    examine->setChecked(true);
    view->addAction(tr("&Reset View"), QKeySequence(Qt::Key_Home), view_,
                    &viewer::SceneWidget::resetView);
    view->addSeparator();
    auto* drawGroup = new QActionGroup(this);
    const std::pair<QString, viewer::DrawAs> modes[] = {{tr("&Shaded"), viewer::DrawAs::Faces},
                                                        {tr("&Wireframe"), viewer::DrawAs::Edges},
                                                        {tr("&Points"), viewer::DrawAs::Vertices}};
    for (const auto& [name, mode] : modes) {
        QAction* a = view->addAction(name, this, [this, mode = mode] { view_->setDrawAs(mode); });
        a->setCheckable(true);
        a->setChecked(mode == viewer::DrawAs::Faces);
        drawGroup->addAction(a);
    }
    QAction* domains = view->addAction(tr("Show &Domain Boxes"), this,
                                       [this](bool on) { view_->setShowDomains(on); });
    domains->setCheckable(true);
    view->addAction(tr("&Play / Pause"), QKeySequence(Qt::CTRL | Qt::Key_Space), this,
                    [this] { timeline_->playButton()->toggle(); });

    auto* viewBar = addToolBar(tr("View"));
    viewBar->setObjectName(QStringLiteral("view"));
    viewBar->addWidget(new QLabel(tr(" Viewpoint ")));
    viewBar->addWidget(viewpoints_);
    // A cross-section: everything beyond a plane across x, y or z is cut away.
    viewBar->addSeparator();
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
    viewBar->addWidget(cut);
    viewBar->addWidget(cutAxis);
    viewBar->addWidget(cutAt);
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

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About FunctionLab"), this, [this] {
        QMessageBox::about(this, tr("About FunctionLab"),
                           tr("FunctionLab %1: function-defined 3D objects for teaching.")
                               .arg(QCoreApplication::applicationVersion()));
    });
}

QString MainWindow::screenErrorText() const {
    return screenError_->text();
}

bool MainWindow::busy() const {
    return parser_->pending() || player_->busy() || lodTimer_.isActive() || errorMeter_->busy() ||
           std::any_of(panels_.begin(), panels_.end(), [](const Panel* p) { return p->busy(); });
}

bool MainWindow::isModified() const {
    return editor_->document()->isModified();
}

void MainWindow::setPath(const QString& path) {
    path_ = path;
    setWindowFilePath(path.isEmpty() ? tr("untitled.x3d") : path);
    setWindowTitle(QStringLiteral("%1[*] — FunctionLab")
                       .arg(path.isEmpty() ? tr("untitled.x3d") : QFileInfo(path).fileName()));
    editor_->setSyntax(
        editor::syntaxFor(path.isEmpty() ? QStringLiteral("a.x3d") : path, editor_->toPlainText()));
}

void MainWindow::newScene() {
    setPath({});
    firstFrameOfScene_ = true;
    editor_->setPlainText(QString::fromUtf8(kNewScene));
    editor_->document()->setModified(false);
    parser_->parseNow();
}

bool MainWindow::openFile(const QString& path, QString* error) {
    QFile f(path);
    QString problemText;
    if (!f.open(QIODevice::ReadOnly))
        problemText = tr("Cannot open %1: %2").arg(path, f.errorString());
    else if (f.size() > kMaxFileBytes)
        problemText =
            tr("%1 is larger than 64 MiB; FunctionLab does not edit files this big").arg(path);
    if (!problemText.isEmpty()) {
        if (error) *error = problemText;
        problem(problemText);
        return false;
    }
    QByteArray bytes = f.read(kMaxFileBytes + 1); // a device without a size cannot run on
    if (bytes.size() > kMaxFileBytes) {
        problemText =
            tr("%1 is larger than 64 MiB; FunctionLab does not edit files this big").arg(path);
        if (error) *error = problemText;
        problem(problemText);
        return false;
    }
    // Compressed scenes (.x3dz, .wrl.gz) are shown as the text they hold
    // (saved uncompressed).
    if (scene::isGzip(std::string_view(bytes.constData(), std::size_t(bytes.size())))) {
        std::string why;
        auto text = scene::gunzip(std::string_view(bytes.constData(), std::size_t(bytes.size())),
                                  std::size_t(kMaxFileBytes), why);
        if (!text) {
            problemText = tr("Cannot read %1: %2").arg(path, QString::fromStdString(why));
            if (error) *error = problemText;
            problem(problemText);
            return false;
        }
        bytes = QByteArray::fromStdString(*text);
    }
    setPath(path);
    firstFrameOfScene_ = true;
    editor_->setPlainText(QString::fromUtf8(bytes));
    editor_->document()->setModified(false);
    setWindowModified(false);
    addRecent(path);
    parser_->setText(editor_->toPlainText(), path_);
    parser_->parseNow();
    QSettings().setValue(QStringLiteral("file/last"), path);
    return true;
}

bool MainWindow::saveTo(const QString& path, QString* error) {
    QSaveFile out(path);
    if (!out.open(QIODevice::WriteOnly) || out.write(editor_->toPlainText().toUtf8()) < 0 ||
        !out.commit()) {
        const QString text = tr("Cannot save %1: %2").arg(path, out.errorString());
        if (error) *error = text;
        problem(text);
        return false;
    }
    setPath(path);
    editor_->document()->setModified(false);
    setWindowModified(false);
    addRecent(path);
    QFile::remove(recoveryPath());
    return true;
}

bool MainWindow::save() {
    return path_.isEmpty() ? saveAs() : saveTo(path_);
}

bool MainWindow::saveAs() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save scene"), path_.isEmpty() ? QDir::homePath() : path_,
        tr("X3D scenes (*.x3d);;ClassicVRML (*.x3dv);;VRML97 (*.wrl)"));
    return !path.isEmpty() && saveTo(path);
}

void MainWindow::openDialog() {
    if (!maybeKeepChanges()) return;
    const QString path = QFileDialog::getOpenFileName(
        this, tr("Open scene"), path_.isEmpty() ? examplesFolder() : QFileInfo(path_).path(),
        tr("Scenes (%1);;All files (*)").arg(QString::fromStdString(scene::sceneFilePatterns())));
    if (!path.isEmpty()) openFile(path);
}

bool MainWindow::maybeKeepChanges() {
    if (!isModified() || !prompts_) return true;
    const auto answer = QMessageBox::question(
        this, tr("Unsaved changes"), tr("The scene has changes that are not saved. Save them?"),
        QMessageBox::Save | QMessageBox::Discard | QMessageBox::Cancel);
    if (answer == QMessageBox::Cancel) return false;
    if (answer == QMessageBox::Save) return save();
    return true;
}

void MainWindow::problem(const QString& text) {
    lastProblem_ = text;
    statusBar()->showMessage(visibleText(text), 10000);
    if (prompts_) warnPlainly(this, tr("FunctionLab"), text);
}

void MainWindow::addRecent(const QString& path) {
    QSettings settings;
    QStringList recent = settings.value(QStringLiteral("file/recent")).toStringList();
    recent.removeAll(path);
    recent.prepend(path);
    while (recent.size() > kMaxRecent)
        recent.removeLast();
    settings.setValue(QStringLiteral("file/recent"), recent);
    fillRecentMenu();
}

void MainWindow::fillRecentMenu() {
    if (!recentMenu_) return;
    recentMenu_->clear();
    const QStringList recent = QSettings().value(QStringLiteral("file/recent")).toStringList();
    for (const QString& path : recent)
        recentMenu_
            // '&' in a file name is not a keyboard accelerator.
            ->addAction(QFileInfo(path).fileName().replace(QLatin1Char('&'), QStringLiteral("&&")),
                        this,
                        [this, path] {
                            if (maybeKeepChanges()) openFile(path);
                        })
            ->setToolTip(plainToolTip(path));
    recentMenu_->setEnabled(!recent.isEmpty());
}

void MainWindow::parsed(const editor::ParseOutcome& outcome) {
    editor_->setDiagnostics(outcome.inThisFile);
    textParses_ = outcome.scene != nullptr;
    if (!outcome.scene)
        statusBar()->showMessage(tr("The text has errors: the view shows the last good scene"));
    else
        statusBar()->clearMessage();
}

void MainWindow::sceneChanged(std::shared_ptr<const scene::Scene> scene) {
    scene_ = scene;
    for (Panel* panel : panels_)
        panel->sceneChanged(scene);
    timeline_->setSpan(timelineSpan(*scene));
    player_->setParameters(parameters_->values());
    lod_->clear();
    chosenResolutions_.clear(); // they name the old scene's nodes
    errorMeter_->focusOn(nullptr);
    view_->setMarker(std::nullopt); // it marked a point of the old shapes
    player_->setScene(scene);
}

void MainWindow::playResolutions() {
    // The level of detail's resolutions, but a shape whose resolution was
    // chosen in the Accuracy panel keeps that choice.
    auto resolutions = lod_->resolutions();
    for (const auto& [geometry, resolution] : chosenResolutions_)
        resolutions[geometry] = resolution;
    player_->setResolutions(std::move(resolutions));
}

void MainWindow::meshesReady(std::shared_ptr<const mesh::SceneMeshes> meshes, double) {
    // A scene's NavigationInfo picks how one moves through it, once, when it opens.
    if (meshes->source == scene_ && meshes->source != lodScene_) { // a new scene's first frame
        lodScene_ = meshes->source;
        lodPending_ = true;
    }
    if (firstFrameOfScene_) {
        firstFrameOfScene_ = false;
        view_->placeCameraOnNextMeshes();
        const auto& types = meshes->view.navigation.types;
        const bool walk = meshes->view.hasNavigation && !types.empty() &&
                          (types.front() == "WALK" || types.front() == "FLY");
        (walk ? walkAction_ : examineAction_)->trigger();
    }
    view_->setMeshes(meshes);
    viewpoints_->showViewpoints(view_->viewpointNames());
    double ms = 0;
    for (const auto& s : meshes->shapes)
        ms += s.stats.milliseconds;
    triangles_->setText(tr("%1 triangles").arg(view_->triangleCount()));
    meshTime_->setText(tr("meshed in %1 ms").arg(ms, 0, 'f', 0));
    errorMeter_->measure(meshes);
    if (lodPending_) { // the first frame of a scene is at the file's resolutions
        lodPending_ = false;
        lodTimer_.start();
    }
}

void MainWindow::exportMesh() {
    if (!scene_) return problem(tr("There is no scene to export yet: fix the errors listed first"));
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Export mesh"), QDir::homePath(),
        tr("glTF binary (*.glb);;STL (*.stl);;OBJ (*.obj);;PLY (*.ply);;X3D (*.x3d)"));
    if (path.isEmpty()) return;
    mesh::SceneMeshOptions o;
    o.sceneSeconds = player_->sceneSeconds();
    o.parameters = parameters_->values();
    o.text = viewer::qtTextOutliner();
    const mesh::SceneMeshes meshes = mesh::meshScene(*scene_, o);
    std::string error;
    if (!mesh::writeMesh(mesh::mergeMeshes(meshes.shapes), path.toStdString(), error))
        problem(QString::fromStdString(error));
    else
        statusBar()->showMessage(tr("Wrote %1").arg(path), 5000);
}

void MainWindow::exportImage() {
    const QString path = QFileDialog::getSaveFileName(this, tr("Export image"), QDir::homePath(),
                                                      tr("PNG image (*.png)"));
    if (path.isEmpty()) return;
    const QImage image = view_->grabFrame();
    if (image.isNull() || !image.save(path))
        problem(tr("Cannot write the image %1").arg(path));
    else
        statusBar()->showMessage(tr("Wrote %1").arg(path), 5000);
}

QString MainWindow::recoveryPath() const {
    const QString folder = QStandardPaths::writableLocation(QStandardPaths::AppDataLocation);
    QDir().mkpath(folder);
    return folder + QStringLiteral("/recovery.x3d");
}

// Unsaved text, kept so a crash or a power cut never loses a student's work.
void MainWindow::writeRecovery() {
    if (!isModified()) return;
    QSaveFile out(recoveryPath());
    if (out.open(QIODevice::WriteOnly)) {
        out.write(editor_->toPlainText().toUtf8());
        out.commit();
        QSettings().setValue(QStringLiteral("file/recoveryOf"), path_);
    }
}

bool MainWindow::recoverUnsavedWork() {
    QFile f(recoveryPath());
    if (!f.exists() || !f.open(QIODevice::ReadOnly)) return false;
    const QString of = QSettings().value(QStringLiteral("file/recoveryOf")).toString();
    if (prompts_ &&
        !askPlainly(this, tr("Unsaved work"),
                    tr("FunctionLab closed last time with unsaved changes%1. Restore them?")
                        .arg(of.isEmpty() ? QString() : tr(" to %1").arg(of)))) {
        f.close();
        QFile::remove(recoveryPath());
        return false;
    }
    setPath(of);
    editor_->setPlainText(QString::fromUtf8(f.readAll()));
    editor_->document()->setModified(true); // still to be saved
    setWindowModified(true);
    parser_->parseNow();
    return true;
}

void MainWindow::closeEvent(QCloseEvent* event) {
    if (!maybeKeepChanges()) {
        event->ignore();
        return;
    }
    QSettings settings;
    settings.setValue(QStringLiteral("window/geometry"), saveGeometry());
    settings.setValue(QStringLiteral("window/state"), saveState());
    if (!isModified()) QFile::remove(recoveryPath());
    event->accept();
}

} // namespace fl::suite
