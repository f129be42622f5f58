#include "class_session.h"

#include "member_name.h"
#include "scene_policy.h"

#include <QRandomGenerator>

#include <algorithm>
#include <chrono>
#include <stdexcept>

namespace fl::classroom {

namespace {

// Changes waiting for their check: the class over, and one student's.
constexpr std::size_t kMaxWaitingChecks = 64;
constexpr std::size_t kMaxWaitingChecksOfAStudent = 4;
// Chat a newly joined member is shown from before they came.
constexpr std::size_t kChatLinesOnWelcome = 50;

// Member ids count up from 1: far below 2^53, the largest a JSON number
// holds exactly.
std::int64_t wireId(MemberId id) {
    return static_cast<std::int64_t>(id);
}

QString frame(const ServerMessage& message) {
    return QString::fromStdString(encodeServerMessage(message));
}

std::int64_t unixMillis() {
    using namespace std::chrono;
    return duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count();
}

std::string randomToken() {
    static const char* hex = "0123456789abcdef";
    std::string out;
    for (int i = 0; i < 4; ++i) {
        quint32 word = QRandomGenerator::system()->generate();
        for (int k = 0; k < 8; ++k, word >>= 4)
            out += hex[word & 15];
    }
    return out;
}

std::vector<RefusalDiagnostic>
refusalDiagnostics(const std::vector<scene::SceneDiagnostic>& diagnostics) {
    std::vector<RefusalDiagnostic> out;
    for (const scene::SceneDiagnostic& d : diagnostics)
        out.push_back({d.pos.line, d.pos.column,
                       d.severity == scene::Severity::Error ? DiagnosticSeverity::Error
                                                            : DiagnosticSeverity::Warning,
                       d.message, d.suggestion});
    return out;
}

// Constant-time comparison: the key is not guessed a byte at a time.
bool sameKey(const std::string& a, const std::string& b) {
    if (a.size() != b.size()) return false;
    unsigned char diff = 0;
    for (std::size_t i = 0; i < a.size(); ++i)
        diff |= static_cast<unsigned char>(a[i] ^ b[i]);
    return diff == 0;
}

} // namespace

ClassSession::ClassSession(ClassConfig config, const Clock& clock, EditLog* log)
    : config_(std::move(config)), clock_(clock), log_(log),
      lock_(config_.limits.leaseMillis, config_.limits.disconnectGraceMillis,
            config_.limits.brokenLockCooldownMillis),
      failedJoins_(config_.limits.maxFailedJoins, config_.limits.failedJoinWindow),
      joinsByAddress_(config_.limits.joinBurstPerAddress, config_.limits.joinsPerSecondPerAddress),
      instructorKey_(config_.limits.keyFreeTries, config_.limits.maxKeyDelayMillis) {
    if (log_)
        if (auto latest = log_->latest()) {
            version_ = latest->version;
            if (checkClassroomScene(latest->scene, config_.limits).ok) {
                scene_ = std::move(latest->scene);
                return;
            }
            restoreGoodVersion();
            return;
        }
    const SceneCheck check = checkClassroomScene(config_.initialScene, config_.limits);
    if (!check.ok) {
        std::string why = "the class scene cannot be used";
        for (const auto& d : check.diagnostics)
            if (d.severity == scene::Severity::Error) {
                why += ": " + scene::formatSceneDiagnostic(d);
                break;
            }
        throw std::runtime_error(why);
    }
    Out ignored;
    if (!commit(nullptr, config_.initialScene, EditKind::Start, ignored))
        throw std::runtime_error("the class log cannot be written");
}

// The newest version is not a scene this server accepts (written by an
// older server, before a check existed, or damaged): the newest version
// that is goes on, as a new version, so no window ever loads the bad one.
void ClassSession::restoreGoodVersion() {
    const std::int64_t bad = version_;
    std::string good;
    std::string from;
    for (std::int64_t v = bad - 1; v >= 1 && v > bad - 1000 && good.empty(); --v) {
        std::optional<LoggedVersion> older;
        try {
            older = log_->at(v);
        } catch (const std::exception&) {
            continue; // a damaged row: look further back
        }
        if (older && checkClassroomScene(older->scene, config_.limits).ok) {
            good = std::move(older->scene);
            from = "version " + std::to_string(v);
        }
    }
    if (good.empty()) {
        if (!checkClassroomScene(config_.initialScene, config_.limits).ok)
            throw std::runtime_error("no version in the class log is a valid class scene, nor is "
                                     "the starting scene");
        good = config_.initialScene;
        from = "the starting scene";
    }
    Out ignored;
    if (!commit(nullptr, good, EditKind::Push, ignored))
        throw std::runtime_error("the class log cannot be written");
    startNote_ = "version " + std::to_string(bad) +
                 " in the log is not a valid class scene; the class goes on from " + from +
                 ", as version " + std::to_string(version_);
}

std::optional<ConnectionId> ClassSession::connect(std::string peerAddress) {
    const auto unjoined =
        std::count_if(connections_.begin(), connections_.end(), [&](const auto& c) {
            return c.second.member == 0 && c.second.peer == peerAddress;
        });
    if (std::size_t(unjoined) >= config_.limits.maxUnjoinedPerAddress) return std::nullopt;
    const ConnectionId id = nextConnection_++;
    const Millis now = clock_.now();
    connections_[id] = Connection{std::move(peerAddress), 0, now, now};
    return id;
}

bool ClassSession::freeASeat() {
    auto away = members_.end();
    for (auto it = members_.begin(); it != members_.end(); ++it)
        if (it->second.connection == 0 &&
            (away == members_.end() || it->second.leftAt < away->second.leftAt))
            away = it;
    if (away == members_.end()) return false;
    lock_.release(away->first);
    members_.erase(away);
    return true;
}

ClassSession::Member* ClassSession::memberOf(ConnectionId id) {
    const auto c = connections_.find(id);
    if (c == connections_.end() || c->second.member == 0) return nullptr;
    const auto m = members_.find(c->second.member);
    return m == members_.end() ? nullptr : &m->second;
}

const std::string& ClassSession::shownName(const Member& m) const {
    return anonymous_ ? m.alias : m.name;
}

bool ClassSession::allowed(Member& m, Millis now) {
    // The instructor holds the key and can push any scene anyway: trusted,
    // and free to drive a demonstration (or a benchmark) at any pace.
    return m.role == Role::Instructor || m.bucket.take(now);
}

void ClassSession::send(ConnectionId to, const ServerMessage& message, Out& out, bool close) const {
    if (to) out.push_back({to, frame(message), close});
}

void ClassSession::broadcast(const ServerMessage& message, Out& out, bool wholeScene) const {
    const QString f = frame(message);
    for (const auto& [id, c] : connections_)
        if (c.member != 0) out.push_back({id, f, false, wholeScene});
}

void ClassSession::error(ConnectionId to, ErrorCode code, std::string message, Out& out,
                         bool close) {
    send(to, ErrorMessage{code, std::move(message)}, out, close);
}

void ClassSession::refuse(const Member& to, RefusalReason reason, std::string message, Out& out,
                          const std::string& command, RefusalDetail detail) {
    send(to.connection,
         RefusedMessage{reason, std::move(message), version_, command, std::move(detail.holder),
                        std::move(detail.diagnostics)},
         out);
}

LockMessage ClassSession::lockMessage() {
    const auto holder = lock_.holder(clock_.now());
    if (!holder || !members_.count(holder->member)) return {};
    const Member& m = members_.at(holder->member);
    return {LockHolderEntry{wireId(m.id), shownName(m)}, holder->expires - clock_.now()};
}

void ClassSession::announceLockIfChanged(Out& out) {
    const auto holder = lock_.holder(clock_.now());
    const std::optional<MemberId> now =
        holder ? std::optional<MemberId>(holder->member) : std::nullopt;
    if (now == announcedHolder_) return;
    announcedHolder_ = now;
    broadcast(lockMessage(), out);
}

std::vector<MemberEntry> ClassSession::memberList() const {
    std::vector<MemberEntry> list;
    for (const auto& [id, m] : members_)
        list.push_back({wireId(id), shownName(m), m.role, m.connection != 0});
    return list;
}

void ClassSession::announcePresence(Out& out, bool force) {
    const Millis now = clock_.now();
    if (!force && lastPresence_ && now - *lastPresence_ < 1000) {
        presenceDue_ = true;
        return;
    }
    presenceDue_ = false;
    lastPresence_ = now;
    broadcast(PresenceMessage{memberList()}, out);
}

std::vector<Delivery> ClassSession::rejectFrame(ConnectionId connection, ErrorCode code,
                                                std::string message) {
    Out out;
    if (connections_.count(connection)) error(connection, code, std::move(message), out);
    return out;
}

std::vector<Delivery> ClassSession::receive(ConnectionId id, std::string_view text) {
    Out out;
    const auto it = connections_.find(id);
    if (it == connections_.end()) return out;
    Connection& c = it->second;
    c.lastSeen = clock_.now();
    ParsedClientMessage parsed = parseClientMessage(text, config_.limits);
    if (const auto* failure = std::get_if<ProtocolError>(&parsed)) {
        error(id, failure->code, failure->message, out);
        return out;
    }
    handle(c, id, std::get<ClientMessage>(parsed), out);
    announceLockIfChanged(out);
    return out;
}

void ClassSession::handle(Connection& c, ConnectionId id, const ClientMessage& m, Out& out) {
    if (m.type == MessageType::Join) return join(c, id, std::get<JoinMessage>(m.body), out);
    Member* member = memberOf(id);
    if (!member) return error(id, ErrorCode::NotJoined, "send join first", out);
    // Any message keeps the seat (Connection::lastSeen); only an edit keeps
    // the lock (a lease held by heartbeats alone would never end).
    switch (m.type) {
    case MessageType::Heartbeat:
        return;
    case MessageType::Release:
        lock_.release(member->id);
        return;
    case MessageType::Edit:
        return edit(*member, std::get<EditMessage>(m.body), out);
    case MessageType::Chat:
        return chat(*member, std::get<ChatMessage>(m.body), out);
    case MessageType::History:
        return history(*member, std::get<HistoryMessage>(m.body), out);
    default:
        return instructor(*member, m, out);
    }
}

void ClassSession::join(Connection& c, ConnectionId id, const JoinMessage& m, Out& out) {
    const Millis now = clock_.now();
    if (c.member != 0)
        return error(id, ErrorCode::AlreadyJoined, "this connection has joined", out);
    // The right code always gets in, however many others mistyped behind the
    // same address; wrong ones from an address that guessed too often close
    // the connection.
    if (!sameKey(m.classCode, config_.classCode)) {
        const bool blocked = failedJoins_.blocked(c.peer, now);
        failedJoins_.failed(c.peer, now);
        if (blocked)
            return error(id, ErrorCode::TooManyJoins,
                         "too many wrong class codes from this address; wait a minute", out, true);
        return error(id, ErrorCode::WrongClass, "no class with that code here", out);
    }
    if (m.role == Role::Instructor) {
        if (config_.instructorKey.empty())
            return error(id, ErrorCode::BadKey, "this class has no instructor key", out);
        if (const Millis wait = instructorKey_.waiting(now))
            return error(id, ErrorCode::TooManyJoins,
                         "wrong instructor keys were tried: instructor joins wait " +
                             std::to_string((wait + 999) / 1000) + " s more",
                         out, true);
        if (!sameKey(m.key, config_.instructorKey)) {
            instructorKey_.failed(now);
            return error(id, ErrorCode::BadKey,
                         "joining as instructor needs the class's instructor key", out);
        }
        instructorKey_.succeeded();
    } else if (!joinsByAddress_.take(c.peer, now)) {
        return error(id, ErrorCode::TooManyJoins, "too many joins from this address; wait a moment",
                     out, true);
    }
    if (const auto why = memberNameProblem(m.name, config_.limits.maxNameChars))
        return error(id, ErrorCode::BadName, *why, out);

    Member* member = nullptr;
    bool resumed = false;
    if (!m.resume.empty())
        for (auto& [mid, candidate] : members_)
            if (sameKey(candidate.token, m.resume) && candidate.role == m.role) {
                member = &candidate;
                break;
            }
    const std::string key = memberNameKey(m.name);
    for (const auto& [mid, other] : members_)
        if (&other != member && memberNameKey(other.name) == key)
            return error(id, ErrorCode::BadName,
                         "someone in the class is already called '" + m.name +
                             "'; choose another name",
                         out);
    if (member) {
        if (member->role != Role::Instructor && !member->joins.take(now))
            return error(id, ErrorCode::TooManyJoins, "this seat rejoined too often; wait a moment",
                         out, true);
        resumed = true;
        if (member->connection && member->connection != id) {
            // The same seat from a new connection: the old one is over.
            error(member->connection, ErrorCode::AlreadyJoined, "joined again from elsewhere", out,
                  true);
            connections_[member->connection].member = 0;
        }
        member->connection = id;
        member->name = m.name;
        lock_.reconnected(member->id, now);
    } else {
        // Seats kept for members who may come back do not fill the class:
        // the one away longest makes room. The instructor always gets in.
        if (m.role != Role::Instructor && members_.size() >= config_.limits.maxMembers &&
            !freeASeat())
            return error(id, ErrorCode::ClassFull, "the class is full", out, true);
        const MemberId mid = nextMember_++;
        Member fresh{mid,
                     m.name,
                     m.role == Role::Instructor ? "Instructor" : "Learner " + std::to_string(mid),
                     m.role,
                     randomToken(),
                     id,
                     0,
                     TokenBucket(config_.limits.rateBurst, config_.limits.ratePerSecond, now),
                     std::nullopt,
                     TokenBucket(config_.limits.joinBurstPerSeat,
                                 config_.limits.joinsPerSecondPerSeat, now)};
        member = &members_.emplace(mid, std::move(fresh)).first->second;
    }
    c.member = member->id;

    WelcomeMessage w;
    w.id = wireId(member->id);
    w.token = member->token;
    w.name = shownName(*member);
    w.role = member->role;
    w.version = version_;
    w.scene = scene_;
    w.frozen = frozen_;
    w.anonymous = anonymous_;
    w.resumed = resumed;
    w.members = memberList();
    w.lock = lockMessage().holder;
    // What the log adds is a courtesy: a log that cannot be read leaves it
    // out, and the member is welcomed all the same.
    if (m.since && log_ && *m.since < version_) {
        w.missed.emplace();
        try {
            for (const LoggedVersion& v : log_->after(*m.since, config_.limits.maxMissedListed))
                w.missed->push_back({v.version, anonymous_ ? std::string() : v.author, v.kind});
        } catch (const std::exception&) {
        }
    }
    if (!resumed && log_) {
        w.chat.emplace();
        try {
            for (const ChatLine& line : log_->recentChat(kChatLinesOnWelcome))
                w.chat->push_back(
                    {anonymous_ ? std::string() : line.author, line.text, line.unixMillis});
        } catch (const std::exception&) {
        }
    }
    const ClassroomLimits& l = config_.limits;
    auto whole = [](std::size_t n) { return static_cast<std::int64_t>(n); };
    w.limits = {whole(l.maxMessageBytes), whole(l.maxSceneBytes), whole(l.maxNodes),
                whole(l.maxFormulaBytes), whole(l.maxChatChars),  l.leaseMillis};
    send(id, w, out);
    announcePresence(out);
}

void ClassSession::edit(Member& m, const EditMessage& e, Out& out) {
    apply(m, Change{e.scene, EditKind::Edit, e.version, true, {}, AfterCommit::Nothing, {}}, out);
}

bool ClassSession::admissible(Member& author, const Change& change, Out& out, bool again) {
    const Millis now = clock_.now();
    auto refused = [&](RefusalReason reason, std::string message, RefusalDetail detail = {}) {
        refuse(author, reason, std::move(message), out, change.command, std::move(detail));
        return false;
    };
    if (author.role == Role::Observer)
        return refused(RefusalReason::ReadOnly, "observers cannot change the scene");
    if (frozen_ && author.role != Role::Instructor)
        return refused(RefusalReason::ReadOnly, "the instructor has frozen the class");
    if (!again && !allowed(author, now))
        return refused(RefusalReason::Rate, "too many edits; wait a moment");
    if (change.scene.size() > config_.limits.maxSceneBytes)
        return refused(RefusalReason::TooLarge, "the scene has " +
                                                    std::to_string(change.scene.size()) +
                                                    " bytes; a class scene may have at most " +
                                                    std::to_string(config_.limits.maxSceneBytes));
    if (change.underLock && lock_.heldByOther(author.id, now)) {
        const Member& holder = members_.at(lock_.holder(now)->member);
        return refused(RefusalReason::Locked, shownName(holder) + " is editing the scene",
                       {LockHolderEntry{wireId(holder.id), shownName(holder)}, {}});
    }
    if (change.underLock && lock_.coolingDown(author.id, now))
        return refused(RefusalReason::Locked,
                       "the instructor broke your lock; you can edit again in a moment");
    if (change.basedOn && *change.basedOn != version_)
        return refused(RefusalReason::Stale,
                       "the edit is based on version " + std::to_string(*change.basedOn) +
                           " but the scene is at version " + std::to_string(version_));
    return true;
}

void ClassSession::apply(Member& author, Change change, Out& out) {
    if (!admissible(author, change, out, false)) return;
    if (!deferChecks_) {
        const SceneCheck check = checkClassroomScene(change.scene, config_.limits);
        return finishApply(author, std::move(change), check, out);
    }
    // Checked off the event loop: a few changes of each student at a time,
    // and a bounded queue for the class.
    const auto mine = std::count_if(waiting_.begin(), waiting_.end(),
                                    [&](const auto& w) { return w.second.author == author.id; });
    if (author.role != Role::Instructor && std::size_t(mine) >= kMaxWaitingChecksOfAStudent)
        return refuse(author, RefusalReason::Rate,
                      "your last changes are still being checked; wait for them", out,
                      change.command);
    if (waiting_.size() >= kMaxWaitingChecks)
        return refuse(author, RefusalReason::Rate,
                      "the server is busy checking other changes; try again in a moment", out,
                      change.command);
    const CheckId id = nextCheck_++;
    toCheck_.push_back({id, change.scene});
    waiting_.emplace(id, WaitingCheck{author.id, std::move(change), std::nullopt});
}

void ClassSession::finishApply(Member& author, Change change, const SceneCheck& check, Out& out) {
    if (!check.ok) {
        std::string first = "the scene has errors";
        for (const auto& d : check.diagnostics)
            if (d.severity == scene::Severity::Error) {
                first = scene::formatSceneDiagnostic(d);
                break;
            }
        const RefusalReason reason = check.tooLarge    ? RefusalReason::TooLarge
                                     : check.tooCostly ? RefusalReason::TooCostly
                                                       : RefusalReason::Invalid;
        return refuse(author, reason, first, out, change.command,
                      {std::nullopt, refusalDiagnostics(check.diagnostics)});
    }
    // A deferred check: the class may have moved on while it ran.
    if (deferChecks_ && !admissible(author, change, out, true)) return;
    if (change.underLock) lock_.grant(author.id, clock_.now());
    const std::string before = scene_;
    if (!commit(&author, std::move(change.scene), change.kind, out)) return;
    switch (change.after) {
    case AfterCommit::Nothing:
        break;
    case AfterCommit::RecordUndo:
        author.undo = UndoRecord{version_, std::move(change.sceneBefore)};
        break;
    case AfterCommit::ForgetUndo:
        author.undo.reset();
        break;
    case AfterCommit::BreakLock:
        lock_.breakLock(clock_.now(), false); // everyone's basis changed; no old lease stays
        break;
    }
}

std::vector<ScheduledCheck> ClassSession::takeChecks() {
    std::vector<ScheduledCheck> out;
    out.swap(toCheck_);
    return out;
}

std::vector<Delivery> ClassSession::checked(CheckId id, const SceneCheck& result) {
    Out out;
    const auto it = waiting_.find(id);
    if (it == waiting_.end() || it->second.result) return out; // already timed out
    it->second.result = result;
    applyChecked(out);
    announceLockIfChanged(out);
    return out;
}

void ClassSession::applyChecked(Out& out) {
    while (!waiting_.empty() && waiting_.begin()->second.result) {
        WaitingCheck w = std::move(waiting_.begin()->second);
        waiting_.erase(waiting_.begin());
        const auto m = members_.find(w.author);
        if (m != members_.end()) finishApply(m->second, std::move(w.change), *w.result, out);
    }
}

std::vector<Delivery> ClassSession::checkTimedOut(CheckId id) {
    SceneCheck late;
    late.tooCostly = true;
    late.diagnostics.push_back({scene::Severity::Error,
                                kSceneFileName,
                                {},
                                "checking the scene took longer than " +
                                    std::to_string(config_.limits.maxCheckMillis) +
                                    " ms; a class scene must be quicker to check",
                                "use fewer or simpler formulas, or fewer PROTO instances",
                                true});
    return checked(id, late);
}

bool ClassSession::commit(const Member* author, std::string scene, EditKind kind, Out& out) {
    const std::int64_t next = version_ + 1;
    if (log_) {
        try {
            log_->append({next, author ? author->name : "server", kind, scene, unixMillis()});
            if (config_.limits.autoSnapshotEvery > 0 &&
                next % config_.limits.autoSnapshotEvery == 0)
                log_->snapshot(next, "automatic", "server");
        } catch (const std::exception& e) {
            if (author && author->connection)
                error(author->connection, ErrorCode::Server,
                      std::string("the edit could not be stored: ") + e.what(), out);
            return false;
        }
    }
    version_ = next;
    scene_ = std::move(scene);
    broadcast(SceneMessage{version_, author ? shownName(*author) : "server",
                           author ? std::optional<std::int64_t>(wireId(author->id)) : std::nullopt,
                           kind, scene_},
              out, true);
    return true;
}

void ClassSession::chat(Member& m, const ChatMessage& c, Out& out) {
    if (isChatCommand(c.text)) return command(m, c.text, out);
    if (!allowed(m, clock_.now()))
        return refuse(m, RefusalReason::Rate, "too many messages; wait a moment", out);
    if (log_) {
        try { // kept with the edits: a restarted class still has its chat
            log_->appendChat({m.name, c.text, unixMillis()});
        } catch (const std::exception& e) {
            return error(m.connection, ErrorCode::Server,
                         std::string("the message could not be stored: ") + e.what(), out);
        }
    }
    broadcast(ChatLineMessage{shownName(m), wireId(m.id), c.text}, out);
}

void ClassSession::command(Member& m, const std::string& text, Out& out) {
    const ChatCommandParse parsed = parseChatCommand(text);
    auto notice = [&](const std::string& t) { send(m.connection, NoticeMessage{t}, out); };
    if (!parsed.command) return refuse(m, RefusalReason::Invalid, parsed.error, out, text);
    const ChatCommand& c = *parsed.command;
    switch (c.kind) {
    case ChatCommandKind::Help:
        if (!allowed(m, clock_.now()))
            return refuse(m, RefusalReason::Rate, "too many commands; wait a moment", out, text);
        return notice(chatCommandHelp());
    case ChatCommandKind::Save: {
        if (!allowed(m, clock_.now()))
            return refuse(m, RefusalReason::Rate, "too many commands; wait a moment", out, text);
        if (m.role == Role::Observer)
            return refuse(m, RefusalReason::ReadOnly, "observers cannot save snapshots", out, text);
        if (frozen_ && m.role != Role::Instructor)
            return refuse(m, RefusalReason::ReadOnly, "the instructor has frozen the class", out,
                          text);
        if (characterCount(c.label) > config_.limits.maxLabelChars)
            return refuse(m, RefusalReason::TooLarge,
                          "a snapshot label has at most " +
                              std::to_string(config_.limits.maxLabelChars) + " characters",
                          out, text);
        std::int64_t snapshot = 0;
        if (log_) {
            try {
                snapshot = log_->snapshot(version_, c.label.empty() ? "saved" : c.label, m.name);
            } catch (const std::exception& e) {
                return error(m.connection, ErrorCode::Server, e.what(), out);
            }
        }
        return send(m.connection,
                    SavedMessage{version_, snapshot, c.label.empty() ? "saved" : c.label}, out);
    }
    case ChatCommandKind::Undo: {
        if (!m.undo)
            return refuse(m, RefusalReason::Invalid, "you have no command to undo", out, text);
        if (m.undo->versionAfter != version_)
            return refuse(m, RefusalReason::Stale,
                          "the scene changed after your command (it was version " +
                              std::to_string(m.undo->versionAfter) + ", now " +
                              std::to_string(version_) + "); change it back by hand",
                          out, text);
        return apply(m,
                     Change{m.undo->sceneBefore,
                            EditKind::Undo,
                            version_,
                            true,
                            text,
                            AfterCommit::ForgetUndo,
                            {}},
                     out);
    }
    case ChatCommandKind::Add:
    case ChatCommandKind::Paint: {
        if (c.formula.size() > config_.limits.maxFormulaBytes)
            return refuse(m, RefusalReason::TooLarge, "the formula is too long", out, text);
        // A typo in the formula is said in what was typed (issue 29 §5).
        if (auto mistake = formulaMistakeInCommand(c, text))
            return refuse(m, RefusalReason::Invalid, mistake->said(), out, text,
                          {std::nullopt,
                           {{1, std::int64_t(mistake->column), DiagnosticSeverity::Error,
                             mistake->message, mistake->suggestion}}});
        std::string why;
        std::string next = applyChatCommand(c, scene_, why);
        if (next.empty()) return refuse(m, RefusalReason::Invalid, why, out, text);
        return apply(m,
                     Change{std::move(next), EditKind::Command, version_, true, text,
                            AfterCommit::RecordUndo, scene_},
                     out);
    }
    }
}

void ClassSession::history(Member& m, const HistoryMessage& h, Out& out) {
    if (!allowed(m, clock_.now()))
        return refuse(m, RefusalReason::Rate, "too many requests; wait a moment", out);
    std::optional<LoggedVersion> v;
    if (log_) {
        try {
            v = log_->at(h.version);
        } catch (const std::exception& e) {
            // A damaged page: this request is refused, the class goes on.
            return error(m.connection, ErrorCode::Server,
                         "version " + std::to_string(h.version) +
                             " cannot be read from the class's log: " + e.what(),
                         out);
        }
    }
    if (!v && h.version == version_) v = LoggedVersion{version_, "", EditKind::Edit, scene_, 0};
    if (!v)
        return error(m.connection, ErrorCode::NotFound,
                     "version " + std::to_string(h.version) + " is not in the class's log", out);
    send(m.connection,
         VersionMessage{v->version, anonymous_ ? std::string() : v->author, v->kind, v->unixMillis,
                        v->scene},
         out);
}

void ClassSession::instructor(Member& m, const ClientMessage& msg, Out& out) {
    if (m.role != Role::Instructor)
        return error(m.connection, ErrorCode::Forbidden,
                     "'" + std::string(nameOf(msg.type)) + "' is for the instructor", out);
    const Millis now = clock_.now();
    switch (msg.type) {
    case MessageType::TakeLock:
        lock_.grant(m.id, now);
        return;
    case MessageType::BreakLock:
        lock_.breakLock(now, true);
        return;
    case MessageType::Freeze: {
        frozen_ = std::get<FreezeMessage>(msg.body).frozen;
        return broadcast(FrozenMessage{frozen_}, out);
    }
    case MessageType::Anonymise:
        anonymous_ = std::get<AnonymiseMessage>(msg.body).anonymous;
        // Names changed: say again who is here and who holds the lock.
        announcePresence(out, true);
        broadcast(lockMessage(), out);
        return;
    case MessageType::Push:
        return apply(m,
                     Change{std::get<PushMessage>(msg.body).scene,
                            EditKind::Push,
                            std::nullopt,
                            false,
                            {},
                            AfterCommit::BreakLock,
                            {}},
                     out);
    case MessageType::Snapshot: {
        const std::string label = std::get<SnapshotMessage>(msg.body).label;
        ChatMessage save{"/save " + label};
        return command(m, save.text, out);
    }
    default:
        return error(m.connection, ErrorCode::UnknownType, "not a client message", out);
    }
}

std::vector<Delivery> ClassSession::disconnected(ConnectionId id) {
    Out out;
    const auto it = connections_.find(id);
    if (it == connections_.end()) return out;
    const MemberId mid = it->second.member;
    connections_.erase(it);
    if (mid && members_.count(mid) && members_.at(mid).connection == id) {
        Member& m = members_.at(mid);
        m.connection = 0;
        m.leftAt = clock_.now();
        lock_.disconnected(mid, clock_.now());
        announcePresence(out);
    }
    announceLockIfChanged(out);
    return out;
}

std::vector<Delivery> ClassSession::tick() {
    Out out;
    const Millis now = clock_.now();
    for (auto& [id, c] : connections_)
        if (c.member == 0 && now - c.connectedAt > config_.limits.joinDeadlineMillis)
            // Heartbeats do not keep a connection that never joins.
            error(id, ErrorCode::NotJoined, "no join in time", out, true);
        else if (now - c.lastSeen > config_.limits.silentMemberMillis)
            error(id, ErrorCode::Malformed, "no message for too long (send heartbeats)", out, true);
    bool left = false;
    for (auto it = members_.begin(); it != members_.end();) {
        const Member& m = it->second;
        if (m.connection == 0 && now - m.leftAt >= config_.limits.disconnectGraceMillis) {
            it = members_.erase(it);
            left = true;
        } else {
            ++it;
        }
    }
    if (left || presenceDue_) announcePresence(out, true);
    announceLockIfChanged(out);
    return out;
}

} // namespace fl::classroom
