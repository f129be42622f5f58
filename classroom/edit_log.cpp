#include "edit_log.h"

#include "platform/sqlite_database.h"

#include <array>
#include <chrono>
#include <fstream>
#include <system_error>
#include <utility>

#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>

namespace fl::classroom {

namespace {

EditKind kindNamed(std::string_view name) {
    return editKindNamed(name).value_or(EditKind::Edit);
}

LoggedVersion readRow(platform::SqliteStatement& s, bool withScene) {
    LoggedVersion v;
    v.version = s.integer(0);
    v.author = s.text(1);
    v.kind = kindNamed(s.text(2));
    v.unixMillis = s.integer(3);
    if (withScene) v.scene = s.text(4);
    return v;
}

} // namespace

struct EditLog::FolderLock {
    int fd = -1;
    FolderLock() = default;
    FolderLock(const FolderLock&) = delete;
    FolderLock& operator=(const FolderLock&) = delete;
    ~FolderLock() {
        if (fd >= 0) ::close(fd); // and with it the flock
    }
};

EditLog::EditLog(const std::filesystem::path& dataDir, bool startNew) : dir_(dataDir) {
    namespace fs = std::filesystem;
    std::error_code ec;
    fs::create_directories(dataDir, ec);
    const std::string shown = dataDir.string();
    // One server per folder: a second one's edits would fail against the
    // first's (and both would answer to the same class).
    lock_ = std::make_unique<FolderLock>();
    lock_->fd = ::open((dataDir / kLockFile).c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
    if (lock_->fd < 0)
        throw EditLogRefused("cannot open " + (dataDir / kLockFile).string() +
                             ": is the folder writable?");
    if (::flock(lock_->fd, LOCK_EX | LOCK_NB) != 0)
        throw EditLogRefused("another server is using the class in " + shown +
                             "; stop it first (one server per --data folder)");
    const fs::path logPath = dataDir / kLogFile;
    marked_ = fs::exists(dataDir / kMarkerFile, ec);
    const bool logThere = fs::exists(logPath, ec) && fs::file_size(logPath, ec) > 0;
    if (marked_ && !logThere && !startNew)
        throw EditLogRefused(
            "the class in " + shown + " had a log (" + kMarkerFile + " is there) but " + kLogFile +
            " is missing or empty: restore it from a backup, or start a new class there with "
            "--new (the old versions are then gone)");
    try {
        db_ = std::make_unique<platform::SqliteDatabase>(logPath.string());
        auto check = db_->prepare("PRAGMA quick_check");
        std::string verdict;
        while (check.step())
            verdict += (verdict.empty() ? "" : "; ") + check.text(0);
        if (verdict != "ok") throw platform::SqliteError(verdict.substr(0, 300));
    } catch (const platform::SqliteError& e) {
        db_.reset();
        throw EditLogRefused(
            "the class log " + logPath.string() + " is damaged (" + e.what() +
            "). Keep a copy of the folder, then recover what can be read: sqlite3 " +
            logPath.string() + " .recover | sqlite3 NEWDIR/" + kLogFile +
            " and start with --data NEWDIR; or start a new class in an empty folder");
    }
    // The wrapper opens in WAL mode: a committed version survives the process
    // being killed (it is in the WAL file before COMMIT returns).
    db_->execute("CREATE TABLE IF NOT EXISTS versions ("
                 " version INTEGER PRIMARY KEY, author TEXT NOT NULL, kind TEXT NOT NULL,"
                 " unix_ms INTEGER NOT NULL, scene TEXT NOT NULL);"
                 "CREATE TABLE IF NOT EXISTS snapshots ("
                 " id INTEGER PRIMARY KEY AUTOINCREMENT, version INTEGER NOT NULL,"
                 " label TEXT NOT NULL, author TEXT NOT NULL, unix_ms INTEGER NOT NULL);"
                 "CREATE TABLE IF NOT EXISTS chat ("
                 " id INTEGER PRIMARY KEY AUTOINCREMENT, author TEXT NOT NULL,"
                 " text TEXT NOT NULL, unix_ms INTEGER NOT NULL);");
    if (marked_ && !latest() && !startNew)
        throw EditLogRefused("the class log " + logPath.string() +
                             " holds no version, but the class in " + shown +
                             " had some: restore the log from a backup, or start a new class "
                             "there with --new");
}

EditLog::~EditLog() {
    db_.reset(); // closed before the folder is let go
}

std::optional<LoggedVersion> EditLog::latest() {
    auto s = db_->prepare("SELECT version, author, kind, unix_ms, scene FROM versions "
                          "ORDER BY version DESC LIMIT 1");
    if (!s.step()) return std::nullopt;
    return readRow(s, true);
}

std::optional<LoggedVersion> EditLog::at(std::int64_t version) {
    auto s = db_->prepare(
        "SELECT version, author, kind, unix_ms, scene FROM versions WHERE version = ?1");
    s.bind(1, version);
    if (!s.step()) return std::nullopt;
    return readRow(s, true);
}

std::vector<LoggedVersion> EditLog::after(std::int64_t version, std::size_t limit) {
    auto s = db_->prepare("SELECT version, author, kind, unix_ms FROM versions "
                          "WHERE version > ?1 ORDER BY version LIMIT ?2");
    s.bind(1, version).bind(2, static_cast<std::int64_t>(limit));
    std::vector<LoggedVersion> out;
    while (s.step())
        out.push_back(readRow(s, false));
    return out;
}

void EditLog::append(const LoggedVersion& entry) {
    platform::SqliteDatabase::Transaction t(*db_);
    auto s = db_->prepare(
        "INSERT INTO versions (version, author, kind, unix_ms, scene) VALUES (?1, ?2, ?3, ?4, ?5)");
    s.bind(1, entry.version)
        .bind(2, entry.author)
        .bind(3, nameOf(entry.kind))
        .bind(4, entry.unixMillis)
        .bind(5, entry.scene);
    s.run();
    t.commit();
    if (!marked_) {
        // From now on the folder holds a class: an empty log is damage.
        std::ofstream marker(dir_ / kMarkerFile);
        marker << "a FunctionLab class; its log is " << kLogFile << "\n";
        marked_ = bool(marker);
    }
}

std::int64_t EditLog::snapshot(std::int64_t version, const std::string& label,
                               const std::string& author) {
    using namespace std::chrono;
    auto s = db_->prepare(
        "INSERT INTO snapshots (version, label, author, unix_ms) VALUES (?1, ?2, ?3, ?4)");
    s.bind(1, version)
        .bind(2, label)
        .bind(3, author)
        .bind(4, static_cast<std::int64_t>(
                     duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count()));
    s.run();
    return db_->lastInsertId();
}

void EditLog::appendChat(const ChatLine& line) {
    auto s = db_->prepare("INSERT INTO chat (author, text, unix_ms) VALUES (?1, ?2, ?3)");
    s.bind(1, line.author).bind(2, line.text).bind(3, line.unixMillis);
    s.run();
}

std::vector<ChatLine> EditLog::recentChat(std::size_t limit) {
    auto s = db_->prepare("SELECT author, text, unix_ms FROM (SELECT * FROM chat ORDER BY id DESC "
                          "LIMIT ?1) ORDER BY id");
    s.bind(1, static_cast<std::int64_t>(limit));
    std::vector<ChatLine> out;
    while (s.step())
        out.push_back({s.text(0), s.text(1), s.integer(2)});
    return out;
}

std::vector<SnapshotInfo> EditLog::snapshots() {
    auto s = db_->prepare("SELECT id, version, label, author FROM snapshots ORDER BY id");
    std::vector<SnapshotInfo> out;
    while (s.step())
        out.push_back({s.integer(0), s.integer(1), s.text(2), s.text(3)});
    return out;
}

} // namespace fl::classroom
