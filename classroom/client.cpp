#include "client.h"

#include <QJsonDocument>
#include <QRandomGenerator>
#include <QWebSocket>

#include <algorithm>

namespace fl::classroom {

namespace {

QString typeName(MessageType type) {
    return QString::fromLatin1(nameOf(type).data(), nameOf(type).size());
}

QJsonObject typed(MessageType type) {
    return {{"type", typeName(type)}};
}

// Scene frames carry whole scenes, JSON-escaped: allow well over the
// server's scene limit, but not Qt's 2 GiB default.
constexpr quint64 kMaxIncomingBytes = 16u << 20;

} // namespace

ClassroomClient::ClassroomClient(QObject* parent) : QObject(parent) {
    heartbeat_.setSingleShot(false);
    connect(&heartbeat_, &QTimer::timeout, this, [this] { send(typed(MessageType::Heartbeat)); });
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
        QJsonObject j = typed(MessageType::Join);
        j["class"] = options_.classCode;
        j["name"] = options_.name;
        j["role"] = QString::fromLatin1(nameOf(options_.role).data(), nameOf(options_.role).size());
        if (!options_.key.isEmpty()) j["key"] = options_.key;
        if (!token_.isEmpty()) j["resume"] = token_;
        if (version_ >= 0) j["since"] = static_cast<double>(version_);
        send(j);
    });
    connect(socket_, &QWebSocket::textMessageReceived, this, &ClassroomClient::received);
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

void ClassroomClient::onDisconnected() {
    heartbeat_.stop();
    if (leaving_ || !options_.reconnect) {
        setState(State::Disconnected);
        return;
    }
    setState(State::Reconnecting);
    // Backoff with jitter, so a class whose server restarts does not come
    // back all in the same millisecond.
    const int jitter = static_cast<int>(QRandomGenerator::global()->bounded(backoffMs_ / 4 + 1));
    reconnect_.start(backoffMs_ + jitter);
    backoffMs_ = std::min(backoffMs_ * 2, options_.maxBackoffMs);
}

void ClassroomClient::send(const QJsonObject& message) {
    if (!socket_ || socket_->state() != QAbstractSocket::ConnectedState) return;
    socket_->sendTextMessage(
        QString::fromUtf8(QJsonDocument(message).toJson(QJsonDocument::Compact)));
}

void ClassroomClient::submitEdit(const QString& sceneText) {
    QJsonObject o = typed(MessageType::Edit);
    o["version"] = static_cast<double>(version_);
    o["scene"] = sceneText;
    lastEdit_ = sceneText;
    send(o);
}

void ClassroomClient::releaseLock() {
    send(typed(MessageType::Release));
}

void ClassroomClient::sendChat(const QString& text) {
    QJsonObject o = typed(MessageType::Chat);
    o["text"] = text;
    send(o);
}

void ClassroomClient::requestVersion(qint64 version) {
    QJsonObject o = typed(MessageType::History);
    o["version"] = static_cast<double>(version);
    send(o);
}

void ClassroomClient::takeLock() {
    send(typed(MessageType::TakeLock));
}
void ClassroomClient::breakLock() {
    send(typed(MessageType::BreakLock));
}

void ClassroomClient::setFrozen(bool frozen) {
    QJsonObject o = typed(MessageType::Freeze);
    o["frozen"] = frozen;
    send(o);
}

void ClassroomClient::pushScene(const QString& sceneText) {
    QJsonObject o = typed(MessageType::Push);
    o["scene"] = sceneText;
    send(o);
}

void ClassroomClient::takeSnapshot(const QString& label) {
    QJsonObject o = typed(MessageType::Snapshot);
    o["label"] = label;
    send(o);
}

