#include "main_window.h"

#include "accuracy_panel.h"
#include "assignment_panel.h"
#include "classroom_panel.h"
#include "detail_driver.h"
#include "editor/code_editor.h"
#include "editor/find_bar.h"
#include "editor/live_parser.h"
#include "examples.h"
#include "examples_dock.h"
#include "export_actions.h"
#include "grading_panel.h"
#include "haptics_panel.h"
#include "issues_dock.h"
#include "parameters_dock.h"
#include "plain_text.h"
#include "recent_files_menu.h"
#include "recovery_file.h"
#include "scene/scene_writer.h"
#include "scene_text_dock.h"
#include "scene_text_file.h"
#include "scene_tree_dock.h"
#include "screen_error_meter.h"
#include "status_figures.h"
#include "timeline_bar.h"
#include "view_controls.h"
#include "view_pointing.h"
#include "viewer/scene_player.h"
#include "viewer/scene_widget.h"
#include "viewpoint_box.h"
#include "window_placement.h"
#include "working_copy.h"

#include <QCloseEvent>
#include <QCoreApplication>
#include <QFileDialog>
#include <QFileInfo>
#include <QMenuBar>
#include <QMessageBox>
#include <QStatusBar>
#include <QTabBar>
#include <QToolBar>

namespace fl::suite {
MainWindow::MainWindow(QWidget* parent)
    : QMainWindow(parent), editor_(new editor::CodeEditor), find_(new editor::FindBar(editor_)),
      parser_(new editor::LiveParser(this)), view_(new viewer::SceneWidget),
      player_(new viewer::ScenePlayer(nullptr, this)), timeline_(new TimelineBar(player_)),
      viewpoints_(new ViewpointBox), views_(new ViewControls(view_, timeline_, viewpoints_, this)),
      errorMeter_(new ScreenErrorMeter(this)),
      figures_(new StatusFigures(statusBar(), view_, player_, errorMeter_, this)),
      detail_(new DetailDriver(
          view_, player_, [this] { return scene_; }, this)) {
    setWindowTitle(QStringLiteral("FunctionLab[*]"));
    setCentralWidget(view_);
    buildContext();
    exports_ = new ExportActions(
        context_, [this] { return parameters_->values(); }, this);
    buildMenus();
    buildDocks();
    context_.fileMenu->addSeparator();
    context_.fileMenu->addAction(tr("&Quit"), QKeySequence::Quit, this, &QWidget::close);

    auto* timeBar = new QToolBar(tr("Timeline"));
    timeBar->setObjectName(QStringLiteral("timeline"));
    timeBar->addWidget(timeline_);
    addToolBar(Qt::BottomToolBarArea, timeBar);

    connect(editor_, &QPlainTextEdit::textChanged, this, [this] {
        parser_->setText(editor_->toPlainText(), path_);
        recoveryTimer_.start();
        setWindowModified(isModified());
    });
    connect(parser_, &editor::LiveParser::parsed, this, &MainWindow::parsed);
    // An edit arriving while a panel replays the past (a class member's, or
    // one's own) must not take the view from under the replay.
    connect(parser_, &editor::LiveParser::sceneChanged, this,
            [this](std::shared_ptr<const scene::Scene> scene) {
                if (!aPanelHoldsTheView()) sceneChanged(std::move(scene));
            });
    connect(player_, &viewer::ScenePlayer::meshesReady, this, &MainWindow::meshesReady);
    connect(player_, &viewer::ScenePlayer::timeChanged, timeline_, &TimelineBar::showTime);

    recoveryTimer_.setSingleShot(true);
    recoveryTimer_.setInterval(2000);
    connect(&recoveryTimer_, &QTimer::timeout, this, &MainWindow::writeRecovery);

    new ViewPointing(context_, errorMeter_, this);

    restorePlacement(*this);
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
        detail_->choose(geometry, resolution);
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
        if (!placementSaved()) {
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
    recentMenu_ = new RecentFilesMenu(
        tr("Open &Recent"),
        [this](const QString& path) {
            if (maybeKeepChanges()) openFile(path);
        },
        file);
    file->addMenu(recentMenu_);
    file->addAction(tr("&Save"), QKeySequence::Save, this, &MainWindow::save);
    file->addAction(tr("Save &As…"), QKeySequence::SaveAs, this, &MainWindow::saveAs);
    file->addSeparator();
    exports_->fillMenu(file);
    file->addSeparator(); // the panels' actions (Hand In, Join Class), then Quit
    context_.fileMenu = file;
    context_.courseMenu = menuBar()->addMenu(tr("&Course"));

    find_->fillEditMenu(menuBar()->addMenu(tr("&Edit")));

    views_->fillMenu(menuBar()->addMenu(tr("&View")));
    auto* viewBar = addToolBar(tr("View"));
    viewBar->setObjectName(QStringLiteral("view"));
    views_->fillToolBar(viewBar);

    QMenu* help = menuBar()->addMenu(tr("&Help"));
    help->addAction(tr("&About FunctionLab"), this, [this] {
        QMessageBox::about(this, tr("About FunctionLab"),
                           tr("FunctionLab %1: function-defined 3D objects for teaching.")
                               .arg(QCoreApplication::applicationVersion()));
    });
}

const viewer::LevelOfDetail& MainWindow::levelOfDetail() const {
    return detail_->levelOfDetail();
}

QString MainWindow::screenErrorText() const {
    return figures_->screenErrorText();
}

bool MainWindow::busy() const {
    return parser_->pending() || player_->busy() || detail_->busy() || errorMeter_->busy() ||
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
    player_->seek(0);
    editor_->setPlainText(newSceneText());
    editor_->document()->setModified(false);
    parser_->parseNow();
}

bool MainWindow::openFile(const QString& path, QString* error) {
    QString why;
    const std::optional<QString> text = readSceneText(path, why);
    if (!text) {
        if (error) *error = why;
        problem(why);
        return false;
    }
    setPath(path);
    firstFrameOfScene_ = true;
    editor_->setPlainText(*text);
    editor_->document()->setModified(false);
    setWindowModified(false);
    recentMenu_->add(path);
    parser_->setText(editor_->toPlainText(), path_);
    parser_->parseNow();
    player_->seek(0); // a scene opened starts at its beginning
    return true;
}

bool MainWindow::saveTo(const QString& path, QString* error) {
    QString why;
    if (!writeSceneText(path, editor_->toPlainText(), why)) {
        if (error) *error = why;
        problem(why);
        return false;
    }
    setPath(path);
    editor_->document()->setModified(false);
    setWindowModified(false);
    recentMenu_->add(path);
    forgetKeptText();
    return true;
}

bool MainWindow::save() {
    return saveNeedsAPlace(path_) ? saveAs() : saveTo(path_); // never into the courseware
}

bool MainWindow::saveAs() {
    const QString path = QFileDialog::getSaveFileName(
        this, tr("Save scene"), saveAsStartFor(path_),
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

void MainWindow::parsed(const editor::ParseOutcome& outcome) {
    editor_->setDiagnostics(outcome.inThisFile);
    textParses_ = outcome.scene != nullptr;
    if (aPanelHoldsTheView()) return; // its own message stays ("replaying the class ...")
    if (!outcome.scene)
        statusBar()->showMessage(tr("The text has errors: the view shows the last good scene"));
    else
        statusBar()->clearMessage();
}

bool MainWindow::aPanelHoldsTheView() const {
    for (const Panel* panel : panels_)
        if (panel->holdsTheView()) return true;
    return false;
}

void MainWindow::sceneChanged(std::shared_ptr<const scene::Scene> scene) {
    scene_ = scene;
    for (Panel* panel : panels_)
        panel->sceneChanged(scene);
    timeline_->fitTo(*scene);
    player_->setParameters(parameters_->values());
    detail_->sceneChanged();
    errorMeter_->focusOn(nullptr);
    view_->setMarker(std::nullopt); // it marked a point of the old shapes
    player_->setScene(scene);
}

void MainWindow::meshesReady(std::shared_ptr<const mesh::SceneMeshes> meshes, double) {
    // A scene's NavigationInfo picks how one moves through it, once, when it opens.
    if (firstFrameOfScene_) {
        firstFrameOfScene_ = false;
        view_->placeCameraOnNextMeshes();
        views_->navigateAsTheSceneSays(*meshes);
    }
    view_->setMeshes(meshes);
    viewpoints_->showViewpoints(view_->viewpointNames());
    figures_->frameShown(*meshes);
    errorMeter_->measure(meshes);
    detail_->frameShown(meshes);
}

void MainWindow::writeRecovery() {
    if (isModified()) keepUnsavedText(editor_->toPlainText(), path_);
}

bool MainWindow::recoverUnsavedWork() {
    const auto kept = keptText();
    if (!kept) return false;
    if (prompts_ &&
        !askPlainly(this, tr("Unsaved work"),
                    tr("FunctionLab closed last time with unsaved changes%1. Restore them?")
                        .arg(kept->of.isEmpty() ? QString() : tr(" to %1").arg(kept->of)))) {
        forgetKeptText();
        return false;
    }
    setPath(kept->of);
    editor_->setPlainText(kept->text);
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
    savePlacement(*this);
    if (!isModified()) forgetKeptText();
    event->accept();
}

} // namespace fl::suite
