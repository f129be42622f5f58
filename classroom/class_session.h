#pragma once
// One class: its scene and version, who is in it, the lock, the chat and its
// commands — the protocol's rules with no sockets attached. The server feeds
// it frames per connection and sends what it returns; tests feed it frames
// and a ManualClock. Everything received is checked before it changes
// anything; a version is in the log before anyone hears of it.
#include "chat_commands.h"
#include "class_clock.h"
#include "classroom_limits.h"
#include "edit_log.h"
#include "protocol.h"
#include "rate_limit.h"
#include "scene_lock.h"
#include "scene_policy.h"
#include "server_message.h"

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

// A scene the class waits to see checked (ClassSession::takeChecks): the
// server checks it off the event loop and hands the result back.
using CheckId = std::uint64_t;
struct ScheduledCheck {
    CheckId id = 0;
    std::string scene;
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

    // A new connection from `peerAddress`; nullopt when that address already
    // has ClassroomLimits::maxUnjoinedPerAddress connections that have not
    // joined (the transport closes it).
    std::optional<ConnectionId> connect(std::string peerAddress);
    std::vector<Delivery> receive(ConnectionId connection, std::string_view frame);
    // A frame the transport could not take (binary, over the size limit).
    std::vector<Delivery> rejectFrame(ConnectionId connection, ErrorCode code, std::string message);
    std::vector<Delivery> disconnected(ConnectionId connection);
    // Lets leases and grace periods run out and closes silent connections;
    // the server calls it about once a second.
    std::vector<Delivery> tick();

    // Checking a changed scene costs work (issue 26 §3). By default a change
    // is checked as it arrives; deferred, it waits in takeChecks() for the
    // server to check it on a worker (checkClassroomScene) and hand the result
    // to checked() — or to say checkTimedOut() when it took longer than
    // limits().maxCheckMillis. Meanwhile the class goes on; the cheap rules
    // (lock, version, freeze) are applied again when the result comes, and
    // changes are applied in the order they arrived.
    void setDeferredChecks(bool deferred) { deferChecks_ = deferred; }
    std::vector<ScheduledCheck> takeChecks();
    std::vector<Delivery> checked(CheckId id, const SceneCheck& result);
    std::vector<Delivery> checkTimedOut(CheckId id);
    std::size_t checksWaiting() const { return waiting_.size(); }

    std::int64_t version() const { return version_; }
    const std::string& scene() const { return scene_; }
    std::size_t memberCount() const { return members_.size(); }
    bool frozen() const { return frozen_; }
    // What the server should say at start (a version of the log it could not
    // use), or empty.
    const std::string& startNote() const { return startNote_; }
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
        TokenBucket joins; // resumes of this seat
    };
    // Makes room for a new member in a full class: the seat of the member
    // away longest goes (a seat kept for a reconnect is not a member).
    bool freeASeat();
    struct Connection {
        std::string peer;
        MemberId member = 0; // 0 before a welcome
        Millis lastSeen = 0;
        Millis connectedAt = 0;
    };
    using Out = std::vector<Delivery>;

    void handle(Connection& c, ConnectionId id, const ClientMessage& m, Out& out);
    void join(Connection& c, ConnectionId id, const JoinMessage& m, Out& out);
    void edit(Member& m, const EditMessage& e, Out& out);
    void chat(Member& m, const ChatMessage& c, Out& out);
    void command(Member& m, const std::string& text, Out& out);
    void instructor(Member& m, const ClientMessage& msg, Out& out);
    void history(Member& m, const HistoryMessage& h, Out& out);

    // What else a change does once it is committed.
    enum class AfterCommit : std::uint8_t { Nothing, RecordUndo, ForgetUndo, BreakLock };
    struct Change {
        std::string scene;
        EditKind kind = EditKind::Edit;
        std::optional<std::int64_t> basedOn; // checked as a fencing token when given
        bool underLock = true;               // false: an instructor's push
        std::string command;                 // the chat text, for refusals
        AfterCommit after = AfterCommit::Nothing;
        std::string sceneBefore; // for RecordUndo
    };
    // The one path every change takes: role, freeze, size, lock, version
    // (admissible), the scene's check (now or deferred), then log and
    // broadcast (finishApply).
    void apply(Member& author, Change change, Out& out);
    bool admissible(Member& author, const Change& change, Out& out, bool again);
    void finishApply(Member& author, Change change, const SceneCheck& check, Out& out);
    bool commit(const Member* author, std::string scene, EditKind kind, Out& out);
    void restoreGoodVersion();

    // What a refusal says beyond its reason: who holds the lock, where the
    // scene is wrong.
    struct RefusalDetail {
        std::optional<LockHolderEntry> holder;
        std::vector<RefusalDiagnostic> diagnostics;
    };
    void refuse(const Member& to, RefusalReason reason, std::string message, Out& out,
                const std::string& command = {}, RefusalDetail detail = {});
    void error(ConnectionId to, ErrorCode code, std::string message, Out& out, bool close = false);
    // The rate limit: one token of the member's bucket.
    bool allowed(Member& m, Millis now);
    void send(ConnectionId to, const ServerMessage& message, Out& out, bool close = false) const;
    void broadcast(const ServerMessage& message, Out& out, bool wholeScene = false) const;
    void announceLockIfChanged(Out& out);
    // Who is here, to everyone: at once when forced or after a quiet second,
    // else at the next tick — a join storm costs one list per second, not
    // one per join (each to everyone: quadratic).
    void announcePresence(Out& out, bool force = false);
    Member* memberOf(ConnectionId id);
    const std::string& shownName(const Member& m) const;
    LockMessage lockMessage();
    std::vector<MemberEntry> memberList() const;

    struct WaitingCheck {
        MemberId author = 0;
        Change change;
        std::optional<SceneCheck> result; // once checked (or timed out)
    };
    // Applies the checked changes at the head of the queue: changes are
    // applied in the order they came, whichever check ends first.
    void applyChecked(Out& out);
    std::string startNote_;
    bool deferChecks_ = false;
    std::map<CheckId, WaitingCheck> waiting_;
    std::vector<ScheduledCheck> toCheck_;
    CheckId nextCheck_ = 1;

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
    AddressBuckets joinsByAddress_;
    KeyThrottle instructorKey_;
    std::map<ConnectionId, Connection> connections_;
    std::map<MemberId, Member> members_;
    ConnectionId nextConnection_ = 1;
    MemberId nextMember_ = 1;
};

} // namespace fl::classroom
