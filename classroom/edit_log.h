#pragma once
// The class's memory (docs/classroom.md, "Recovery"): an append-only SQLite
// log in WAL mode with one row per applied version (the whole scene text, so
// any version is one read: replay and export need no patching) and named
// snapshots. The class writes a version here before anyone is told of it, so
// a server killed at any moment restarts with every version it announced.
#include "clock.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace fl::grading {
class SqliteDatabase;
}

namespace fl::classroom {

enum class EditKind { Start, Edit, Command, Push, Undo };

struct LoggedVersion {
    std::int64_t version = 0;
    std::string author;
    EditKind kind = EditKind::Edit;
    std::string scene;
    std::int64_t unixMillis = 0;
};

struct SnapshotInfo {
    std::int64_t id = 0;
    std::int64_t version = 0;
    std::string label;
    std::string author;
};

class EditLog {
  public:
    // Opens (creating) DIR/classroom.sqlite; throws grading::SqliteError.
    explicit EditLog(const std::filesystem::path& dataDir);
    ~EditLog();
    EditLog(const EditLog&) = delete;
    EditLog& operator=(const EditLog&) = delete;

    // The newest version, if the log holds any.
    std::optional<LoggedVersion> latest();
    std::optional<LoggedVersion> at(std::int64_t version);
    // Versions after `version`, oldest first, at most `limit`, without their scenes.
    std::vector<LoggedVersion> after(std::int64_t version, std::size_t limit);
    // Durable when it returns (one transaction); throws when it cannot be.
    void append(const LoggedVersion& entry);
    std::int64_t snapshot(std::int64_t version, const std::string& label,
                          const std::string& author);
    std::vector<SnapshotInfo> snapshots();

  private:
    std::unique_ptr<grading::SqliteDatabase> db_;
};

std::string_view nameOf(EditKind kind);

} // namespace fl::classroom
