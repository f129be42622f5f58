#pragma once
// One class: its scene and version, who is in it, the lock, the chat and its
// commands — the protocol's rules with no sockets attached. The server feeds
// it frames per connection and sends what it returns; tests feed it frames
// and a ManualClock. Everything received is checked before it changes
// anything; a version is in the log before anyone hears of it.
#include "chat_commands.h"
#include "classroom_limits.h"
#include "clock.h"
#include "edit_log.h"
#include "protocol.h"
#include "rate_limit.h"
#include "scene_lock.h"

#include <QString>

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace fl::classroom {

using ConnectionId = std::uint64_t;

// One frame for one connection; `close`: close it after sending.
// `wholeScene`: a scene frame, which the next one makes worthless (a
// connection that reads slowly may skip to the newest).
struct Delivery {
    ConnectionId to = 0;
    QString frame;
    bool close = false;
    bool wholeScene = false;
};

struct ClassConfig {
    std::string classCode;
    std::string instructorKey; // empty: nobody can join as instructor
    std::string initialScene;  // used when the log is empty; must pass checkClassroomScene
    ClassroomLimits limits;
};

class ClassSession {
  public:
    // `log` may be null (a class kept in memory only). Restores the newest
    // version from the log when it has one. Throws when the initial scene is
    // invalid or the log cannot be written.
    ClassSession(ClassConfig config, const Clock& clock, EditLog* log);

    ConnectionId connect(std::string peerAddress);
    std::vector<Delivery> receive(ConnectionId connection, std::string_view frame);
    // A frame the transport could not take (binary, over the size limit).
    std::vector<Delivery> rejectFrame(ConnectionId connection, ErrorCode code, std::string message);
    std::vector<Delivery> disconnected(ConnectionId connection);
    // Lets leases and grace periods run out and closes silent connections;
    // the server calls it about once a second.
    std::vector<Delivery> tick();

    std::int64_t version() const { return version_; }
    const std::string& scene() const { return scene_; }
    std::size_t memberCount() const { return members_.size(); }
    bool frozen() const { return frozen_; }
    const ClassroomLimits& limits() const { return config_.limits; }

  private:
    struct UndoRecord {
        std::int64_t versionAfter = 0;
        std::string sceneBefore;
    };
    struct Member {
        MemberId id = 0;
        std::string name;
        std::string alias; // shown when names are anonymised
        Role role = Role::Student;
        std::string token;           // secret: resumes this seat after a reconnect
        ConnectionId connection = 0; // 0 while disconnected
        Millis leftAt = 0;
        TokenBucket bucket;
        std::optional<UndoRecord> undo;
    };
    struct Connection {
        std::string peer;
        MemberId member = 0; // 0 before a welcome
        Millis lastSeen = 0;
    };
    using Out = std::vector<Delivery>;

    void handle(Connection& c, ConnectionId id, const ClientMessage& m, Out& out);
    void join(Connection& c, ConnectionId id, const JoinMessage& m, Out& out);
    void edit(Member& m, const EditMessage& e, Out& out);
    void chat(Member& m, const ChatMessage& c, Out& out);
    void command(Member& m, const std::string& text, Out& out);
    void instructor(Member& m, const ClientMessage& msg, Out& out);
    void history(Member& m, const HistoryMessage& h, Out& out);

    struct Change {
        std::string scene;
        EditKind kind = EditKind::Edit;
        std::optional<std::int64_t> basedOn; // checked as a fencing token when given
        bool underLock = true;               // false: an instructor's push
        std::string command;                 // the chat text, for refusals
    };
    // The one path every change takes: role, freeze, size, lock, version,
    // checks, log, broadcast. Returns whether it was applied.
    bool apply(Member& author, Change change, Out& out);
    bool commit(const Member* author, std::string scene, EditKind kind, Out& out);

    void refuse(const Member& to, RefusalReason reason, std::string message, Out& out,
                const std::string& command = {}, QString extraJson = {});
    void error(ConnectionId to, ErrorCode code, std::string message, Out& out, bool close = false);
    // The rate limit: one token of the member's bucket.
    bool allowed(Member& m, Millis now);
    void broadcast(const QString& frame, Out& out, bool wholeScene = false) const;
    void announceLockIfChanged(Out& out);
    // Who is here, to everyone: at once when forced or after a quiet second,
    // else at the next tick — a join storm costs one list per second, not
    // one per join (each to everyone: quadratic).
    void announcePresence(Out& out, bool force = false);
    Member* memberOf(ConnectionId id);
    const std::string& shownName(const Member& m) const;
    QString lockJson();
    QString membersJson() const;

    ClassConfig config_;
    const Clock& clock_;
    EditLog* log_;
    std::int64_t version_ = 0;
    std::string scene_;
    bool frozen_ = false;
    bool anonymous_ = false;
    SceneLock lock_;
    std::optional<MemberId> announcedHolder_;
    std::optional<Millis> lastPresence_;
    bool presenceDue_ = false;
    FailedJoinThrottle failedJoins_;
    std::map<ConnectionId, Connection> connections_;
    std::map<MemberId, Member> members_;
    ConnectionId nextConnection_ = 1;
    MemberId nextMember_ = 1;
};

} // namespace fl::classroom
