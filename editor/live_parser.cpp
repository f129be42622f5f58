#include "live_parser.h"

#include "scene/scene_reader.h"

#include <QFileInfo>

namespace fl::editor {

ParseOutcome parseSceneText(const QString& text, const QString& path, const ParseLimits& limits) {
    ParseOutcome out;
    const std::string file = path.isEmpty() ? std::string("untitled.x3d") : path.toStdString();
    scene::ReadResult r = scene::readSceneBytes(text.toStdString(), file, limits.read);
    if (r.ok())
        if (auto costly = scene::checkWorkBudget(*r.scene, limits.work)) {
            r.diagnostics.push_back(std::move(*costly));
            r.scene.reset();
        }
    bool errors = !r.ok();
    for (const auto& d : r.diagnostics) {
        const bool isError = d.severity == scene::Severity::Error;
        errors = errors || isError;
        // Diagnostics of inlined files are listed, not underlined here.
        if (d.file.empty() || QFileInfo(QString::fromStdString(d.file)).fileName() ==
                                  QFileInfo(QString::fromStdString(file)).fileName()) {
            QString message = QString::fromStdString(d.message);
            if (!d.suggestion.empty()) message += " (" + QString::fromStdString(d.suggestion) + ")";
            std::optional<EditorFix> fix;
            if (d.fix)
                fix = EditorFix{d.fix->at.line, d.fix->at.column, d.fix->length,
                                QString::fromStdString(d.fix->text),
                                QString::fromStdString(d.fix->label)};
            out.inThisFile << EditorDiagnostic{d.pos.line, d.pos.column, isError, message, fix};
        }
    }
    out.all = std::move(r.diagnostics);
    if (!errors) out.scene = std::shared_ptr<const scene::Scene>(std::move(r.scene));
    return out;
}

LiveParser::LiveParser(QObject* parent)
    : QObject(parent),
      worker_(
          this,
          [](const Request& r) {
              return std::make_shared<ParseOutcome>(parseSceneText(r.text, r.path, r.limits));
          },
          [this](const Request& r, std::shared_ptr<ParseOutcome> outcome) {
              finished(r, std::move(outcome));
          }) {
    timer_.setSingleShot(true);
    timer_.setInterval(250);
    connect(&timer_, &QTimer::timeout, this, &LiveParser::start);
}

LiveParser::~LiveParser() = default; // the worker finishes its parse; its result is dropped

void LiveParser::setText(const QString& text, const QString& path) {
    text_ = text;
    path_ = path;
    ++generation_;
    timer_.start();
}

void LiveParser::parseNow() {
    timer_.stop();
    start();
}

// A text that arrives while a parse runs waits, replacing any older waiting
// one, so fast typing never piles up parses.
void LiveParser::start() {
    worker_.request({generation_, text_, path_, limits_});
}

void LiveParser::finished(const Request& request, std::shared_ptr<ParseOutcome> outcome) {
    if (request.generation != generation_) return; // a newer text is on its way
    ++finished_;
    if (outcome->scene) {
        lastGood_ = outcome->scene;
        Q_EMIT sceneChanged(lastGood_);
    }
    Q_EMIT parsed(*outcome);
}

} // namespace fl::editor
