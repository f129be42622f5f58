#pragma once
// The class's memory (docs/classroom.md, "Recovery"): an append-only SQLite
// log in WAL mode with one row per applied version (the whole scene text, so
// any version is one read: replay and export need no patching), named
// snapshots, and the chat. The class writes a version here before anyone is
// told of it, so a server killed at any moment restarts with every version it
// announced.
//
// The log refuses damage instead of crash-looping (issue 26 §5): it is
// checked (PRAGMA quick_check) when opened; a folder that held a class (its
// marker, classroom.id) but whose log is missing or empty is refused unless a
// new class is asked for; and one server at a time holds the folder.
#include "class_clock.h"
#include "protocol.h"

#include <cstdint>
#include <filesystem>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace fl::platform {
class SqliteDatabase;
}

namespace fl::classroom {

struct LoggedVersion {
    std::int64_t version = 0;
    std::string author;
    EditKind kind = EditKind::Edit;
    std::string scene;
    std::int64_t unixMillis = 0;
};

struct ChatLine {
    std::string author;
    std::string text;
    std::int64_t unixMillis = 0;
};

// Why a class's data folder cannot be used; what() says what to do.
struct EditLogRefused : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct SnapshotInfo {
    std::int64_t id = 0;
    std::int64_t version = 0;
    std::string label;
    std::string author;
};

class EditLog {
  public:
    // Opens (creating) DIR/classroom.sqlite and holds DIR for this process.
    // Throws EditLogRefused when another server holds DIR, the log is
    // damaged, or the folder held a class whose log is gone (unless
    // `startNew`), and platform::SqliteError when SQLite cannot open it.
    explicit EditLog(const std::filesystem::path& dataDir, bool startNew = false);
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
    void appendChat(const ChatLine& line);
    // The newest `limit` lines, oldest first.
    std::vector<ChatLine> recentChat(std::size_t limit);

    // The file names in the data folder.
    static constexpr const char* kLogFile = "classroom.sqlite";
    static constexpr const char* kMarkerFile = "classroom.id";
    static constexpr const char* kLockFile = "classroom.lock";

  private:
    struct FolderLock; // held while the log is open (released if opening fails)
    std::filesystem::path dir_;
    std::unique_ptr<FolderLock> lock_;
    bool marked_ = false;
    std::unique_ptr<platform::SqliteDatabase> db_;
};

} // namespace fl::classroom
