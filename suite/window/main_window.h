#pragma once
// The FunctionLab window: the 3D view in the middle; the scene's text, its
// node tree, the issues list, the examples and the parameter sliders in
// docks; the timeline below; a status bar with triangles, meshing time,
// frame rate and t. Every file operation reports problems in the window,
// never by crashing, and unsaved text is kept in a recovery file.
#include "panel_context.h"

#include <QMainWindow>
#include <QPointF>
#include <QTimer>

#include <memory>
#include <unordered_map>
#include <vector>

class QLabel;
class QListWidget;
class QTreeWidget;
class QMenu;
class QAction;

namespace fl::scene {
struct Node;
struct Scene;
} // namespace fl::scene
namespace fl::mesh {
struct SceneMeshes;
}
namespace fl::editor {
class CodeEditor;
class FindBar;
class LiveParser;
struct ParseOutcome;
} // namespace fl::editor
namespace fl::viewer {
class LevelOfDetail;
class SceneWidget;
class ScenePlayer;
} // namespace fl::viewer

namespace fl::suite {

class ExamplesDock;
class IssuesDock;
class Panel;
class ParametersDock;
class SceneTreeDock;
class AccuracyPanel;
class HapticsPanel;
class ClassroomPanel;
class ScreenErrorMeter;
class StatusFigures;
class RecentFilesMenu;
class ExportActions;
class DetailDriver;
class ViewControls;
class AssignmentPanel;
class GradingPanel;
class TimelineBar;
class ViewpointBox;

class MainWindow : public QMainWindow {
  public:
    explicit MainWindow(QWidget* parent = nullptr);
    ~MainWindow() override;

    // Opens a scene file into the editor (its text even when it has errors:
    // they are listed to be fixed). False, with `error`, when it cannot be read.
    bool openFile(const QString& path, QString* error = nullptr);
    bool saveTo(const QString& path, QString* error = nullptr);
    void newScene();
    // Text left unsaved when FunctionLab last stopped (the recovery file):
    // offered back; true when it was restored.
    bool recoverUnsavedWork();
    QString currentPath() const { return path_; }
    bool isModified() const;
    // Parsing, meshing, about to re-mesh for the level of detail, or
    // measuring the error of what is on screen.
    bool busy() const;
    QString screenErrorText() const; // the status bar's accuracy figure
    // Tests turn off the dialogs (unsaved-changes questions, message boxes).
    void setPromptsEnabled(bool on) { prompts_ = on; }
    QString lastProblem() const { return lastProblem_; }

    editor::CodeEditor* editor() const { return editor_; }
    viewer::SceneWidget* view() const { return view_; }
    viewer::ScenePlayer* player() const { return player_; }
    editor::LiveParser* parser() const { return parser_; }
    QListWidget* issues() const;
    QTreeWidget* sceneTree() const;
    TimelineBar* timeline() const { return timeline_; }
    QWidget* parametersPanel() const;
    QListWidget* examples() const;
    const viewer::LevelOfDetail& levelOfDetail() const;
    AssignmentPanel* assignmentPanel() const { return assignment_; }
    // The instructor's grading panel (hidden until a gradebook is open).
    GradingPanel* gradingPanel() const { return grading_; }
    ScreenErrorMeter* errorMeter() const { return errorMeter_; }
    AccuracyPanel* accuracyPanel() const { return accuracy_; }
    HapticsPanel* hapticsPanel() const { return haptics_; }
    ClassroomPanel* classroomPanel() const { return classroom_; }
    // The window's panels, in the order they were added.
    const std::vector<Panel*>& panels() const { return panels_; }

    // Docks a panel on its side (tabbed with the panels already there when
    // `tabbed`), lets it wire itself (Panel::attach with the window's
    // PanelContext) and hands it every scene the window shows from now on.
    // One line per panel.
    template <class P>
    P* addPanel(P* panel, bool tabbed = false) {
        dockPanel(panel, tabbed);
        return panel;
    }

  protected:
    void closeEvent(QCloseEvent* event) override;

  private:
    void buildContext();
    void buildMenus();
    void buildDocks();
    void dockPanel(Panel* panel, bool tabbed);
    void openDialog();
    bool save();
    bool saveAs();
    bool maybeKeepChanges(); // false: the user cancelled
    void problem(const QString& text);
    void setPath(const QString& path);
    void parsed(const editor::ParseOutcome& outcome);
    void sceneChanged(std::shared_ptr<const scene::Scene> scene);
    void meshesReady(std::shared_ptr<const mesh::SceneMeshes> meshes, double seconds);
    void writeRecovery();

    PanelContext context_; // what the panels use of the window
    editor::CodeEditor* editor_;
    editor::FindBar* find_;
    editor::LiveParser* parser_;
    viewer::SceneWidget* view_;
    viewer::ScenePlayer* player_;
    TimelineBar* timeline_;
    std::vector<Panel*> panels_;
    // A panel shows a scene of its own in the view (Panel::holdsTheView).
    bool aPanelHoldsTheView() const;
    IssuesDock* issues_ = nullptr;
    SceneTreeDock* tree_ = nullptr;
    ExamplesDock* examples_ = nullptr;
    ParametersDock* parameters_ = nullptr;
    AssignmentPanel* assignment_ = nullptr;
    AccuracyPanel* accuracy_ = nullptr;
    HapticsPanel* haptics_ = nullptr;
    ClassroomPanel* classroom_ = nullptr;
    GradingPanel* grading_ = nullptr;
    bool textParses_ = true; // the editor's text, as last parsed, has no errors
    ViewpointBox* viewpoints_;
    ViewControls* views_;
    bool firstFrameOfScene_ = true;
    RecentFilesMenu* recentMenu_ = nullptr;
    ScreenErrorMeter* errorMeter_;
    StatusFigures* figures_;
    ExportActions* exports_ = nullptr;
    DetailDriver* detail_; // the level of detail, with the Accuracy panel's choices
    QTimer recoveryTimer_;
    QString path_;
    QString lastProblem_;
    bool prompts_ = true;
    std::shared_ptr<const scene::Scene> scene_;
};

} // namespace fl::suite
