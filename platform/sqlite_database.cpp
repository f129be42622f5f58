#include "platform/sqlite_database.h"

#include <sqlite3.h>

namespace fl::platform {
namespace {

[[noreturn]] void fail(sqlite3* db, const std::string& what) {
    throw SqliteError(what + ": " + (db ? sqlite3_errmsg(db) : "out of memory"));
}

} // namespace

SqliteDatabase::SqliteDatabase(const std::string& path, bool readOnly) {
    const int flags =
        readOnly ? SQLITE_OPEN_READONLY : (SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE);
    if (sqlite3_open_v2(path.c_str(), &db_, flags | SQLITE_OPEN_NOMUTEX, nullptr) != SQLITE_OK) {
        const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
        sqlite3_close(db_);
        db_ = nullptr;
        throw SqliteError("cannot open " + path + ": " + message);
    }
    // A batch writing while the grading view reads: wait for each other briefly.
    sqlite3_busy_timeout(db_, 10000);
    execute("PRAGMA foreign_keys = ON");
    if (!readOnly) execute("PRAGMA journal_mode = WAL; PRAGMA synchronous = NORMAL");
}

SqliteDatabase::~SqliteDatabase() {
    sqlite3_close(db_);
}

void SqliteDatabase::execute(std::string_view sql) {
    char* error = nullptr;
    const std::string text(sql);
    if (sqlite3_exec(db_, text.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
        const std::string message = error ? error : "error";
        sqlite3_free(error);
        throw SqliteError(message + " (in: " + text.substr(0, 80) + ")");
    }
}

SqliteStatement SqliteDatabase::prepare(std::string_view sql) {
    return SqliteStatement(db_, sql);
}

std::int64_t SqliteDatabase::lastInsertId() const {
    return sqlite3_last_insert_rowid(db_);
}

SqliteDatabase::Transaction::Transaction(SqliteDatabase& db)
    : db_(db), nested_(sqlite3_get_autocommit(db.db_) == 0) {
    if (!nested_) db_.execute("BEGIN IMMEDIATE");
}

SqliteDatabase::Transaction::~Transaction() {
    if (!done_ && !nested_) {
        char* error = nullptr;
        sqlite3_exec(db_.db_, "ROLLBACK", nullptr, nullptr, &error);
        sqlite3_free(error);
    }
}

void SqliteDatabase::Transaction::commit() {
    if (!nested_) db_.execute("COMMIT");
    done_ = true;
}

SqliteStatement::SqliteStatement(sqlite3* db, std::string_view sql) : db_(db) {
    if (sqlite3_prepare_v2(db, sql.data(), int(sql.size()), &statement_, nullptr) != SQLITE_OK)
        fail(db, "cannot prepare " + std::string(sql.substr(0, 60)));
}

SqliteStatement::~SqliteStatement() {
    sqlite3_finalize(statement_);
}

SqliteStatement::SqliteStatement(SqliteStatement&& o) noexcept
    : db_(o.db_), statement_(o.statement_) {
    o.statement_ = nullptr;
}

SqliteStatement& SqliteStatement::bind(int index, std::string_view text) {
    if (sqlite3_bind_text(statement_, index, text.data(), int(text.size()), SQLITE_TRANSIENT) !=
        SQLITE_OK)
        fail(db_, "bind");
    return *this;
}

SqliteStatement& SqliteStatement::bind(int index, double value) {
    if (sqlite3_bind_double(statement_, index, value) != SQLITE_OK) fail(db_, "bind");
    return *this;
}

SqliteStatement& SqliteStatement::bind(int index, std::int64_t value) {
    if (sqlite3_bind_int64(statement_, index, value) != SQLITE_OK) fail(db_, "bind");
    return *this;
}

SqliteStatement& SqliteStatement::bindNull(int index) {
    if (sqlite3_bind_null(statement_, index) != SQLITE_OK) fail(db_, "bind");
    return *this;
}

bool SqliteStatement::step() {
    const int r = sqlite3_step(statement_);
    if (r == SQLITE_ROW) return true;
    if (r == SQLITE_DONE) return false;
    fail(db_, "step");
}

void SqliteStatement::run() {
    while (step()) {
    }
}

void SqliteStatement::reset() {
    sqlite3_reset(statement_);
    sqlite3_clear_bindings(statement_);
}

std::string SqliteStatement::text(int column) const {
    const auto* p = sqlite3_column_text(statement_, column);
    return p ? std::string(reinterpret_cast<const char*>(p),
                           std::size_t(sqlite3_column_bytes(statement_, column)))
             : std::string{};
}

double SqliteStatement::number(int column) const {
    return sqlite3_column_double(statement_, column);
}

std::int64_t SqliteStatement::integer(int column) const {
    return sqlite3_column_int64(statement_, column);
}

bool SqliteStatement::isNull(int column) const {
    return sqlite3_column_type(statement_, column) == SQLITE_NULL;
}

int SqliteStatement::columns() const {
    return sqlite3_column_count(statement_);
}

std::string SqliteStatement::columnName(int column) const {
    const char* name = sqlite3_column_name(statement_, column);
    return name ? name : "";
}

} // namespace fl::platform
