#pragma once
// The class on the network: a QWebSocketServer that hands each text frame to
// the ClassSession and sends what it answers. It bounds incoming messages
// (1 MiB), and keeps one slow reader from costing the others: a connection
// whose unsent bytes pass a high-water mark gets only the newest scene when
// it drains (every scene frame is the whole scene, so the ones between do
// not matter) and is closed if even that does not keep up. A changed scene is
// checked on a worker thread, never on the event loop, with a time limit
// (ClassroomLimits::maxCheckMillis): a costly edit cannot freeze the class.
// One port serves both the class and its web page (issue 32 §2): each new
// connection's request head is read (bounded in size and time, and in how
// many may be read at once per address); a WebSocket upgrade goes to the
// class, any other request to the LivePage, which follows the class as one
// more observer of it.
#include "class_session.h"
#include "live_page.h"
#include "rate_limit.h"

#include <QHostAddress>
#include <QObject>
#include <QThreadPool>
#include <QTimer>

#include <map>
#include <memory>
#include <optional>
#include <string>

class QTcpServer;
class QTcpSocket;
class QWebSocket;
class QWebSocketServer;

namespace fl::classroom {

struct ServerOptions {
    qint64 highWaterBytes = 4 << 20;   // unsent bytes before a connection is held back
    qint64 closeAboveBytes = 64 << 20; // unsent bytes before a connection is given up
    int tickMillis = 1000;
    int checkThreads = 2; // workers that check changed scenes
    bool web = false;     // answer browsers with the live page (serve: true unless --no-web)
    LivePageOptions livePage;
    int headMillis = 5000;                  // to send a request head, or be closed
    std::size_t maxUnreadConnections = 256; // connections whose head is not read yet
    std::size_t maxUnreadPerAddress = 16;
    // Page requests per address: a burst, then so many a second (a page
    // loads about a dozen files; a projector reloads now and then).
    double webBurst = 120;
    double webPerSecond = 20;
};

class ClassroomServer : public QObject {
    Q_OBJECT
  public:
    ClassroomServer(ClassSession& session, ServerOptions options = {}, QObject* parent = nullptr);
    ~ClassroomServer() override;

    // False with `why` when the address cannot be listened on.
    bool listen(const QHostAddress& address, quint16 port, QString* why = nullptr);
    quint16 port() const;
    QHostAddress address() const;
    void close();
    std::size_t connectionCount() const { return sockets_.size(); }
    const LivePage* livePage() const { return live_; }

  private:
    struct Peer {
        QWebSocket* socket = nullptr;
        QString heldScene;         // newest scene frame not sent while held back
        std::vector<QString> held; // other frames while held back (bounded)
        bool closing = false;
    };
    void sniff();
    void headArrived(QTcpSocket* socket);
    void forgetUnread(QTcpSocket* socket);
    void joinWebObserver();
    void accept();
    void deliver(const std::vector<Delivery>& deliveries);
    void send(Peer& peer, const QString& frame, bool wholeScene);
    void drain(ConnectionId id);
    void dropped(ConnectionId id);
    // Starts the checks the session waits for on the workers.
    void dispatchChecks();

    ClassSession& session_;
    ServerOptions options_;
    QTcpServer* tcp_ = nullptr;
    QWebSocketServer* server_ = nullptr; // takes the upgrades tcp_ hands it
    LivePage* live_ = nullptr;
    std::optional<ConnectionId> webObserver_;
    std::map<QTcpSocket*, std::string> unread_; // connections whose head is not read yet
    AddressBuckets webRequests_;                // page requests per address
    SteadyClock webClock_;
    QTimer tick_;
    std::map<ConnectionId, Peer> sockets_;
    QThreadPool checks_; // last: destroyed (waiting for its workers) first
};

} // namespace fl::classroom
