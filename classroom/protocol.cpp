#include "protocol.h"

#include "json_fields.h"
#include "member_name.h"
#include "text/kind_names.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include <array>
#include <cmath>
#include <utility>

namespace fl::classroom {

namespace {

constexpr text::KindNames<MessageType, 22> kMessageNames{{
    {"join", MessageType::Join},           {"edit", MessageType::Edit},
    {"release", MessageType::Release},     {"chat", MessageType::Chat},
    {"heartbeat", MessageType::Heartbeat}, {"history", MessageType::History},
    {"take-lock", MessageType::TakeLock},  {"break-lock", MessageType::BreakLock},
    {"freeze", MessageType::Freeze},       {"push", MessageType::Push},
    {"snapshot", MessageType::Snapshot},   {"anonymise", MessageType::Anonymise},
    {"welcome", MessageType::Welcome},     {"error", MessageType::Error},
    {"scene", MessageType::Scene},         {"refused", MessageType::Refused},
    {"presence", MessageType::Presence},   {"lock", MessageType::Lock},
    {"frozen", MessageType::Frozen},       {"notice", MessageType::Notice},
    {"saved", MessageType::Saved},         {"version", MessageType::Version},
}};
constexpr text::KindNames<Role, 3> kRoleNames{{
    {"student", Role::Student},
    {"instructor", Role::Instructor},
    {"observer", Role::Observer},
}};
constexpr text::KindNames<RefusalReason, 7> kReasonNames{{
    {"locked", RefusalReason::Locked},
    {"stale", RefusalReason::Stale},
    {"invalid", RefusalReason::Invalid},
    {"read-only", RefusalReason::ReadOnly},
    {"rate", RefusalReason::Rate},
    {"too-large", RefusalReason::TooLarge},
    {"too-costly", RefusalReason::TooCostly},
}};
constexpr text::KindNames<ErrorCode, 13> kErrorNames{{
    {"malformed", ErrorCode::Malformed},
    {"unknown-type", ErrorCode::UnknownType},
    {"wrong-class", ErrorCode::WrongClass},
    {"bad-key", ErrorCode::BadKey},
    {"bad-name", ErrorCode::BadName},
    {"not-joined", ErrorCode::NotJoined},
    {"already-joined", ErrorCode::AlreadyJoined},
    {"forbidden", ErrorCode::Forbidden},
    {"too-many-joins", ErrorCode::TooManyJoins},
    {"class-full", ErrorCode::ClassFull},
    {"too-large", ErrorCode::TooLarge},
    {"not-found", ErrorCode::NotFound},
    {"server", ErrorCode::Server},
}};
constexpr text::KindNames<EditKind, 5> kEditKindNames{{
    {"start", EditKind::Start},
    {"edit", EditKind::Edit},
    {"command", EditKind::Command},
    {"push", EditKind::Push},
    {"undo", EditKind::Undo},
}};

ClientBody readBody(MessageType type, JsonFields& r, const ClassroomLimits& limits) {
    switch (type) {
    case MessageType::Join: {
        JoinMessage m;
        m.classCode = r.text("class", {limits.maxClassCodeChars, true, true, false});
        m.name = r.text("name", {limits.maxNameChars, true, true, false, ErrorCode::BadName});
        const std::string role = r.text("role", {16, false, true, false});
        if (r.has("role") && role.empty())
            r.fail(ErrorCode::Malformed,
                   "join: \"role\" is student, instructor or observer; leave it out for student");
        if (!role.empty()) {
            if (auto known = roleNamed(role))
                m.role = *known;
            else
                r.fail(ErrorCode::Malformed,
                       "join: \"role\" is student, instructor or observer, not '" + role + "'");
        }
        m.key = r.text("key", {256, false, true, false});
        m.resume = r.text("resume", {128, false, true, false});
        m.since = r.count("since", false);
        return m;
    }
    case MessageType::Edit: {
        EditMessage m;
        m.version = r.count("version");
        // The scene's own size limit is a refusal (too-large), checked by the class.
        m.scene = r.text("scene", {limits.maxMessageBytes, true, true, true});
        return m;
    }
    case MessageType::Chat:
        return ChatMessage{
            r.text("text", {limits.maxChatChars, true, true, true, ErrorCode::TooLarge})};
    case MessageType::Freeze:
        return FreezeMessage{r.boolean("frozen", true)};
    case MessageType::Push:
        return PushMessage{r.text("scene", {limits.maxMessageBytes, true, true, true})};
    case MessageType::Snapshot:
        return SnapshotMessage{
            r.text("label", {limits.maxLabelChars, false, true, false, ErrorCode::TooLarge})};
    case MessageType::Anonymise:
        return AnonymiseMessage{r.boolean("anonymous", true)};
    case MessageType::History:
        return HistoryMessage{r.count("version")};
    case MessageType::Release:
    case MessageType::Heartbeat:
    case MessageType::TakeLock:
    case MessageType::BreakLock:
        return std::monostate{};
    case MessageType::Welcome:
    case MessageType::Error:
    case MessageType::Scene:
    case MessageType::Refused:
    case MessageType::Presence:
    case MessageType::Lock:
    case MessageType::Frozen:
    case MessageType::Notice:
    case MessageType::Saved:
    case MessageType::Version:
        break;
    }
    r.fail(ErrorCode::UnknownType,
           "'" + std::string(nameOf(type)) + "' is sent by the server, not by clients");
    return std::monostate{};
}

} // namespace

std::string_view nameOf(MessageType type) {
    return text::nameOfKind(kMessageNames, type);
}
std::string_view nameOf(Role role) {
    return text::nameOfKind(kRoleNames, role);
}
std::string_view nameOf(RefusalReason reason) {
    return text::nameOfKind(kReasonNames, reason);
}
std::string_view nameOf(ErrorCode code) {
    return text::nameOfKind(kErrorNames, code);
}
std::optional<MessageType> messageTypeNamed(std::string_view name) {
    return text::kindNamed(kMessageNames, name);
}
std::optional<Role> roleNamed(std::string_view name) {
    return text::kindNamed(kRoleNames, name);
}
std::optional<RefusalReason> refusalReasonNamed(std::string_view name) {
    return text::kindNamed(kReasonNames, name);
}
std::optional<ErrorCode> errorCodeNamed(std::string_view name) {
    return text::kindNamed(kErrorNames, name);
}
std::string_view nameOf(EditKind kind) {
    return text::nameOfKind(kEditKindNames, kind);
}
std::optional<EditKind> editKindNamed(std::string_view name) {
    return text::kindNamed(kEditKindNames, name);
}

bool isCleanText(std::string_view s, bool allowLineBreaks) {
    for (std::size_t i = 0; i < s.size();) {
        const auto c = static_cast<unsigned char>(s[i]);
        if (c < 0x80) {
            const bool lineBreak = c == '\n' || c == '\r' || c == '\t';
            if ((c < 0x20 && !(allowLineBreaks && lineBreak)) || c == 0x7f) return false;
            ++i;
            continue;
        }
        int extra = 0;
        if (c >= 0xc2 && c <= 0xdf)
            extra = 1;
        else if (c >= 0xe0 && c <= 0xef)
            extra = 2;
        else if (c >= 0xf0 && c <= 0xf4)
            extra = 3;
        else
            return false;
        if (s.size() - i <= static_cast<std::size_t>(extra)) return false;
        for (int k = 1; k <= extra; ++k)
            if ((static_cast<unsigned char>(s[i + k]) & 0xc0) != 0x80) return false;
        i += extra + 1;
    }
    return true;
}

namespace {

void writeBody(QJsonObject& o, const ClientBody& body) {
    std::visit(
        [&](const auto& m) {
            using T = std::decay_t<decltype(m)>;
            if constexpr (std::is_same_v<T, JoinMessage>) {
                o["class"] = qText(m.classCode);
                o["name"] = qText(m.name);
                o["role"] = qText(nameOf(m.role));
                if (!m.key.empty()) o["key"] = qText(m.key);
                if (!m.resume.empty()) o["resume"] = qText(m.resume);
                if (m.since) o["since"] = QJsonValue(qint64(*m.since));
            } else if constexpr (std::is_same_v<T, EditMessage>) {
                o["version"] = QJsonValue(qint64(m.version));
                o["scene"] = qText(m.scene);
            } else if constexpr (std::is_same_v<T, ChatMessage>) {
                o["text"] = qText(m.text);
            } else if constexpr (std::is_same_v<T, FreezeMessage>) {
                o["frozen"] = m.frozen;
            } else if constexpr (std::is_same_v<T, PushMessage>) {
                o["scene"] = qText(m.scene);
            } else if constexpr (std::is_same_v<T, SnapshotMessage>) {
                o["label"] = qText(m.label);
            } else if constexpr (std::is_same_v<T, AnonymiseMessage>) {
                o["anonymous"] = m.anonymous;
            } else if constexpr (std::is_same_v<T, HistoryMessage>) {
                o["version"] = QJsonValue(qint64(m.version));
            }
        },
        body);
}

} // namespace

std::string encodeClientMessage(const ClientMessage& message) {
    QJsonObject o{{"type", qText(nameOf(message.type))}};
    writeBody(o, message.body);
    return QJsonDocument(o).toJson(QJsonDocument::Compact).toStdString();
}

ParsedClientMessage parseClientMessage(std::string_view frame, const ClassroomLimits& limits) {
    if (frame.size() > limits.maxMessageBytes)
        return ProtocolError{ErrorCode::TooLarge, "a message may hold at most " +
                                                      std::to_string(limits.maxMessageBytes) +
                                                      " bytes"};
    auto typed = readTypedObject(frame);
    if (auto* e = std::get_if<ProtocolError>(&typed)) return *e;
    const TypedObject& t = std::get<TypedObject>(typed);
    std::optional<ProtocolError> failure;
    JsonFields reader(t.object, std::string(nameOf(t.type)), failure);
    ClientMessage message{t.type, readBody(t.type, reader, limits)};
    if (failure) return *failure;
    return message;
}

} // namespace fl::classroom
