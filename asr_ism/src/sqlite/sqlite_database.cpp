#include "asr_ism/sqlite/sqlite_database.hpp"

#include <sys/stat.h>

#include "asr_ism/input_error.hpp"

namespace asr_ism::sqlite {

Statement::Statement(sqlite3* db, const std::string& sql, const std::string& path)
    : db_(db), path_(path) {
  check(sqlite3_prepare_v2(db_, sql.c_str(), -1, &statement_, nullptr), "preparing a query");
}

Statement::~Statement() {
  sqlite3_finalize(statement_);
}

void Statement::check(int code, const char* action) const {
  if (code != SQLITE_OK && code != SQLITE_ROW && code != SQLITE_DONE) {
    throw InputError(path_ + ": SQLite error while " + action + ": " + sqlite3_errmsg(db_));
  }
}

Statement& Statement::bind(int index, double value) {
  check(sqlite3_bind_double(statement_, index, value), "binding a value");
  return *this;
}

Statement& Statement::bind(int index, std::int64_t value) {
  check(sqlite3_bind_int64(statement_, index, value), "binding a value");
  return *this;
}

Statement& Statement::bind(int index, const std::string& value) {
  check(sqlite3_bind_text(statement_, index, value.c_str(), static_cast<int>(value.size()),
                          SQLITE_TRANSIENT),
        "binding a value");
  return *this;
}

Statement& Statement::bindNull(int index) {
  check(sqlite3_bind_null(statement_, index), "binding a value");
  return *this;
}

bool Statement::step() {
  const int code = sqlite3_step(statement_);
  check(code, "reading or writing rows");
  return code == SQLITE_ROW;
}

void Statement::execute() {
  while (step()) {
  }
  reset();
}

void Statement::reset() {
  sqlite3_reset(statement_);
  sqlite3_clear_bindings(statement_);
}

bool Statement::isNull(int column) const {
  return sqlite3_column_type(statement_, column) == SQLITE_NULL;
}

double Statement::columnDouble(int column) const {
  return sqlite3_column_double(statement_, column);
}

double Statement::columnNumber(int column, const std::string& row) const {
  const int type = sqlite3_column_type(statement_, column);
  if (type == SQLITE_FLOAT || type == SQLITE_INTEGER)
    return sqlite3_column_double(statement_, column);
  const std::string name = row + ": column " + sqlite3_column_name(statement_, column);
  if (type == SQLITE_NULL)
    throw InputError(name + " is missing (NULL, as SQLite stores a NaN)");
  throw InputError(name + " is not a number ('" + columnText(column) + "')");
}

std::int64_t Statement::columnInt(int column) const {
  return sqlite3_column_int64(statement_, column);
}

std::string Statement::columnText(int column) const {
  const unsigned char* text = sqlite3_column_text(statement_, column);
  return text == nullptr ? std::string() : std::string(reinterpret_cast<const char*>(text));
}

Database::Database(const std::string& path, Mode mode) : path_(path) {
  struct stat info;
  if (mode == Mode::kReadOnly && stat(path.c_str(), &info) != 0) {
    throw InputError(path + ": no such file");
  }
  const int flags =
      mode == Mode::kReadOnly ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  if (sqlite3_open_v2(path.c_str(), &db_, flags, nullptr) != SQLITE_OK) {
    const std::string message = db_ ? sqlite3_errmsg(db_) : "out of memory";
    sqlite3_close(db_);
    throw InputError(path + ": cannot open as SQLite database: " + message);
  }
  sqlite3_busy_timeout(db_, 5000);
  // A file that is not SQLite opens fine but fails on the first read: check now.
  try {
    execute("SELECT count(*) FROM sqlite_master");
  } catch (const InputError&) {
    sqlite3_close(db_);
    throw InputError(path + ": not an SQLite database");
  }
}

Database::~Database() {
  sqlite3_close(db_);
}

void Database::execute(const std::string& sql) {
  char* error = nullptr;
  if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, &error) != SQLITE_OK) {
    const std::string message = error ? error : "unknown error";
    sqlite3_free(error);
    throw InputError(path_ + ": SQLite error: " + message);
  }
}

bool Database::hasTable(const std::string& table) {
  Statement query = prepare("SELECT 1 FROM sqlite_master WHERE type = 'table' AND name = ?");
  query.bind(1, table);
  return query.step();
}

std::int64_t Database::lastInsertId() const {
  return sqlite3_last_insert_rowid(db_);
}

Transaction::Transaction(Database& db) : db_(db) {
  db_.execute("BEGIN IMMEDIATE");
}

Transaction::~Transaction() {
  if (!done_) {
    try {
      db_.execute("ROLLBACK");
    } catch (...) {
      // Nothing more can be done in a destructor; SQLite rolls back on close anyway.
    }
  }
}

void Transaction::commit() {
  db_.execute("COMMIT");
  done_ = true;
}

}  // namespace asr_ism::sqlite
