#pragma once
// Live preview: the editor's text is read again on a worker thread a short
// pause (250 ms) after the last keystroke. Only the newest text counts: an
// older parse finishing late is thrown away. A text with errors leaves the
// last good scene where it was, so the view never goes blank while typing.
// One worker thread at a time (platform::NewestOnlyWorker), joined when the
// parser goes.
#include "code_editor.h" // EditorDiagnostic
#include "platform/newest_only_worker.h"
#include "scene/scene.h"
#include "scene/scene_diagnostic.h"
#include "scene/scene_reader.h"
#include "scene/scene_work.h"

#include <QObject>
#include <QTimer>

#include <memory>
#include <vector>

namespace fl::editor {

struct ParseOutcome {
    QList<EditorDiagnostic> inThisFile; // to underline
    std::vector<scene::SceneDiagnostic> all;
    std::shared_ptr<const scene::Scene> scene; // null when the text has errors
};

// How a text is read and what showing it may cost: a file's defaults, or the
// tighter bounds of a class scene (classroom::readOptionsFor).
struct ParseLimits {
    scene::ReadOptions read;
    scene::WorkBudget work;
};

// Reads `text` as the scene file `path` (its folder resolves Inline urls).
ParseOutcome parseSceneText(const QString& text, const QString& path,
                            const ParseLimits& limits = {});

class LiveParser : public QObject {
    Q_OBJECT
  public:
    explicit LiveParser(QObject* parent = nullptr);
    ~LiveParser() override;

    void setDelay(int milliseconds) { timer_.setInterval(milliseconds); }
    // The bounds of the next parses (a scene from a class is held to the
    // class's; see issue 26 §3).
    void setLimits(const ParseLimits& limits) { limits_ = limits; }
    // The text changed: parse it after the pause.
    void setText(const QString& text, const QString& path);
    // Parse now, without the pause.
    void parseNow();
    std::shared_ptr<const scene::Scene> lastGoodScene() const { return lastGood_; }
    int parsesFinished() const { return finished_; }
    bool pending() const { return timer_.isActive() || worker_.busy(); }

  Q_SIGNALS:
    void parsed(const fl::editor::ParseOutcome& outcome);
    // Only when a new good scene replaces the last one.
    void sceneChanged(std::shared_ptr<const fl::scene::Scene> scene);

  private:
    struct Request {
        int generation = 0;
        QString text, path;
        ParseLimits limits;
    };
    void start();
    void finished(const Request& request, std::shared_ptr<ParseOutcome> outcome);

    QTimer timer_;
    QString text_, path_;
    ParseLimits limits_;
    std::shared_ptr<const scene::Scene> lastGood_;
    int generation_ = 0, finished_ = 0;
    platform::NewestOnlyWorker<Request, std::shared_ptr<ParseOutcome>> worker_;
};

} // namespace fl::editor

Q_DECLARE_METATYPE(fl::editor::ParseOutcome)
