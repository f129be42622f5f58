#pragma once
// The class, live, in a browser (issue 32 §2): what `functionlab serve`
// answers a browser on its own port. `GET /` is a read-only page that shows
// the class's scene (baked as `export-web` bakes it, web/web_bake.h) and its
// chat, and follows every accepted edit. It learns of them as an observer of
// the class over the existing protocol — the server feeds it the frames the
// class sends that observer (observe()) — so the web adds no way to write:
// browsers get the page's files, the baked scene (`/scene.json`) and a
// stream of "a newer version is ready" and chat lines (`/events`, Server-Sent
// Events), nothing else. Names are looked up in a fixed table (no path ever
// reaches the file system, so nothing can climb out or list a folder);
// streams, request sizes and baking time are bounded.
#include "http_request.h"

#include "web/web_bake.h"

#include <QByteArray>
#include <QObject>
#include <QThreadPool>
#include <QTimer>

#include <atomic>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <map>
#include <memory>
#include <string>
#include <vector>

class QTcpSocket;

namespace fl::classroom {

struct LivePageOptions {
    std::filesystem::path xIteDir; // X_ITE's dist folder (web::findXite); empty: none
    std::string classCode;
    bool needsClassCode = false; // every page request must carry ?class=CODE
    web::BakeOptions bake = defaultBake();
    int bakeMillis = 10'000;       // a version that takes longer is not shown
    std::size_t maxStreams = 256;  // open /events streams, all browsers together
    std::size_t maxChatLines = 50; // the newest, shown to a page that opens

    static web::BakeOptions defaultBake() {
        web::BakeOptions o;
        o.resolutions = {16, 32};
        o.frames = 12;
        o.threads = 1;
        o.maxTriangles = 2'000'000; // what a phone's browser still opens
        return o;
    }
};

class LivePage : public QObject {
    Q_OBJECT
  public:
    explicit LivePage(LivePageOptions options, QObject* parent = nullptr);
    ~LivePage() override;

    // A frame the class sent the page's observer (welcome, scene, chat ...).
    void observe(std::string_view frame);
    // Answers a request whose head has been read from `socket`; the page
    // owns the socket from here (closes it, or keeps it as an event stream).
    void serve(QTcpSocket* socket, const HttpRequest& request);

    std::int64_t shownVersion() const { return shownVersion_; }
    std::size_t streamCount() const { return streams_.size(); }

  private:
    struct Response {
        int status = 200;
        QByteArray type;
        QByteArray body;
        bool gzipped = false;
    };
    Response respond(const HttpRequest& request) const;
    void openStream(QTcpSocket* socket);
    void sendToStreams(const QByteArray& event);
    void schedule(std::int64_t version, std::string scene);
    void startBake();
    void baked(std::int64_t version, QByteArray json, QString problem);
    void addChat(const std::string& from, const std::string& text);

    LivePageOptions options_;
    std::map<std::string, std::filesystem::path> viewerFiles_; // "/viewer/..." -> file
    QThreadPool baker_;
    std::shared_ptr<std::atomic<bool>> cancel_; // of the bake under way
    bool baking_ = false;
    std::int64_t pendingVersion_ = -1;
    std::string pendingScene_;
    std::int64_t shownVersion_ = -1;
    QByteArray sceneJson_, sceneJsonGzip_;
    std::deque<QByteArray> chat_; // "event: chat" frames, newest last
    std::vector<QTcpSocket*> streams_;
    QTimer keepAlive_;
};

} // namespace fl::classroom
