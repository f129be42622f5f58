#pragma once
// What the server says (docs/classroom-protocol.md), as types: one struct per
// message, one ServerMessage variant, one encoder the server uses and one
// decoder the client (and any tool) uses. A field is named in one place and
// every number is read with its range checked (json_fields.h), so the class
// of bug "a number cast from whatever the wire held" cannot come back.
#include "protocol.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>
#include <vector>

namespace fl::classroom {

struct MemberEntry {
    std::int64_t id = 0;
    std::string name;
    Role role = Role::Student;
    bool connected = true;
    bool operator==(const MemberEntry&) const = default;
};
struct LockHolderEntry {
    std::int64_t id = 0;
    std::string name;
    bool operator==(const LockHolderEntry&) const = default;
};
struct MissedVersion {
    std::int64_t version = 0;
    std::string author; // empty while the class is anonymous
    EditKind kind = EditKind::Edit;
    bool operator==(const MissedVersion&) const = default;
};
struct EarlierChat {
    std::string from; // empty while the class is anonymous
    std::string text;
    std::int64_t unixMs = 0;
    bool operator==(const EarlierChat&) const = default;
};
enum class DiagnosticSeverity { Error, Warning };
struct RefusalDiagnostic {
    std::int64_t line = 0; // 0: the scene as a whole
    std::int64_t column = 0;
    DiagnosticSeverity severity = DiagnosticSeverity::Error;
    std::string message;
    std::string suggestion; // may be empty
    bool operator==(const RefusalDiagnostic&) const = default;
};
// The limits a client should keep to (the welcome says them).
struct AnnouncedLimits {
    std::int64_t maxMessageBytes = 0;
    std::int64_t maxSceneBytes = 0;
    std::int64_t maxNodes = 0;
    std::int64_t maxFormulaBytes = 0;
    std::int64_t maxChatChars = 0;
    std::int64_t leaseMs = 0;
    bool operator==(const AnnouncedLimits&) const = default;
};

struct WelcomeMessage {
    std::int64_t id = 0;
    std::string token; // secret: resumes the seat
    std::string name;
    Role role = Role::Student;
    std::int64_t version = 0;
    std::string scene;
    bool frozen = false;
    bool anonymous = false;
    bool resumed = false;
    std::vector<MemberEntry> members;
    std::optional<LockHolderEntry> lock;
    std::optional<std::vector<MissedVersion>> missed; // only when the join said `since`
    std::optional<std::vector<EarlierChat>> chat;     // only on a first join
    AnnouncedLimits limits;
    bool operator==(const WelcomeMessage&) const = default;
};
struct ErrorMessage {
    ErrorCode code = ErrorCode::Malformed;
    std::string message;
    bool operator==(const ErrorMessage&) const = default;
};
struct SceneMessage {
    std::int64_t version = 0;
    std::string author; // "server" for the class's own changes
    std::optional<std::int64_t> authorId;
    EditKind kind = EditKind::Edit;
    std::string scene;
    bool operator==(const SceneMessage&) const = default;
};
struct RefusedMessage {
    RefusalReason reason = RefusalReason::Invalid;
    std::string message;
    std::int64_t version = 0;                   // the class's version when refused
    std::string command;                        // the chat command refused, if it was one
    std::optional<LockHolderEntry> holder;      // Locked, while held
    std::vector<RefusalDiagnostic> diagnostics; // Invalid, TooLarge, TooCostly
    bool operator==(const RefusedMessage&) const = default;
};
struct ChatLineMessage { // a chat line, to everyone
    std::string from;
    std::int64_t fromId = 0;
    std::string text;
    bool operator==(const ChatLineMessage&) const = default;
};
struct NoticeMessage {
    std::string text;
    bool operator==(const NoticeMessage&) const = default;
};
struct PresenceMessage {
    std::vector<MemberEntry> members;
    bool operator==(const PresenceMessage&) const = default;
};
struct LockMessage {
    std::optional<LockHolderEntry> holder; // none: the scene is free
    std::int64_t expiresInMs = 0;
    bool operator==(const LockMessage&) const = default;
};
struct FrozenMessage {
    bool frozen = false;
    bool operator==(const FrozenMessage&) const = default;
};
struct SavedMessage {
    std::int64_t version = 0;
    std::int64_t snapshot = 0;
    std::string label;
    bool operator==(const SavedMessage&) const = default;
};
struct VersionMessage { // the answer to History
    std::int64_t version = 0;
    std::string author;
    EditKind kind = EditKind::Edit;
    std::int64_t unixMs = 0;
    std::string scene;
    bool operator==(const VersionMessage&) const = default;
};

using ServerMessage = std::variant<WelcomeMessage, ErrorMessage, SceneMessage, RefusedMessage,
                                   ChatLineMessage, NoticeMessage, PresenceMessage, LockMessage,
                                   FrozenMessage, SavedMessage, VersionMessage>;

MessageType typeOf(const ServerMessage& message);

// The usual helper for std::visit over a message: one lambda per type.
template <class... F>
struct Overloaded : F... {
    using F::operator()...;
};
template <class... F>
Overloaded(F...) -> Overloaded<F...>;

// One compact JSON text frame.
std::string encodeServerMessage(const ServerMessage& message);

// A frame from the server. A type this client does not know (a newer
// server's) is ErrorCode::UnknownType, to be ignored; anything else wrong is
// Malformed with the path to the field.
using ParsedServerMessage = std::variant<ServerMessage, ProtocolError>;
ParsedServerMessage parseServerMessage(std::string_view frame);

} // namespace fl::classroom
