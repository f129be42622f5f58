#pragma once
// A class member over the network: what the window's classroom panel sits
// on. It joins, keeps the shared scene and version, the members, the lock
// holder, and hands each change on as a signal. It sends heartbeats (they
// renew its lease), reconnects with backoff (doubling, with jitter, capped)
// and resumes its seat — and its lock, within the grace — with the token of
// its welcome and the last version it has. A join that cannot succeed stops
// and says why (stopReason): a server not reached in kFirstAttempts tries,
// a class code, key or name the server refuses. An edit refused because another
// member holds the lock (or because the scene moved on) is kept as the
// pending edit; pendingEditCanBeApplied says when the lock is free, and
// reofferPendingEdit sends it again on the newest version.
#include "protocol.h"
#include "server_message.h"

#include <QList>
#include <QObject>
#include <QString>
#include <QTimer>
#include <QUrl>

#include <optional>
#include <vector>

class QWebSocket;

namespace fl::classroom {

class ClassroomClient : public QObject {
    Q_OBJECT
  public:
    enum class State { Disconnected, Connecting, Joined, Reconnecting };

    struct JoinOptions {
        QUrl url; // ws://HOST:PORT
        QString classCode;
        QString name;
        Role role = Role::Student;
        QString key; // instructor key
        int initialBackoffMs = 500;
        int maxBackoffMs = 10'000;
        int heartbeatMs = 3'000;
        bool reconnect = true;
    };
    struct Member {
        qint64 id = 0;
        QString name;
        Role role = Role::Student;
        bool connected = true;
    };
    struct Refusal {
        RefusalReason reason = RefusalReason::Invalid;
        QString message;
        qint64 version = 0;                         // the class's version when refused
        QString holder;                             // Locked: who holds the lock
        QString command;                            // the chat command refused, if it was one
        std::vector<RefusalDiagnostic> diagnostics; // where the scene is wrong
    };

    explicit ClassroomClient(QObject* parent = nullptr);
    ~ClassroomClient() override;

    void join(const JoinOptions& options);
    void leave(); // closes and stops reconnecting

    // Sends the whole new scene text based on the version this client has.
    void submitEdit(const QString& sceneText);
    void releaseLock();
    void sendChat(const QString& text);  // '/...' is a modelling command
    void requestVersion(qint64 version); // answered by versionReceived
    // Instructor controls (the server refuses them from others).
    void takeLock();
    void breakLock();
    void setFrozen(bool frozen);
    void pushScene(const QString& sceneText);
    void takeSnapshot(const QString& label);
    void setAnonymous(bool anonymous);

    // Tries to reach a server before a first join is given up.
    static constexpr int kFirstAttempts = 3;

    State state() const { return state_; }
    // Why the client stopped without being asked to (empty otherwise), and
    // the last network error while connecting or reconnecting.
    const QString& stopReason() const { return stopReason_; }
    const QString& lastNetworkError() const { return lastNetworkError_; }
    qint64 version() const { return version_; }
    const QString& scene() const { return scene_; }
    qint64 memberId() const { return memberId_; }
    const QString& shownName() const { return shownName_; }
    bool frozen() const { return frozen_; }
    bool anonymous() const { return anonymous_; }
    const QList<Member>& members() const { return members_; }
    std::optional<Member> lockHolder() const { return lockHolder_; }
    bool holdsLock() const { return lockHolder_ && lockHolder_->id == memberId_; }

    bool hasPendingEdit() const { return !pendingEdit_.isEmpty(); }
    const QString& pendingEdit() const { return pendingEdit_; }
    // Sends the pending edit on the newest version; false when there is none.
    bool reofferPendingEdit();
    void discardPendingEdit();

  Q_SIGNALS:
    void stateChanged(fl::classroom::ClassroomClient::State state);
    void joined(bool resumed);
    void sceneChanged(qint64 version, const QString& author, const QString& scene);
    void chatReceived(const QString& from, const QString& text);
    void noticeReceived(const QString& text);
    void refused(const fl::classroom::ClassroomClient::Refusal& refusal);
    void errorReceived(fl::classroom::ErrorCode code, const QString& message);
    void membersChanged();
    void lockChanged();
    void frozenChanged(bool frozen);
    void saved(qint64 version, const QString& label);
    void versionReceived(qint64 version, const QString& author, const QString& scene);
    void pendingEditChanged();
    // The lock is free (or ours) while a refused edit waits: offer to apply it.
    void pendingEditCanBeApplied();

  private:
    void open();
    void send(MessageType type, ClientBody body = std::monostate{});
    void received(const QString& text);
    void onWelcome(const WelcomeMessage& w);
    void onScene(const SceneMessage& m);
    void onRefused(const RefusedMessage& m);
    void onError(const ErrorMessage& m);
    void onLock(const std::optional<LockHolderEntry>& holder);
    void onMembers(const std::vector<MemberEntry>& list);
    void onDisconnected();
    void stop(const QString& reason); // gives up: Disconnected, with why
    void setState(State state);

    QWebSocket* socket_ = nullptr;
    JoinOptions options_;
    State state_ = State::Disconnected;
    bool leaving_ = false;
    int backoffMs_ = 0;
    QTimer heartbeat_;
    QTimer reconnect_;
    QString token_;
    qint64 memberId_ = 0;
    QString shownName_;
    qint64 version_ = -1;
    QString scene_;
    bool frozen_ = false;
    bool anonymous_ = false;
    QList<Member> members_;
    std::optional<Member> lockHolder_;
    QString lastEdit_;        // the newest edit sent and not yet seen applied
    QString pendingEdit_;     // refused under a lock or as stale: kept for its author
    bool everJoined_ = false; // since join(): a lost class is reconnected, a wrong address not
    int failedFirstAttempts_ = 0;
    QString stopReason_;
    QString lastNetworkError_;
};

} // namespace fl::classroom