void ClassroomClient::setAnonymous(bool anonymous) {
    QJsonObject o = typed(MessageType::Anonymise);
    o["anonymous"] = anonymous;
    send(o);
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

void ClassroomClient::onMembers(const QJsonArray& list) {
    members_.clear();
    for (const QJsonValue& v : list) {
        const QJsonObject m = v.toObject();
        members_.push_back({m["id"].toInteger(), m["name"].toString(),
                            roleNamed(m["role"].toString().toStdString()).value_or(Role::Student),
                            m["connected"].toBool(true)});
    }
    emit membersChanged();
}

void ClassroomClient::onLock(const QJsonValue& holder) {
    if (holder.isObject()) {
        const QJsonObject h = holder.toObject();
        lockHolder_ = Member{h["id"].toInteger(), h["name"].toString(), Role::Student, true};
    } else {
        lockHolder_.reset();
    }
    emit lockChanged();
    if (hasPendingEdit() && (!lockHolder_ || holdsLock())) emit pendingEditCanBeApplied();
}

void ClassroomClient::onWelcome(const QJsonObject& o) {
    const bool resumed = o["resumed"].toBool();
    token_ = o["token"].toString();
    memberId_ = o["id"].toInteger();
    shownName_ = o["name"].toString();
    frozen_ = o["frozen"].toBool();
    anonymous_ = o["anonymous"].toBool();
    backoffMs_ = options_.initialBackoffMs;
    const qint64 version = o["version"].toInteger();
    const bool changed = version != version_ || o["scene"].toString() != scene_;
    version_ = version;
    scene_ = o["scene"].toString();
    onMembers(o["members"].toArray());
    setState(State::Joined);
    heartbeat_.start(options_.heartbeatMs);
    emit joined(resumed);
    // The chat before this member came (kept in the class's log).
    for (const QJsonValue& line : o["chat"].toArray()) {
        const QJsonObject c = line.toObject();
        const QString from = c["from"].toString();
        emit chatReceived(from.isEmpty() ? tr("(earlier)") : from, c["text"].toString());
    }
    if (changed) emit sceneChanged(version_, QString(), scene_);
    onLock(o["lock"]);
}

void ClassroomClient::received(const QString& text) {
    const QJsonObject o = QJsonDocument::fromJson(text.toUtf8()).object();
    const auto type = messageTypeNamed(o["type"].toString().toStdString());
    if (!type) return; // a newer server's message this client does not know
    switch (*type) {
    case MessageType::Welcome:
        return onWelcome(o);
    case MessageType::Scene:
        version_ = o["version"].toInteger();
        scene_ = o["scene"].toString();
        if (o["authorId"].toInteger() == memberId_) lastEdit_.clear();
        emit sceneChanged(version_, o["author"].toString(), scene_);
        return;
    case MessageType::Refused: {
        Refusal r;
        r.reason = refusalReasonNamed(o["reason"].toString().toStdString())
                       .value_or(RefusalReason::Invalid);
        r.message = o["message"].toString();
        r.version = o["version"].toInteger();
        r.holder = o["holder"].toString();
        r.command = o["command"].toString();
        r.diagnostics = o["diagnostics"].toArray();
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
        return;
    }
    case MessageType::Chat:
        return emit chatReceived(o["from"].toString(), o["text"].toString());
    case MessageType::Notice:
        return emit noticeReceived(o["text"].toString());
    case MessageType::Presence:
        return onMembers(o["members"].toArray());
    case MessageType::Lock:
        return onLock(o["holder"]);
    case MessageType::Frozen:
        frozen_ = o["frozen"].toBool();
        return emit frozenChanged(frozen_);
    case MessageType::Saved:
        return emit saved(o["version"].toInteger(), o["label"].toString());
    case MessageType::Version:
        return emit versionReceived(o["version"].toInteger(), o["author"].toString(),
                                    o["scene"].toString());
    case MessageType::Error: {
        const ErrorCode code =
            errorCodeNamed(o["code"].toString().toStdString()).value_or(ErrorCode::Malformed);
        // A join the server will never accept is not retried.
        if (code == ErrorCode::WrongClass || code == ErrorCode::BadKey ||
            code == ErrorCode::BadName || code == ErrorCode::TooManyJoins ||
            code == ErrorCode::ClassFull)
            leaving_ = true;
        return emit errorReceived(code, o["message"].toString());
    }
    default:
        return;
    }
}

} // namespace fl::classroom
