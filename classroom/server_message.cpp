#include "server_message.h"

#include "json_fields.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QJsonValue>
#include <QString>

#include <type_traits>

namespace fl::classroom {

namespace {

// ---- writing -----------------------------------------------------------

// Whole numbers are written as integers (exact below 2^53, which the
// reader checks).
QJsonValue number(std::int64_t n) {
    return QJsonValue(qint64(n));
}

QJsonValue holderJson(const std::optional<LockHolderEntry>& h) {
    if (!h) return QJsonValue::Null;
    return QJsonObject{{"id", number(h->id)}, {"name", qText(h->name)}};
}

QJsonArray membersJson(const std::vector<MemberEntry>& members) {
    QJsonArray list;
    for (const MemberEntry& m : members)
        list.append(QJsonObject{{"id", number(m.id)},
                                {"name", qText(m.name)},
                                {"role", qText(nameOf(m.role))},
                                {"connected", m.connected}});
    return list;
}

void write(QJsonObject& o, const WelcomeMessage& m) {
    o["id"] = number(m.id);
    o["token"] = qText(m.token);
    o["name"] = qText(m.name);
    o["role"] = qText(nameOf(m.role));
    o["version"] = number(m.version);
    o["scene"] = qText(m.scene);
    o["frozen"] = m.frozen;
    o["anonymous"] = m.anonymous;
    o["resumed"] = m.resumed;
    o["members"] = membersJson(m.members);
    o["lock"] = holderJson(m.lock);
    if (m.missed) {
        QJsonArray missed;
        for (const MissedVersion& v : *m.missed)
            missed.append(QJsonObject{{"version", number(v.version)},
                                      {"author", qText(v.author)},
                                      {"kind", qText(nameOf(v.kind))}});
        o["missed"] = missed;
    }
    if (m.chat) {
        QJsonArray chat;
        for (const EarlierChat& c : *m.chat)
            chat.append(QJsonObject{
                {"from", qText(c.from)}, {"text", qText(c.text)}, {"unixMs", number(c.unixMs)}});
        o["chat"] = chat;
    }
    o["limits"] = QJsonObject{{"maxMessageBytes", number(m.limits.maxMessageBytes)},
                              {"maxSceneBytes", number(m.limits.maxSceneBytes)},
                              {"maxNodes", number(m.limits.maxNodes)},
                              {"maxFormulaBytes", number(m.limits.maxFormulaBytes)},
                              {"maxChatChars", number(m.limits.maxChatChars)},
                              {"leaseMs", number(m.limits.leaseMs)}};
}
void write(QJsonObject& o, const ErrorMessage& m) {
    o["code"] = qText(nameOf(m.code));
    o["message"] = qText(m.message);
}
void write(QJsonObject& o, const SceneMessage& m) {
    o["version"] = number(m.version);
    o["author"] = qText(m.author);
    if (m.authorId) o["authorId"] = number(*m.authorId);
    o["kind"] = qText(nameOf(m.kind));
    o["scene"] = qText(m.scene);
}
void write(QJsonObject& o, const RefusedMessage& m) {
    o["reason"] = qText(nameOf(m.reason));
    o["message"] = qText(m.message);
    o["version"] = number(m.version);
    if (!m.command.empty()) o["command"] = qText(m.command);
    if (m.holder) {
        o["holder"] = qText(m.holder->name);
        o["holderId"] = number(m.holder->id);
    }
    if (!m.diagnostics.empty()) {
        QJsonArray list;
        for (const RefusalDiagnostic& d : m.diagnostics) {
            QJsonObject j{
                {"line", number(d.line)},
                {"column", number(d.column)},
                {"severity", d.severity == DiagnosticSeverity::Error ? "error" : "warning"},
                {"message", qText(d.message)}};
            if (!d.suggestion.empty()) j["suggestion"] = qText(d.suggestion);
            list.append(j);
        }
        o["diagnostics"] = list;
    }
}
void write(QJsonObject& o, const ChatLineMessage& m) {
    o["from"] = qText(m.from);
    o["fromId"] = number(m.fromId);
    o["text"] = qText(m.text);
}
void write(QJsonObject& o, const NoticeMessage& m) {
    o["text"] = qText(m.text);
}
void write(QJsonObject& o, const PresenceMessage& m) {
    o["members"] = membersJson(m.members);
}
void write(QJsonObject& o, const LockMessage& m) {
    o["holder"] = holderJson(m.holder);
    if (m.holder) o["expiresInMs"] = number(m.expiresInMs);
}
void write(QJsonObject& o, const FrozenMessage& m) {
    o["frozen"] = m.frozen;
}
void write(QJsonObject& o, const SavedMessage& m) {
    o["version"] = number(m.version);
    o["snapshot"] = number(m.snapshot);
    o["label"] = qText(m.label);
}
void write(QJsonObject& o, const VersionMessage& m) {
    o["version"] = number(m.version);
    o["author"] = qText(m.author);
    o["kind"] = qText(nameOf(m.kind));
    o["unixMs"] = number(m.unixMs);
    o["scene"] = qText(m.scene);
}

// ---- reading -----------------------------------------------------------
// Text from the server is taken as it is (a starting scene may hold any
// character); the window draws others' text literally, never as markup.

std::string anyText(JsonFields& r, const char* field, bool required = true) {
    return r.text(field, JsonFields::TextRule{.required = required, .clean = false});
}

std::vector<MemberEntry> readMembers(JsonFields& r) {
    std::vector<MemberEntry> out;
    for (JsonFields& m : r.objects("members", true))
        out.push_back({m.count("id"), anyText(m, "name"),
                       m.kind<Role>("role", roleNamed, false).value_or(Role::Student),
                       m.boolean("connected", true)});
    return out;
}

std::optional<LockHolderEntry> readHolder(JsonFields& r, const char* field) {
    auto h = r.object(field);
    if (!h) return std::nullopt;
    return LockHolderEntry{h->count("id"), anyText(*h, "name")};
}

ServerMessage readWelcome(JsonFields& r) {
    WelcomeMessage m;
    m.id = r.count("id");
    m.token = anyText(r, "token");
    m.name = anyText(r, "name");
    m.role = r.kind<Role>("role", roleNamed, false).value_or(Role::Student);
    m.version = r.count("version");
    m.scene = anyText(r, "scene");
    m.frozen = r.boolean("frozen", false);
    m.anonymous = r.boolean("anonymous", false);
    m.resumed = r.boolean("resumed", false);
    m.members = readMembers(r);
    m.lock = readHolder(r, "lock");
    if (r.has("missed")) {
        m.missed.emplace();
        for (JsonFields& v : r.objects("missed", true))
            m.missed->push_back(
                {v.count("version"), anyText(v, "author", false),
                 v.kind<EditKind>("kind", editKindNamed, false).value_or(EditKind::Edit)});
    }
    if (r.has("chat")) {
        m.chat.emplace();
        for (JsonFields& c : r.objects("chat", true))
            m.chat->push_back({anyText(c, "from", false), anyText(c, "text"),
                               c.count("unixMs", false).value_or(0)});
    }
    if (auto l = r.object("limits")) {
        m.limits.maxMessageBytes = l->count("maxMessageBytes", false).value_or(0);
        m.limits.maxSceneBytes = l->count("maxSceneBytes", false).value_or(0);
        m.limits.maxNodes = l->count("maxNodes", false).value_or(0);
        m.limits.maxFormulaBytes = l->count("maxFormulaBytes", false).value_or(0);
        m.limits.maxChatChars = l->count("maxChatChars", false).value_or(0);
        m.limits.leaseMs = l->count("leaseMs", false).value_or(0);
    }
    return m;
}

ServerMessage readRefused(JsonFields& r) {
    RefusedMessage m;
    m.reason =
        r.kind<RefusalReason>("reason", refusalReasonNamed, true).value_or(RefusalReason::Invalid);
    m.message = anyText(r, "message");
    m.version = r.count("version");
    m.command = anyText(r, "command", false);
    if (r.has("holder") || r.has("holderId"))
        m.holder = LockHolderEntry{r.count("holderId"), anyText(r, "holder")};
    for (JsonFields& d : r.objects("diagnostics", false)) {
        const std::string severity = anyText(d, "severity", false);
        if (!severity.empty() && severity != "error" && severity != "warning")
            d.fail(ErrorCode::Malformed,
                   "refused: a diagnostic's \"severity\" is error or warning");
        m.diagnostics.push_back(
            {d.count("line"), d.count("column"),
             severity == "warning" ? DiagnosticSeverity::Warning : DiagnosticSeverity::Error,
             anyText(d, "message"), anyText(d, "suggestion", false)});
    }
    return m;
}

ServerMessage readBody(MessageType type, JsonFields& r) {
    switch (type) {
    case MessageType::Welcome:
        return readWelcome(r);
    case MessageType::Error:
        return ErrorMessage{
            r.kind<ErrorCode>("code", errorCodeNamed, true).value_or(ErrorCode::Malformed),
            anyText(r, "message")};
    case MessageType::Scene: {
        SceneMessage m;
        m.version = r.count("version");
        m.author = anyText(r, "author", false);
        m.authorId = r.count("authorId", false);
        m.kind = r.kind<EditKind>("kind", editKindNamed, false).value_or(EditKind::Edit);
        m.scene = anyText(r, "scene");
        return m;
    }
    case MessageType::Refused:
        return readRefused(r);
    case MessageType::Chat:
        return ChatLineMessage{anyText(r, "from", false), r.count("fromId", false).value_or(0),
                               anyText(r, "text")};
    case MessageType::Notice:
        return NoticeMessage{anyText(r, "text")};
    case MessageType::Presence:
        return PresenceMessage{readMembers(r)};
    case MessageType::Lock: {
        LockMessage m;
        m.holder = readHolder(r, "holder");
        if (m.holder) m.expiresInMs = r.count("expiresInMs", false).value_or(0);
        return m;
    }
    case MessageType::Frozen:
        return FrozenMessage{r.boolean("frozen", true)};
    case MessageType::Saved:
        return SavedMessage{r.count("version"), r.count("snapshot", false).value_or(0),
                            anyText(r, "label", false)};
    case MessageType::Version: {
        VersionMessage m;
        m.version = r.count("version");
        m.author = anyText(r, "author", false);
        m.kind = r.kind<EditKind>("kind", editKindNamed, false).value_or(EditKind::Edit);
        m.unixMs = r.count("unixMs", false).value_or(0);
        m.scene = anyText(r, "scene");
        return m;
    }
    case MessageType::Join:
    case MessageType::Edit:
    case MessageType::Release:
    case MessageType::Heartbeat:
    case MessageType::History:
    case MessageType::TakeLock:
    case MessageType::BreakLock:
    case MessageType::Freeze:
    case MessageType::Push:
    case MessageType::Snapshot:
    case MessageType::Anonymise:
        break;
    }
    r.fail(ErrorCode::UnknownType,
           "'" + std::string(nameOf(type)) + "' is sent by clients, not by the server");
    return NoticeMessage{};
}

} // namespace

MessageType typeOf(const ServerMessage& message) {
    return std::visit(Overloaded{
                          [](const WelcomeMessage&) { return MessageType::Welcome; },
                          [](const ErrorMessage&) { return MessageType::Error; },
                          [](const SceneMessage&) { return MessageType::Scene; },
                          [](const RefusedMessage&) { return MessageType::Refused; },
                          [](const ChatLineMessage&) { return MessageType::Chat; },
                          [](const NoticeMessage&) { return MessageType::Notice; },
                          [](const PresenceMessage&) { return MessageType::Presence; },
                          [](const LockMessage&) { return MessageType::Lock; },
                          [](const FrozenMessage&) { return MessageType::Frozen; },
                          [](const SavedMessage&) { return MessageType::Saved; },
                          [](const VersionMessage&) { return MessageType::Version; },
                      },
                      message);
}

std::string encodeServerMessage(const ServerMessage& message) {
    QJsonObject o{{"type", qText(nameOf(typeOf(message)))}};
    std::visit([&](const auto& m) { write(o, m); }, message);
    return QJsonDocument(o).toJson(QJsonDocument::Compact).toStdString();
}

ParsedServerMessage parseServerMessage(std::string_view frame) {
    auto typed = readTypedObject(frame);
    if (auto* e = std::get_if<ProtocolError>(&typed)) return *e;
    const TypedObject& t = std::get<TypedObject>(typed);
    std::optional<ProtocolError> failure;
    JsonFields reader(t.object, std::string(nameOf(t.type)), failure);
    ServerMessage message = readBody(t.type, reader);
    if (failure) return *failure;
    return message;
}

} // namespace fl::classroom
