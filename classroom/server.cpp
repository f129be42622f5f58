#include "server.h"

#include "scene_policy.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QTcpServer>
#include <QTcpSocket>
#include <QWebSocket>
#include <QWebSocketServer>

#include <algorithm>
#include <new>

namespace fl::classroom {

namespace {
constexpr std::size_t kMaxHeldFrames = 256;
}

ClassroomServer::ClassroomServer(ClassSession& session, ServerOptions options, QObject* parent)
    : QObject(parent), session_(session), options_(options),
      server_(new QWebSocketServer(QStringLiteral("functionlab-classroom"),
                                   QWebSocketServer::NonSecureMode, this)),
      webRequests_(options.webBurst, options.webPerSecond) {
    server_->setMaxPendingConnections(256);
    connect(server_, &QWebSocketServer::newConnection, this, &ClassroomServer::accept);
    tcp_ = new QTcpServer(this);
    tcp_->setMaxPendingConnections(256);
    connect(tcp_, &QTcpServer::newConnection, this, &ClassroomServer::sniff);
    tick_.setInterval(options_.tickMillis);
    connect(&tick_, &QTimer::timeout, this, [this] {
        deliver(session_.tick());
        if (!live_) return;
        // The page's observer keeps its seat with heartbeats, and takes a
        // new one if the class ever let it go.
        if (webObserver_)
            deliver(session_.receive(*webObserver_, R"({"type":"heartbeat"})"));
        else
            joinWebObserver();
    });
    checks_.setMaxThreadCount(std::max(1, options_.checkThreads));
    session_.setDeferredChecks(true);
}

ClassroomServer::~ClassroomServer() {
    close();
    checks_.clear(); // checks not started are dropped; running ones end within their budget
    checks_.waitForDone();
    session_.setDeferredChecks(false);
}

namespace {

// checkClassroomScene on a worker: whatever happens there is a refusal, never
// an exception out of the thread (memory runs out under the server's cap).
SceneCheck checkOnWorker(const std::string& scene, const ClassroomLimits& limits) {
    auto failed = [](std::string message) {
        SceneCheck c;
        c.tooCostly = true;
        c.diagnostics.push_back({scene::Severity::Error,
                                 kSceneFileName,
                                 {},
                                 std::move(message),
                                 "use fewer or simpler formulas, or fewer PROTO instances",
                                 true});
        return c;
    };
    try {
        return checkClassroomScene(scene, limits);
    } catch (const std::bad_alloc&) {
        return failed("checking the scene needed more memory than the class server allows");
    } catch (const std::exception& e) {
        return failed(std::string("the scene could not be checked: ") + e.what());
    }
}

} // namespace

void ClassroomServer::dispatchChecks() {
    for (ScheduledCheck& c : session_.takeChecks()) {
        const CheckId id = c.id;
        const ClassroomLimits limits = session_.limits();
        const int timeLimit = int(std::min<Millis>(limits.maxCheckMillis, 3'600'000));
        checks_.start([this, id, limits, timeLimit, scene = std::move(c.scene)] {
            // The time limit runs from when a worker takes the check up.
            QMetaObject::invokeMethod(this, [this, id, timeLimit] {
                QTimer::singleShot(timeLimit, this, [this, id] {
                    deliver(session_.checkTimedOut(id));
                    dispatchChecks();
                });
            });
            SceneCheck result = checkOnWorker(scene, limits);
            QMetaObject::invokeMethod(this, [this, id, result = std::move(result)] {
                deliver(session_.checked(id, result));
                dispatchChecks();
            });
        });
    }
}

bool ClassroomServer::listen(const QHostAddress& address, quint16 port, QString* why) {
    if (!tcp_->listen(address, port)) {
        if (why) *why = tcp_->errorString();
        return false;
    }
    if (options_.web && !live_) {
        live_ = new LivePage(options_.livePage, this);
        joinWebObserver();
    }
    tick_.start();
    return true;
}

quint16 ClassroomServer::port() const {
    return tcp_->serverPort();
}
QHostAddress ClassroomServer::address() const {
    return tcp_->serverAddress();
}

void ClassroomServer::joinWebObserver() {
    const std::optional<ConnectionId> id = session_.connect("web page");
    if (!id) return;
    webObserver_ = *id;
    QJsonObject join;
    join["type"] = "join";
    join["class"] = QString::fromStdString(options_.livePage.classCode);
    join["name"] = "Web page";
    join["role"] = "observer";
    deliver(
        session_.receive(*id, QJsonDocument(join).toJson(QJsonDocument::Compact).toStdString()));
}

namespace {

// A short plain-text answer, then the connection closes.
void reply(QTcpSocket* socket, const QByteArray& status, const QByteArray& body) {
    socket->write("HTTP/1.1 " + status +
                  "\r\nContent-Type: text/plain; charset=utf-8\r\nContent-Length: " +
                  QByteArray::number(body.size()) + "\r\nConnection: close\r\n\r\n" + body);
    socket->disconnectFromHost();
    QObject::connect(socket, &QTcpSocket::disconnected, socket, &QObject::deleteLater);
}

} // namespace

void ClassroomServer::sniff() {
    while (QTcpSocket* socket = tcp_->nextPendingConnection()) {
        const std::string address = socket->peerAddress().toString().toStdString();
        const auto fromAddress = std::count_if(unread_.begin(), unread_.end(),
                                               [&](const auto& u) { return u.second == address; });
        if (unread_.size() >= options_.maxUnreadConnections ||
            std::size_t(fromAddress) >= options_.maxUnreadPerAddress) {
            socket->abort();
            socket->deleteLater();
            continue;
        }
        unread_[socket] = address;
        socket->setParent(this);
        // A head that never completes is not waited for.
        auto* timer = new QTimer(socket);
        timer->setSingleShot(true);
        connect(timer, &QTimer::timeout, socket, &QTcpSocket::abort);
        timer->start(options_.headMillis);
        connect(socket, &QTcpSocket::readyRead, this, [this, socket] { headArrived(socket); });
        connect(socket, &QTcpSocket::disconnected, this, [this, socket] {
            forgetUnread(socket);
            socket->deleteLater();
        });
    }
}

void ClassroomServer::forgetUnread(QTcpSocket* socket) {
    unread_.erase(socket);
    socket->disconnect(this);
    for (QTimer* t : socket->findChildren<QTimer*>(Qt::FindDirectChildrenOnly))
        delete t;
}

void ClassroomServer::headArrived(QTcpSocket* socket) {
    // Peeked, not read: a WebSocket handshake is read again by Qt.
    const QByteArray bytes = socket->peek(qint64(kMaxRequestHeadBytes));
    std::size_t length = 0;
    const HeadStatus status =
        findHeadEnd(std::string_view(bytes.constData(), std::size_t(bytes.size())), length);
    if (status == HeadStatus::Incomplete) return;
    const auto unreadAt = unread_.find(socket);
    const std::string unreadAddress = unreadAt != unread_.end() ? unreadAt->second : std::string();
    std::string why = "the request head is longer than 8 KiB";
    std::optional<HttpRequest> request;
    if (status == HeadStatus::Complete)
        request = parseRequestHead(std::string_view(bytes.constData(), length), why);
    forgetUnread(socket);
    if (!request) {
        const QByteArray body = QByteArray::fromStdString("Bad request: " + why + ".\n");
        reply(socket, "400 Bad Request", body);
        return;
    }
    if (request->wantsWebSocket()) {
        socket->setParent(nullptr);
        server_->handleConnection(socket);
        // Qt reads the handshake when more bytes arrive; these are here already.
        QMetaObject::invokeMethod(
            socket, [socket] { emit socket->readyRead(); }, Qt::QueuedConnection);
        return;
    }
    socket->read(qint64(length));
    if (!webRequests_.take(unreadAddress, webClock_.now())) {
        reply(socket, "429 Too Many Requests",
              "Too many requests from this address: wait a few seconds.\n");
        return;
    }
    if (live_) {
        live_->serve(socket, *request);
        return;
    }
    reply(socket, "404 Not Found",
          "This class server has no web page (it was started with --no-web).\n");
}

void ClassroomServer::close() {
    tick_.stop();
    tcp_->close();
    server_->close();
    for (auto& [socket, address] : std::map<QTcpSocket*, std::string>(unread_)) {
        forgetUnread(socket);
        socket->abort();
        socket->deleteLater();
    }
    if (webObserver_) {
        session_.disconnected(*webObserver_);
        webObserver_.reset();
    }
    delete live_;
    live_ = nullptr;
    std::map<ConnectionId, Peer> peers;
    peers.swap(sockets_);
    for (auto& [id, peer] : peers) {
        peer.socket->disconnect(this);
        peer.socket->close(QWebSocketProtocol::CloseCodeGoingAway, "the class server stopped");
        peer.socket->deleteLater();
        // The class outlives this server: its members are disconnected (a
        // lock holder keeps the grace to come back through another one).
        session_.disconnected(id);
    }
}

void ClassroomServer::accept() {
    while (QWebSocket* socket = server_->nextPendingConnection()) {
        const ClassroomLimits& limits = session_.limits();
        // Qt's own default is about 2 GiB: a message over ours closes the
        // connection with code 1009 before it is buffered.
        socket->setMaxAllowedIncomingMessageSize(static_cast<quint64>(limits.maxMessageBytes));
        socket->setMaxAllowedIncomingFrameSize(static_cast<quint64>(limits.maxMessageBytes));
        socket->setParent(this);
        const std::optional<ConnectionId> admitted =
            session_.connect(socket->peerAddress().toString().toStdString());
        if (!admitted) {
            // An address holding open connections that never join.
            socket->close(QWebSocketProtocol::CloseCodePolicyViolated,
                          QStringLiteral("too many connections from this address have not joined"));
            socket->deleteLater();
            continue;
        }
        const ConnectionId id = *admitted;
        sockets_[id] = Peer{socket, {}, {}, false};
        connect(socket, &QWebSocket::textMessageReceived, this, [this, id](const QString& text) {
            const QByteArray utf8 = text.toUtf8();
            try {
                deliver(session_.receive(id, std::string_view(utf8.constData(), utf8.size())));
            } catch (const std::exception& e) {
                // The session refuses what it cannot do; an exception that
                // still gets here costs this one message, never the class.
                deliver(session_.rejectFrame(id, ErrorCode::Server,
                                             std::string("the server could not handle that: ") +
                                                 e.what()));
            }
            dispatchChecks();
        });
        connect(socket, &QWebSocket::binaryMessageReceived, this, [this, id](const QByteArray&) {
            deliver(session_.rejectFrame(id, ErrorCode::Malformed,
                                         "the class speaks JSON in text frames, not binary"));
        });
        connect(socket, &QWebSocket::bytesWritten, this, [this, id](qint64) { drain(id); });
        connect(socket, &QWebSocket::disconnected, this, [this, id] { dropped(id); });
    }
}

void ClassroomServer::dropped(ConnectionId id) {
    const auto it = sockets_.find(id);
    if (it == sockets_.end()) return;
    it->second.socket->deleteLater();
    sockets_.erase(it);
    deliver(session_.disconnected(id));
}

void ClassroomServer::deliver(const std::vector<Delivery>& deliveries) {
    for (const Delivery& d : deliveries) {
        if (webObserver_ && d.to == *webObserver_) {
            if (live_) live_->observe(d.frame.toStdString());
            if (d.close) webObserver_.reset();
            continue;
        }
        const auto it = sockets_.find(d.to);
        if (it == sockets_.end() || it->second.closing) continue;
        send(it->second, d.frame, d.wholeScene);
        if (!d.close) continue;
        // Look again: closing a socket may have dropped it from the map.
        const auto again = sockets_.find(d.to);
        if (again == sockets_.end() || again->second.closing) continue;
        again->second.closing = true;
        again->second.socket->close(QWebSocketProtocol::CloseCodePolicyViolated);
    }
}

void ClassroomServer::send(Peer& peer, const QString& frame, bool wholeScene) {
    const qint64 unsent = peer.socket->bytesToWrite();
    if (unsent > options_.closeAboveBytes) {
        peer.closing = true;
        peer.socket->close(QWebSocketProtocol::CloseCodeTooMuchData, "reading too slowly");
        return;
    }
    if (unsent > options_.highWaterBytes || !peer.heldScene.isEmpty() || !peer.held.empty()) {
        if (wholeScene) {
            peer.heldScene = frame; // only the newest whole scene matters
        } else if (peer.held.size() < kMaxHeldFrames) {
            peer.held.push_back(frame);
        } else {
            peer.closing = true;
            peer.socket->close(QWebSocketProtocol::CloseCodeTooMuchData, "reading too slowly");
        }
        return;
    }
    peer.socket->sendTextMessage(frame);
}

void ClassroomServer::drain(ConnectionId id) {
    const auto it = sockets_.find(id);
    if (it == sockets_.end()) return;
    Peer& peer = it->second;
    if (peer.closing || peer.socket->bytesToWrite() > options_.highWaterBytes / 2) return;
    // Frames held back go out in order, the newest scene after them.
    std::vector<QString> held;
    held.swap(peer.held);
    QString scene;
    scene.swap(peer.heldScene);
    for (const QString& f : held)
        peer.socket->sendTextMessage(f);
    if (!scene.isEmpty()) peer.socket->sendTextMessage(scene);
}

} // namespace fl::classroom
