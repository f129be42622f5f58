#include "live_parser.h"

#include "scene/scene_reader.h"

#include <QFileInfo>
#include <QMetaObject>
#include <QPointer>

#include <thread>

namespace fl::editor {

ParseOutcome parseSceneText(const QString& text, const QString& path) {
    ParseOutcome out;
    const std::string file = path.isEmpty() ? std::string("untitled.x3d") : path.toStdString();
    scene::ReadResult r = scene::readSceneBytes(text.toStdString(), file);
    bool errors = !r.ok();
    for (const auto& d : r.diagnostics) {
        const bool isError = d.severity == scene::Severity::Error;
        errors = errors || isError;
        // Diagnostics of inlined files are listed, not underlined here.
        if (d.file.empty() || QFileInfo(QString::fromStdString(d.file)).fileName() ==
                                  QFileInfo(QString::fromStdString(file)).fileName()) {
            QString message = QString::fromStdString(d.message);
            if (!d.suggestion.empty()) message += " (" + QString::fromStdString(d.suggestion) + ")";
            out.inThisFile << EditorDiagnostic{d.pos.line, d.pos.column, isError, message};
        }
    }
    out.all = std::move(r.diagnostics);
    if (!errors) out.scene = std::shared_ptr<const scene::Scene>(std::move(r.scene));
    return out;
}

LiveParser::LiveParser(QObject* parent) : QObject(parent) {
    timer_.setSingleShot(true);
    timer_.setInterval(250);
    connect(&timer_, &QTimer::timeout, this, &LiveParser::start);
}

LiveParser::~LiveParser() {
    // Workers hold only copies; their results go nowhere once this is gone.
}

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

void LiveParser::start() {
    const int generation = generation_;
    ++running_;
    std::thread([this, generation, text = text_, path = path_, guard = QPointer<LiveParser>(this)] {
        auto outcome = std::make_shared<ParseOutcome>(parseSceneText(text, path));
        QMetaObject::invokeMethod(
            guard.data() ? guard.data() : nullptr,
            [this, generation, outcome] {
                --running_;
                if (generation != generation_) return; // a newer text is on its way
                ++finished_;
                if (outcome->scene) {
                    lastGood_ = outcome->scene;
                    Q_EMIT sceneChanged(lastGood_);
                }
                Q_EMIT parsed(*outcome);
            },
            Qt::QueuedConnection);
    }).detach();
}

} // namespace fl::editor
