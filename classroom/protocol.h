#pragma once
// The classroom protocol's vocabulary (docs/classroom-protocol.md): JSON text
// frames, each an object with a "type". Kinds are enums here; their wire
// names live only in protocol.cpp. parseClientMessage checks everything a
// client sends — shape, types, lengths — before any of it reaches the class.
#include "classroom_limits.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

namespace fl::classroom {

enum class MessageType {
    // client -> server
    Join,
    Edit,
    Release,
    Chat,
    Heartbeat,
    History,   // ask for the scene at a version (replay, export)
    TakeLock,  // instructor
    BreakLock, // instructor
    Freeze,    // instructor
    Push,      // instructor: a scene for everyone, under no lock
    Snapshot,  // instructor (students save with /save)
    Anonymise, // instructor
    // server -> client
    Welcome,
    Error,
    Scene,
    Refused,
    Presence,
    Lock,
    Frozen,
    Notice,  // text for one member (/help, confirmations)
    Saved,   // a snapshot was stored
    Version, // answer to History
};

enum class Role { Student, Instructor, Observer };

// How a version of the class's scene came to be (the log keeps it; scene and
// version messages say it).
enum class EditKind { Start, Edit, Command, Push, Undo };

// Why an edit (or a chat command) was not applied.
enum class RefusalReason { Locked, Stale, Invalid, ReadOnly, Rate, TooLarge, TooCostly };

// Why a message could not be handled at all.
enum class ErrorCode {
    Malformed,     // not a JSON object, or a field of the wrong type
    UnknownType,   // "type" names no message
    WrongClass,    // the class code does not match
    BadKey,        // instructor key missing or wrong
    BadName,       // empty, too long or control characters
    NotJoined,     // anything but join before a welcome
    AlreadyJoined, // a second join on one connection
    Forbidden,     // the role may not do this
    TooManyJoins,  // failed-join throttle
    ClassFull,
    TooLarge, // a message over the size limit
    NotFound, // History of a version the log does not have
    Server,   // the server could not store the edit
};

std::string_view nameOf(MessageType type);
std::string_view nameOf(Role role);
std::string_view nameOf(RefusalReason reason);
std::string_view nameOf(ErrorCode code);
std::string_view nameOf(EditKind kind);
std::optional<MessageType> messageTypeNamed(std::string_view name);
std::optional<Role> roleNamed(std::string_view name);
std::optional<RefusalReason> refusalReasonNamed(std::string_view name);
std::optional<ErrorCode> errorCodeNamed(std::string_view name);
std::optional<EditKind> editKindNamed(std::string_view name);

struct JoinMessage {
    std::string classCode;
    std::string name;
    Role role = Role::Student;
    std::string key;                   // instructor key
    std::string resume;                // the token of an earlier welcome: take that seat back
    std::optional<std::int64_t> since; // the last version this client has
    bool operator==(const JoinMessage&) const = default;
};
struct EditMessage {
    std::int64_t version = 0; // the version the new text is based on (fencing token)
    std::string scene;
    bool operator==(const EditMessage&) const = default;
};
struct ChatMessage {
    std::string text;
    bool operator==(const ChatMessage&) const = default;
};
struct FreezeMessage {
    bool frozen = true;
    bool operator==(const FreezeMessage&) const = default;
};
struct PushMessage {
    std::string scene;
    bool operator==(const PushMessage&) const = default;
};
struct SnapshotMessage {
    std::string label;
    bool operator==(const SnapshotMessage&) const = default;
};
struct AnonymiseMessage {
    bool anonymous = true;
    bool operator==(const AnonymiseMessage&) const = default;
};
struct HistoryMessage {
    std::int64_t version = 0;
    bool operator==(const HistoryMessage&) const = default;
};

using ClientBody =
    std::variant<std::monostate, JoinMessage, EditMessage, ChatMessage, FreezeMessage, PushMessage,
                 SnapshotMessage, AnonymiseMessage, HistoryMessage>;

struct ClientMessage {
    MessageType type = MessageType::Heartbeat;
    ClientBody body; // monostate for release, heartbeat, take-lock, break-lock
    bool operator==(const ClientMessage&) const = default;
};

struct ProtocolError {
    ErrorCode code = ErrorCode::Malformed;
    std::string message;
};

using ParsedClientMessage = std::variant<ClientMessage, ProtocolError>;

// One text frame from a client. Never throws; anything unexpected is a
// ProtocolError saying which field is wrong.
ParsedClientMessage parseClientMessage(std::string_view frame, const ClassroomLimits& limits = {});

// The frame a client sends for `message` (what parseClientMessage reads).
std::string encodeClientMessage(const ClientMessage& message);

// Whether `s` is valid UTF-8 without control characters other than tab and
// line breaks (names allow none at all).
bool isCleanText(std::string_view s, bool allowLineBreaks);

} // namespace fl::classroom
