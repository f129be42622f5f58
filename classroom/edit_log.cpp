#include "edit_log.h"

#include "sqlite_database.h"

#include <array>
#include <chrono>
#include <system_error>
#include <utility>

namespace fl::classroom {

namespace {

constexpr std::array kKindNames{
    std::pair{EditKind::Start, "start"}, std::pair{EditKind::Edit, "edit"},
    std::pair{EditKind::Command, "command"}, std::pair{EditKind::Push, "push"},
    std::pair{EditKind::Undo, "undo"}};

EditKind kindNamed(std::string_view name) {
    for (const auto& [k, n] : kKindNames)
        if (name == n) return k;
    return EditKind::Edit;
}

LoggedVersion readRow(grading::SqliteStatement& s, bool withScene) {
    LoggedVersion v;
    v.version = s.integer(0);
    v.author = s.text(1);
    v.kind = kindNamed(s.text(2));
    v.unixMillis = s.integer(3);
    if (withScene) v.scene = s.text(4);
    return v;
}

} // namespace

std::string_view nameOf(EditKind kind) {
    for (const auto& [k, n] : kKindNames)
        if (k == kind) return n;
    return "edit";
}

EditLog::EditLog(const std::filesystem::path& dataDir) {
    std::error_code ec;
    std::filesystem::create_directories(dataDir, ec);
    db_ = std::make_unique<grading::SqliteDatabase>((dataDir / "classroom.sqlite").string());
    // The wrapper opens in WAL mode: a committed version survives the process
    // being killed (it is in the WAL file before COMMIT returns).
    db_->execute("CREATE TABLE IF NOT EXISTS versions ("
                 " version INTEGER PRIMARY KEY, author TEXT NOT NULL, kind TEXT NOT NULL,"
                 " unix_ms INTEGER NOT NULL, scene TEXT NOT NULL);"
                 "CREATE TABLE IF NOT EXISTS snapshots ("
                 " id INTEGER PRIMARY KEY AUTOINCREMENT, version INTEGER NOT NULL,"
                 " label TEXT NOT NULL, author TEXT NOT NULL, unix_ms INTEGER NOT NULL);");
}

EditLog::~EditLog() = default;

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
    grading::SqliteDatabase::Transaction t(*db_);
    auto s = db_->prepare(
        "INSERT INTO versions (version, author, kind, unix_ms, scene) VALUES (?1, ?2, ?3, ?4, ?5)");
    s.bind(1, entry.version)
        .bind(2, entry.author)
        .bind(3, nameOf(entry.kind))
        .bind(4, entry.unixMillis)
        .bind(5, entry.scene);
    s.run();
    t.commit();
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

std::vector<SnapshotInfo> EditLog::snapshots() {
    auto s = db_->prepare("SELECT id, version, label, author FROM snapshots ORDER BY id");
    std::vector<SnapshotInfo> out;
    while (s.step())
        out.push_back({s.integer(0), s.integer(1), s.text(2), s.text(3)});
    return out;
}

} // namespace fl::classroom
