#include "protocol.h"

#include "member_name.h"
#include "text/kind_names.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonParseError>
#include <QJsonValue>

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

struct FieldReader {
    const QJsonObject& object;
    const char* type;
    std::optional<ProtocolError> failure;

    void fail(ErrorCode code, std::string message) {
        if (!failure) failure = ProtocolError{code, std::move(message)};
    }
    bool has(const char* field) const { return object.contains(QLatin1String(field)); }

    std::string text(const char* field, std::size_t maxChars, bool required, bool lineBreaks,
                     ErrorCode tooLong = ErrorCode::Malformed) {
        const QJsonValue v = object.value(QLatin1String(field));
        if (v.isUndefined()) {
            if (required)
                fail(ErrorCode::Malformed, std::string(type) + " needs a \"" + field + "\" string");
            return {};
        }
        if (!v.isString()) {
            fail(ErrorCode::Malformed, std::string(type) + ": \"" + field + "\" must be a string");
            return {};
        }
        std::string utf8 = v.toString().toStdString();
        if (characterCount(utf8) > maxChars) { // characters, not UTF-16 units
            fail(tooLong, std::string(type) + ": \"" + field + "\" is longer than " +
                              std::to_string(maxChars) + " characters");
            return {};
        }
        if (!isCleanText(utf8, lineBreaks)) {
            fail(ErrorCode::Malformed,
                 std::string(type) + ": \"" + field + "\" holds control characters");
            return {};
        }
        return utf8;
    }

    std::optional<std::int64_t> integer(const char* field, bool required) {
        const QJsonValue v = object.value(QLatin1String(field));
        if (v.isUndefined()) {
            if (required)
                fail(ErrorCode::Malformed, std::string(type) + " needs a \"" + field + "\" number");
            return std::nullopt;
        }
        const double d = v.toDouble(-1.5);
        // JSON numbers are doubles: whole, non-negative, and exact (below 2^53).
        if (!v.isDouble() || d < 0 || d != std::floor(d) || d > 9007199254740991.0) {
            fail(ErrorCode::Malformed,
                 std::string(type) + ": \"" + field + "\" must be a whole number >= 0");
            return std::nullopt;
        }
        return static_cast<std::int64_t>(d);
    }

    bool boolean(const char* field, bool fallback) {
        const QJsonValue v = object.value(QLatin1String(field));
        if (v.isUndefined()) return fallback;
        if (!v.isBool()) {
            fail(ErrorCode::Malformed,
                 std::string(type) + ": \"" + field + "\" must be true or false");
            return fallback;
        }
        return v.toBool();
    }
};

ClientBody readBody(MessageType type, FieldReader& r, const ClassroomLimits& limits) {
    switch (type) {
    case MessageType::Join: {
        JoinMessage m;
        m.classCode = r.text("class", limits.maxClassCodeChars, true, false);
        m.name = r.text("name", limits.maxNameChars, true, false, ErrorCode::BadName);
        const std::string role = r.text("role", 16, false, false);
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
        m.key = r.text("key", 256, false, false);
        m.resume = r.text("resume", 128, false, false);
        m.since = r.integer("since", false);
        return m;
    }
    case MessageType::Edit: {
        EditMessage m;
        m.version = r.integer("version", true).value_or(0);
        // The scene's own size limit is a refusal (too-large), checked by the class.
        m.scene = r.text("scene", limits.maxMessageBytes, true, true);
        return m;
    }
    case MessageType::Chat:
        return ChatMessage{r.text("text", limits.maxChatChars, true, true, ErrorCode::TooLarge)};
    case MessageType::Freeze:
        return FreezeMessage{r.boolean("frozen", true)};
    case MessageType::Push:
        return PushMessage{r.text("scene", limits.maxMessageBytes, true, true)};
    case MessageType::Snapshot:
        return SnapshotMessage{
            r.text("label", limits.maxLabelChars, false, false, ErrorCode::TooLarge)};
    case MessageType::Anonymise:
        return AnonymiseMessage{r.boolean("anonymous", true)};
    case MessageType::History:
        return HistoryMessage{r.integer("version", true).value_or(0)};
    case MessageType::Release:
    case MessageType::Heartbeat:
    case MessageType::TakeLock:
    case MessageType::BreakLock:
        return std::monostate{};
    default:
        r.fail(ErrorCode::UnknownType,
               "'" + std::string(nameOf(type)) + "' is sent by the server, not by clients");
        return std::monostate{};
    }
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

ParsedClientMessage parseClientMessage(std::string_view frame, const ClassroomLimits& limits) {
    if (frame.size() > limits.maxMessageBytes)
        return ProtocolError{ErrorCode::TooLarge, "a message may hold at most " +
                                                      std::to_string(limits.maxMessageBytes) +
                                                      " bytes"};
    QJsonParseError error{};
    const QJsonDocument doc = QJsonDocument::fromJson(
        QByteArray::fromRawData(frame.data(), static_cast<qsizetype>(frame.size())), &error);
    if (error.error != QJsonParseError::NoError)
        return ProtocolError{ErrorCode::Malformed, "not JSON at byte " +
                                                       std::to_string(error.offset) + ": " +
                                                       error.errorString().toStdString()};
    if (!doc.isObject())
        return ProtocolError{ErrorCode::Malformed, "a message is a JSON object with a \"type\""};
    const QJsonObject object = doc.object();
    const QJsonValue typeValue = object.value(QLatin1String("type"));
    if (!typeValue.isString())
        return ProtocolError{ErrorCode::Malformed, "a message needs a \"type\" string"};
    const std::string typeName = typeValue.toString().left(64).toStdString();
    const auto type = messageTypeNamed(typeName);
    if (!type) {
        std::string shown;
        for (char c : typeName)
            shown += (static_cast<unsigned char>(c) < 0x20 || c == 0x7f) ? '?' : c;
        return ProtocolError{ErrorCode::UnknownType, "unknown message type '" + shown + "'"};
    }
    const std::string typeText(nameOf(*type));
    FieldReader reader{object, typeText.c_str(), std::nullopt};
    ClientMessage message{*type, readBody(*type, reader, limits)};
    if (reader.failure) return *reader.failure;
    return message;
}

} // namespace fl::classroom
