#include "live_page.h"

#include "live_page_files.h"
#include "server_message.h"

#include "scene/gzip.h"
#include "scene/scene_reader.h"
#include "scene/scene_writer.h"
#include "web/page_script.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpSocket>

#include <fstream>
#include <sstream>

namespace fl::classroom {
namespace {

namespace fs = std::filesystem;

constexpr std::uintmax_t kMaxViewerFileBytes = 4u << 20;
constexpr std::size_t kMaxViewerFiles = 2000;

QByteArray contentType(const std::string& name) {
    const std::string ext = fs::path(name).extension().string();
    if (ext == ".js" || ext == ".mjs") return "text/javascript; charset=utf-8";
    if (ext == ".css") return "text/css; charset=utf-8";
    if (ext == ".wasm") return "application/wasm";
    if (ext == ".png") return "image/png";
    if (ext == ".woff2") return "font/woff2";
    if (ext == ".ttf") return "font/ttf";
    if (ext == ".json") return "application/json";
    return "text/plain; charset=utf-8";
}

QByteArray reason(int status) {
    switch (status) {
    case 200:
        return "OK";
    case 403:
        return "Forbidden";
    case 404:
        return "Not Found";
    case 405:
        return "Method Not Allowed";
    case 503:
        return "Service Unavailable";
    default:
        return "Error";
    }
}

// Sent with every answer: the page runs its own scripts and X_ITE's only,
// and nothing frames it.
const QByteArray kSecurityHeaders =
    "Content-Security-Policy: default-src 'self'; script-src 'self' 'wasm-unsafe-eval'; "
    "style-src 'self' 'unsafe-inline'; img-src 'self' data: blob:; font-src 'self' data:; "
    "connect-src 'self'; worker-src 'self' blob:; object-src 'none'; base-uri 'none'; "
    "frame-ancestors 'none'\r\n"
    "X-Content-Type-Options: nosniff\r\nReferrer-Policy: no-referrer\r\n";

QByteArray head(int status, const QByteArray& type, qsizetype length, bool gzipped, bool noStore) {
    QByteArray h = "HTTP/1.1 " + QByteArray::number(status) + " " + reason(status) + "\r\n";
    h += "Content-Type: " + type + "\r\n";
    if (length >= 0) h += "Content-Length: " + QByteArray::number(length) + "\r\n";
    if (gzipped) h += "Content-Encoding: gzip\r\n";
    h += noStore ? "Cache-Control: no-store\r\n" : "Cache-Control: max-age=3600\r\n";
    h += kSecurityHeaders;
    return h;
}

QByteArray eventFrame(const QByteArray& event, const QByteArray& data) {
    return "event: " + event + "\ndata: " + data + "\n\n";
}

// The baked scene as the page reads it: {version, clocks, x3d}.
QByteArray sceneJson(std::int64_t version, const web::BakeResult& baked) {
    QJsonObject o;
    o["version"] = double(version);
    QJsonArray clocks;
    for (const web::BakedClock& c : baked.clocks) {
        QJsonObject j;
        j["timeSensor"] = QString::fromStdString(c.timeSensor);
        j["base"] = QString::fromUtf8(web::clockBaseName(c.base).data(),
                                      qsizetype(web::clockBaseName(c.base).size()));
        j["start"] = c.startSeconds;
        j["cycle"] = c.cycleSeconds;
        clocks.append(j);
    }
    o["clocks"] = clocks;
    o["x3d"] = QString::fromStdString(scene::writeScene(baked.scene, scene::Encoding::Xml));
    return QJsonDocument(o).toJson(QJsonDocument::Compact);
}

} // namespace

LivePage::LivePage(LivePageOptions options, QObject* parent)
    : QObject(parent), options_(std::move(options)) {
    baker_.setMaxThreadCount(1);
    // X_ITE's files, each by its name under /viewer/: the only files the
    // page ever reads, listed once (regular files only, no links).
    std::error_code ec;
    if (!options_.xIteDir.empty())
        for (auto it = fs::recursive_directory_iterator(options_.xIteDir, ec);
             !ec && it != fs::recursive_directory_iterator() &&
             viewerFiles_.size() < kMaxViewerFiles;
             it.increment(ec)) {
            if (!it->is_regular_file(ec) || it->is_symlink(ec) ||
                it->file_size(ec) > kMaxViewerFileBytes)
                continue;
            viewerFiles_["/viewer/" +
                         fs::relative(it->path(), options_.xIteDir, ec).generic_string()] =
                it->path();
        }
    for (const char* licence : {"LICENSE.md"})
        if (fs::is_regular_file(options_.xIteDir / ".." / licence, ec))
            viewerFiles_[std::string("/viewer/") + licence] = options_.xIteDir / ".." / licence;
    keepAlive_.setInterval(15'000);
    connect(&keepAlive_, &QTimer::timeout, this, [this] { sendToStreams(":\n\n"); });
    keepAlive_.start();
}

LivePage::~LivePage() {
    if (cancel_) cancel_->store(true);
    baker_.clear();
    baker_.waitForDone();
}

void LivePage::observe(std::string_view frame) {
    const ParsedServerMessage parsed = parseServerMessage(frame);
    const auto* message = std::get_if<ServerMessage>(&parsed);
    if (!message) return;
    if (const auto* w = std::get_if<WelcomeMessage>(message)) {
        if (w->chat)
            for (const EarlierChat& c : *w->chat)
                addChat(c.from, c.text);
        schedule(w->version, w->scene);
    } else if (const auto* s = std::get_if<SceneMessage>(message)) {
        schedule(s->version, s->scene);
    } else if (const auto* c = std::get_if<ChatLineMessage>(message)) {
        addChat(c->from, c->text);
    }
}

void LivePage::addChat(const std::string& from, const std::string& text) {
    QJsonObject o;
    o["from"] = QString::fromStdString(from);
    o["text"] = QString::fromStdString(text);
    const QByteArray frame = eventFrame("chat", QJsonDocument(o).toJson(QJsonDocument::Compact));
    chat_.push_back(frame);
    while (chat_.size() > options_.maxChatLines)
        chat_.pop_front();
    sendToStreams(frame);
}

// Newest only: a version that arrives while another bakes cancels it.
void LivePage::schedule(std::int64_t version, std::string scene) {
    if (version <= shownVersion_ || version <= pendingVersion_) return;
    pendingVersion_ = version;
    pendingScene_ = std::move(scene);
    if (baking_ && cancel_) cancel_->store(true);
    if (!baking_) startBake();
}

void LivePage::startBake() {
    if (pendingVersion_ <= shownVersion_) return;
    baking_ = true;
    cancel_ = std::make_shared<std::atomic<bool>>(false);
    const std::int64_t version = pendingVersion_;
    std::string scene = std::move(pendingScene_);
    pendingScene_.clear();
    QTimer::singleShot(options_.bakeMillis, this, [cancel = cancel_] { cancel->store(true); });
    web::BakeOptions bake = options_.bake;
    baker_.start([this, version, bake, cancel = cancel_, scene = std::move(scene)]() mutable {
        QByteArray json;
        QString problem;
        try {
            scene::ReadResult r = scene::readSceneBytes(std::move(scene), "class.x3d");
            if (!r.ok()) {
                problem = "the class's scene could not be read";
            } else {
                bake.cancel = cancel.get();
                const web::BakeResult baked = web::bakeForWeb(*r.scene, bake);
                if (!baked.error.empty())
                    problem = "version " + QString::number(version) +
                              " is not shown: " + QString::fromStdString(baked.error);
                else if (baked.cancelled)
                    problem = "drawing version " + QString::number(version) +
                              " took too long; the page shows an earlier one";
                else
                    json = sceneJson(version, baked);
            }
        } catch (const std::exception& e) {
            problem = QString("version %1 could not be drawn: %2").arg(version).arg(e.what());
        }
        QMetaObject::invokeMethod(this, [this, version, json = std::move(json), problem] {
            baked(version, json, problem);
        });
    });
}

void LivePage::baked(std::int64_t version, QByteArray json, QString problem) {
    baking_ = false;
    if (!json.isEmpty() && version > shownVersion_) {
        shownVersion_ = version;
        sceneJson_ = json;
        const std::string zipped = scene::gzip(std::string_view(json.constData(), json.size()));
        sceneJsonGzip_ = QByteArray(zipped.data(), qsizetype(zipped.size()));
        sendToStreams(eventFrame("version", QByteArray::number(version)));
    } else if (!problem.isEmpty() && version > shownVersion_ && pendingVersion_ == version) {
        sendToStreams(eventFrame("notice", problem.toUtf8()));
    }
    startBake();
}

LivePage::Response LivePage::respond(const HttpRequest& request) const {
    const std::string& p = request.path;
    const bool page = p == "/" || p == "/index.html" || p == "/scene.json" || p == "/events";
    if (page && options_.needsClassCode && request.queryValue("class") != options_.classCode)
        return {403, "text/plain; charset=utf-8",
                "This class's page needs the class code: add ?class=CODE to its address.\n"};
    if (p == "/" || p == "/index.html") return {200, "text/html; charset=utf-8", kLivePageHtml};
    if (p == "/live.js") return {200, "text/javascript; charset=utf-8", kLivePageScript};
    if (p == "/viewer/page.css")
        return {200, "text/css; charset=utf-8",
                QByteArray(web::kPageStyle) + QByteArray(kLivePageChatStyle)};
    if (p == "/scene.json") {
        if (sceneJson_.isEmpty())
            return {503, "text/plain; charset=utf-8", "The class's scene is being drawn.\n"};
        if (request.acceptsGzip()) return {200, "application/json", sceneJsonGzip_, true};
        return {200, "application/json", sceneJson_};
    }
    if (const auto it = viewerFiles_.find(p); it != viewerFiles_.end()) {
        std::ifstream in(it->second, std::ios::binary);
        std::ostringstream s;
        s << in.rdbuf();
        if (in || in.eof()) {
            const std::string bytes = s.str();
            return {200, contentType(p), QByteArray(bytes.data(), qsizetype(bytes.size()))};
        }
    }
    return {404, "text/plain; charset=utf-8", "Not here.\n"};
}

void LivePage::serve(QTcpSocket* socket, const HttpRequest& request) {
    socket->setParent(this);
    // Every answer ends with the connection (an event stream when the page
    // goes): the socket goes with it.
    connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
    const bool headOnly = request.method == "HEAD";
    if (request.method != "GET" && !headOnly) {
        const QByteArray body = "The class's page only answers GET.\n";
        socket->write(head(405, "text/plain; charset=utf-8", body.size(), false, true) +
                      "Allow: GET, HEAD\r\nConnection: close\r\n\r\n" + body);
        socket->disconnectFromHost();
        return;
    }
    if (request.path == "/events" &&
        !(options_.needsClassCode && request.queryValue("class") != options_.classCode) &&
        !headOnly) {
        openStream(socket);
        return;
    }
    const Response r = respond(request);
    const bool dynamic = request.path == "/scene.json" || r.status != 200;
    QByteArray out =
        head(r.status, r.type, r.body.size(), r.gzipped, dynamic) + "Connection: close\r\n\r\n";
    if (!headOnly) out += r.body;
    socket->write(out);
    socket->disconnectFromHost();
}

void LivePage::openStream(QTcpSocket* socket) {
    if (streams_.size() >= options_.maxStreams) {
        const QByteArray body = "Too many pages follow this class; try again later.\n";
        socket->write(head(503, "text/plain; charset=utf-8", body.size(), false, true) +
                      "Retry-After: 30\r\nConnection: close\r\n\r\n" + body);
        socket->disconnectFromHost();
        return;
    }
    streams_.push_back(socket);
    connect(socket, &QTcpSocket::disconnected, this,
            [this, socket] { std::erase(streams_, socket); });
    // A browser only listens: whatever it sends on a stream is dropped.
    connect(socket, &QTcpSocket::readyRead, socket, [socket] { socket->readAll(); });
    QByteArray out = head(200, "text/event-stream; charset=utf-8", -1, false, true) +
                     "Connection: keep-alive\r\n\r\n";
    for (const QByteArray& line : chat_)
        out += line;
    if (shownVersion_ >= 0) out += eventFrame("version", QByteArray::number(shownVersion_));
    socket->write(out);
}

void LivePage::sendToStreams(const QByteArray& event) {
    for (QTcpSocket* s : std::vector<QTcpSocket*>(streams_)) {
        // A page that stops reading is let go rather than buffered for.
        if (s->bytesToWrite() > (1 << 20)) {
            s->abort();
            continue;
        }
        s->write(event);
    }
}

} // namespace fl::classroom
