#pragma once
// What a panel may use of the window, handed to it once when it is added
// (Panel::attach): the editor, the view, the player, the live parser, the
// status bar and menus to put its own actions in, and the few things only
// the window can do (open a file, keep unsaved work, go to a line, say a
// problem). A panel wires itself from these; the window never wires a
// panel's signals for it, so adding a panel is one line.
#include "field/vec3.h"

#include <QObject>
#include <QString>

#include <functional>
#include <memory>
#include <optional>

class QWidget;
class QMenu;
class QStatusBar;

namespace fl::scene {
struct Node;
struct Scene;
} // namespace fl::scene
namespace fl::editor {
class CodeEditor;
class LiveParser;
} // namespace fl::editor
namespace fl::viewer {
class SceneWidget;
class ScenePlayer;
} // namespace fl::viewer

namespace fl::suite {

class PanelContext : public QObject {
    Q_OBJECT
  public:
    QWidget* window = nullptr; // the parent of dialogs
    editor::CodeEditor* editor = nullptr;
    editor::LiveParser* parser = nullptr;
    viewer::SceneWidget* view = nullptr;
    viewer::ScenePlayer* player = nullptr;
    QStatusBar* status = nullptr;
    QMenu* fileMenu = nullptr;   // File: a panel's actions go before Quit
    QMenu* courseMenu = nullptr; // Course: gradebooks and hand-in

    // Unsaved work saved or kept (asking); false: the user cancelled.
    std::function<bool()> keepChanges;
    // Opens a scene file into the editor; false (said) when it cannot be read.
    std::function<bool(const QString& path)> open;
    // The editor's cursor to a line and column (from 1).
    std::function<void(int line, int column)> goTo;
    // Says what went wrong: status bar, and a dialog when prompts are on.
    std::function<void(const QString& text)> problem;
    // The scene file open in the editor ("" for none), and making the
    // editor's text nobody's file (Save then asks where).
    std::function<QString()> path;
    std::function<void()> forgetPath;
    // The scene shown: the editor's as last read without errors (or a class's
    // past version while a panel replays it: parser->lastGoodScene() is the
    // editor's always), and whether the editor's text as last parsed had none.
    std::function<std::shared_ptr<const scene::Scene>()> scene;
    std::function<bool()> textParses;
    // Shows this scene in the view and every panel (a class's past version).
    std::function<void(std::shared_ptr<const scene::Scene>)> showScene;
    // Meshes this shape at this resolution from now on (the Accuracy panel's choice).
    std::function<void(const scene::Node* geometry, double resolution)> chooseResolution;
    // Dialogs are asked only when true (tests turn them off).
    std::function<bool()> prompts;

  Q_SIGNALS:
    // A point of the scene the student chose, in the scene's coordinates:
    // clicked on the view (on the shape numbered `shape` of the frame) or
    // touched by the haptic tool (shape -1: the shape whose box holds it).
    void pointChosen(fl::field::Vec3 point, int shape);
};

} // namespace fl::suite
