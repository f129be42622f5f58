#include "client.h"

#include <QRandomGenerator>
#include <QWebSocket>

#include <algorithm>

namespace fl::classroom {

namespace {

std::string utf8(const QString& s) {
    return s.toStdString();
}

// Scene frames carry whole scenes, JSON-escaped: allow well over the
// server's scene limit, but not Qt's 2 GiB default.
constexpr quint64 kMaxIncomingBytes = 16u << 20;

} // namespace

ClassroomClient::ClassroomClient(QObject* parent) : QObject(parent) {
    heartbeat_.setSingleShot(false);
    connect(&heartbeat_, &QTimer::timeout, this, [this] { send(MessageType::Heartbeat); });
    reconnect_.setSingleShot(true);
    connect(&reconnect_, &QTimer::timeout, this, &ClassroomClient::open);
}

ClassroomClient::~ClassroomClient() {
    leaving_ = true;
    if (socket_) {
        socket_->disconnect(this);
        socket_->abort();
    }
}

void ClassroomClient::setState(State state) {
    if (state_ == state) return;
    state_ = state;
    emit stateChanged(state);
}

void ClassroomClient::join(const JoinOptions& options) {
    options_ = options;
    leaving_ = false;
    token_.clear();
    version_ = -1;
    everJoined_ = false;
    failedFirstAttempts_ = 0;
    stopReason_.clear();
    lastNetworkError_.clear();
    backoffMs_ = options.initialBackoffMs;
    open();
}

void ClassroomClient::open() {
    if (socket_) {
        socket_->disconnect(this);
        socket_->abort();
        socket_->deleteLater();
    }
    socket_ = new QWebSocket(QString(), QWebSocketProtocol::VersionLatest, this);
    socket_->setMaxAllowedIncomingMessageSize(kMaxIncomingBytes);
    socket_->setMaxAllowedIncomingFrameSize(kMaxIncomingBytes);
    connect(socket_, &QWebSocket::connected, this, [this] {
        JoinMessage j;
        j.classCode = utf8(options_.classCode);
        j.name = utf8(options_.name);
        j.role = options_.role;
        j.key = utf8(options_.key);
        j.resume = utf8(token_);
        if (version_ >= 0) j.since = version_;
        send(MessageType::Join, j);
    });
    connect(socket_, &QWebSocket::textMessageReceived, this, &ClassroomClient::received);
    connect(socket_, qOverload<QAbstractSocket::SocketError>(&QWebSocket::error), this,
            [this](QAbstractSocket::SocketError) { lastNetworkError_ = socket_->errorString(); });
    connect(socket_, &QWebSocket::disconnected, this, &ClassroomClient::onDisconnected);
    setState(token_.isEmpty() ? State::Connecting : State::Reconnecting);
    socket_->open(options_.url);
}

void ClassroomClient::leave() {
    leaving_ = true;
    reconnect_.stop();
    heartbeat_.stop();
    if (socket_) socket_->close();
    setState(State::Disconnected);
}

void ClassroomClient::stop(const QString& reason) {
    stopReason_ = reason;
    leaving_ = true;
    reconnect_.stop();
    heartbeat_.stop();
    if (socket_) socket_->close();
    setState(State::Disconnected);
}

void ClassroomClient::onDisconnected() {
    heartbeat_.stop();
    if (leaving_ || !options_.reconnect) {
        setState(State::Disconnected);
        return;
    }
    // A server never reached (a wrong address, nothing listening) is not
    // tried for ever: a class that was joined is.
    if (!everJoined_ && ++failedFirstAttempts_ >= kFirstAttempts)
        return stop(tr("%1 cannot be reached (%2); check the address and that the class's "
                       "server runs")
                        .arg(options_.url.toString(),
                             lastNetworkError_.isEmpty() ? tr("no answer") : lastNetworkError_));
    setState(State::Reconnecting);
    // Backoff with jitter, so a class whose server restarts does not come
    // back all in the same millisecond.
    const int jitter = static_cast<int>(QRandomGenerator::global()->bounded(backoffMs_ / 4 + 1));
    reconnect_.start(backoffMs_ + jitter);
    backoffMs_ = std::min(backoffMs_ * 2, options_.maxBackoffMs);
}

void ClassroomClient::send(MessageType type, ClientBody body) {
    if (!socket_ || socket_->state() != QAbstractSocket::ConnectedState) return;
    socket_->sendTextMessage(
        QString::fromStdString(encodeClientMessage(ClientMessage{type, std::move(body)})));
}

void ClassroomClient::submitEdit(const QString& sceneText) {
    lastEdit_ = sceneText;
    // Before the first welcome there is no version (-1) and the server
    // refuses anything but a join; a version is never negative on the wire.
    send(MessageType::Edit, EditMessage{std::max<qint64>(version_, 0), utf8(sceneText)});
}

void ClassroomClient::releaseLock() {
    send(MessageType::Release);
}

void ClassroomClient::sendChat(const QString& text) {
    send(MessageType::Chat, ChatMessage{utf8(text)});
}

void ClassroomClient::requestVersion(qint64 version) {
    send(MessageType::History, HistoryMessage{std::max<qint64>(version, 0)});
}

void ClassroomClient::takeLock() {
    send(MessageType::TakeLock);
}
void ClassroomClient::breakLock() {
    send(MessageType::BreakLock);
}

void ClassroomClient::setFrozen(bool frozen) {
    send(MessageType::Freeze, FreezeMessage{frozen});
}

void ClassroomClient::pushScene(const QString& sceneText) {
    send(MessageType::Push, PushMessage{utf8(sceneText)});
}

void ClassroomClient::takeSnapshot(const QString& label) {
    send(MessageType::Snapshot, SnapshotMessage{utf8(label)});
}

void ClassroomClient::setAnonymous(bool anonymous) {
    send(MessageType::Anonymise, AnonymiseMessage{anonymous});
}

bool ClassroomClient::reofferPendingEdit() {
    if (pendingEdit_.isEmpty()) return false;
    const QString edit = pendingEdit_;
    discardPendingEdit();
    submitEdit(edit);
    return true;
}

void ClassroomClient::discardPendingEdit() {
    if (pendingEdit_.isEmpty()) return;
    pendingEdit_.clear();
    emit pendingEditChanged();
}

void ClassroomClient::onMembers(const std::vector<MemberEntry>& list) {
    members_.clear();
    for (const MemberEntry& m : list)
        members_.push_back({m.id, QString::fromStdString(m.name), m.role, m.connected});
    emit membersChanged();
}

void ClassroomClient::onLock(const std::optional<LockHolderEntry>& holder) {
    if (holder)
        lockHolder_ = Member{holder->id, QString::fromStdString(holder->name), Role::Student, true};
    else
        lockHolder_.reset();
    emit lockChanged();
    if (hasPendingEdit() && (!lockHolder_ || holdsLock())) emit pendingEditCanBeApplied();
}

void ClassroomClient::onWelcome(const WelcomeMessage& w) {
    token_ = QString::fromStdString(w.token);
    memberId_ = w.id;
    shownName_ = QString::fromStdString(w.name);
    frozen_ = w.frozen;
    anonymous_ = w.anonymous;
    backoffMs_ = options_.initialBackoffMs;
    everJoined_ = true;
    lastNetworkError_.clear();
    const QString scene = QString::fromStdString(w.scene);
    const bool changed = w.version != version_ || scene != scene_;
    version_ = w.version;
    scene_ = scene;
    onMembers(w.members);
    setState(State::Joined);
    heartbeat_.start(options_.heartbeatMs);
    emit joined(w.resumed);
    // The chat before this member came (kept in the class's log).
    if (w.chat)
        for (const EarlierChat& c : *w.chat)
            emit chatReceived(c.from.empty() ? tr("(earlier)") : QString::fromStdString(c.from),
                              QString::fromStdString(c.text));
    if (changed) emit sceneChanged(version_, QString(), scene_);
    onLock(w.lock);
}

void ClassroomClient::onScene(const SceneMessage& m) {
    version_ = m.version;
    scene_ = QString::fromStdString(m.scene);
    if (m.authorId == memberId_) lastEdit_.clear();
    emit sceneChanged(version_, QString::fromStdString(m.author), scene_);
}

void ClassroomClient::onRefused(const RefusedMessage& m) {
    Refusal r;
    r.reason = m.reason;
    r.message = QString::fromStdString(m.message);
    r.version = m.version;
    if (m.holder) r.holder = QString::fromStdString(m.holder->name);
    r.command = QString::fromStdString(m.command);
    r.diagnostics = m.diagnostics;
    // An edit refused for want of the lock, or overtaken, is kept for its author.
    if (r.command.isEmpty() && !lastEdit_.isEmpty() &&
        (r.reason == RefusalReason::Locked || r.reason == RefusalReason::Stale)) {
        pendingEdit_ = lastEdit_;
        lastEdit_.clear();
        emit pendingEditChanged();
    }
    emit refused(r);
    if (hasPendingEdit() && r.reason == RefusalReason::Stale && (!lockHolder_ || holdsLock()))
        emit pendingEditCanBeApplied();
}

void ClassroomClient::onError(const ErrorMessage& m) {
    // A join the server will never accept is not retried.
    switch (m.code) {
    case ErrorCode::WrongClass:
    case ErrorCode::BadKey:
    case ErrorCode::BadName:
    case ErrorCode::TooManyJoins:
    case ErrorCode::ClassFull:
        emit errorReceived(m.code, QString::fromStdString(m.message));
        return stop(QString::fromStdString(m.message));
    case ErrorCode::Malformed:
    case ErrorCode::UnknownType:
    case ErrorCode::NotJoined:
    case ErrorCode::AlreadyJoined:
    case ErrorCode::Forbidden:
    case ErrorCode::TooLarge:
    case ErrorCode::NotFound:
    case ErrorCode::Server:
        break;
    }
    emit errorReceived(m.code, QString::fromStdString(m.message));
}

void ClassroomClient::received(const QString& text) {
    const ParsedServerMessage parsed = parseServerMessage(utf8(text));
    // A malformed frame, or a newer server's message this client does not
    // know, is passed over: the next scene or presence brings it up to date.
    const auto* message = std::get_if<ServerMessage>(&parsed);
    if (!message) return;
    std::visit(
        Overloaded{
            [this](const WelcomeMessage& m) { onWelcome(m); },
            [this](const SceneMessage& m) { onScene(m); },
            [this](const RefusedMessage& m) { onRefused(m); },
            [this](const ErrorMessage& m) { onError(m); },
            [this](const ChatLineMessage& m) {
                emit chatReceived(QString::fromStdString(m.from), QString::fromStdString(m.text));
            },
            [this](const NoticeMessage& m) { emit noticeReceived(QString::fromStdString(m.text)); },
            [this](const PresenceMessage& m) { onMembers(m.members); },
            [this](const LockMessage& m) { onLock(m.holder); },
            [this](const FrozenMessage& m) {
                frozen_ = m.frozen;
                emit frozenChanged(frozen_);
            },
            [this](const SavedMessage& m) {
                emit saved(m.version, QString::fromStdString(m.label));
            },
            [this](const VersionMessage& m) {
                emit versionReceived(m.version, QString::fromStdString(m.author),
                                     QString::fromStdString(m.scene));
            },
        },
        *message);
}

} // namespace fl::classroom
