#pragma once

#include <sqlite3.h>

#include <cstdint>
#include <string>

namespace asr_ism::sqlite {

/// A prepared statement; binds by 1-based index, steps, and reads columns by 0-based index.
class Statement {
 public:
  Statement(sqlite3* db, const std::string& sql, const std::string& path);
  ~Statement();
  Statement(const Statement&) = delete;
  Statement& operator=(const Statement&) = delete;

  Statement& bind(int index, double value);
  Statement& bind(int index, std::int64_t value);
  Statement& bind(int index, int value) { return bind(index, static_cast<std::int64_t>(value)); }
  Statement& bind(int index, const std::string& value);
  Statement& bindNull(int index);

  /// Advances to the next row; false when done. Throws InputError on failure.
  bool step();
  /// Runs a statement that returns no row, then resets it for reuse.
  void execute();
  void reset();

  bool isNull(int column) const;
  double columnDouble(int column) const;
  /// The column's value if it is stored as a number; throws InputError naming `row` and the
  /// column for NULL (as SQLite stores a NaN) or text, which columnDouble would read as 0.
  double columnNumber(int column, const std::string& row) const;
  std::int64_t columnInt(int column) const;
  std::string columnText(int column) const;

 private:
  void check(int code, const char* action) const;

  sqlite3* db_;
  sqlite3_stmt* statement_ = nullptr;
  std::string path_;
};

/// An open SQLite file. Read-only opening never creates a file; errors name the file.
class Database {
 public:
  enum class Mode { kReadOnly, kReadWriteCreate };

  Database(const std::string& path, Mode mode);
  ~Database();
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;

  void execute(const std::string& sql);
  Statement prepare(const std::string& sql) { return Statement(db_, sql, path_); }
  bool hasTable(const std::string& table);
  std::int64_t lastInsertId() const;
  const std::string& path() const { return path_; }

 private:
  sqlite3* db_ = nullptr;
  std::string path_;
};

/// Commits on commit(); rolls back if destroyed before, so an error never leaves half a write.
class Transaction {
 public:
  explicit Transaction(Database& db);
  ~Transaction();
  void commit();

 private:
  Database& db_;
  bool done_ = false;
};

}  // namespace asr_ism::sqlite
