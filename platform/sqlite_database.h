#pragma once
// The SQLite C API, held by RAII: a connection (WAL, foreign keys, a busy
// timeout so readers and one writer share a file) and prepared statements
// with bound values. Errors throw SqliteError with SQLite's message.
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

struct sqlite3;
struct sqlite3_stmt;

namespace fl::platform {

struct SqliteError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

class SqliteStatement;

class SqliteDatabase {
  public:
    explicit SqliteDatabase(const std::string& path, bool readOnly = false);
    ~SqliteDatabase();
    SqliteDatabase(const SqliteDatabase&) = delete;
    SqliteDatabase& operator=(const SqliteDatabase&) = delete;

    void execute(std::string_view sql); // one or more statements, no results
    SqliteStatement prepare(std::string_view sql);
    std::int64_t lastInsertId() const;

    // BEGIN IMMEDIATE ... COMMIT, rolled back if the scope is left by an
    // exception. Inside another transaction it is part of that one (the
    // outer one commits or rolls back).
    class Transaction {
      public:
        explicit Transaction(SqliteDatabase& db);
        ~Transaction();
        void commit();

      private:
        SqliteDatabase& db_;
        bool nested_ = false;
        bool done_ = false;
    };

  private:
    friend class SqliteStatement;
    sqlite3* db_ = nullptr;
};

class SqliteStatement {
  public:
    SqliteStatement(sqlite3* db, std::string_view sql);
    ~SqliteStatement();
    SqliteStatement(SqliteStatement&& o) noexcept;
    SqliteStatement(const SqliteStatement&) = delete;
    SqliteStatement& operator=(const SqliteStatement&) = delete;

    // Parameters are numbered from 1, as in SQL's ?1 ?2 ...
    SqliteStatement& bind(int index, std::string_view text);
    SqliteStatement& bind(int index, double value);
    SqliteStatement& bind(int index, std::int64_t value);
    SqliteStatement& bindNull(int index);
    // The next row: true while there is one. run() steps to the end.
    bool step();
    void run();
    void reset();

    std::string text(int column) const;
    double number(int column) const;
    std::int64_t integer(int column) const;
    bool isNull(int column) const;
    int columns() const; // of the result rows
    std::string columnName(int column) const;

  private:
    sqlite3* db_;
    sqlite3_stmt* statement_ = nullptr;
};

} // namespace fl::platform
