#include "asr_ism/sqlite/sqlite_database.hpp"

#include <sys/stat.h>

#include "asr_ism/common_types.hpp"

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

namespace {

bool fileExists(const std::string& path) {
  struct stat info;
  return stat(path.c_str(), &info) == 0;
}

// Opens `path` with `flags` and reads the schema, which is where SQLite notices a file that is
// not a database, or a hot journal. Returns the SQLite result code; *db is closed on failure.
int openAndRead(const std::string& path, int flags, sqlite3** db, std::string& message) {
  if (sqlite3_open_v2(path.c_str(), db, flags, nullptr) != SQLITE_OK) {
    message = *db ? sqlite3_errmsg(*db) : "out of memory";
    sqlite3_close(*db);
    *db = nullptr;
    return SQLITE_CANTOPEN;
  }
  sqlite3_extended_result_codes(*db, 1);
  sqlite3_busy_timeout(*db, 5000);
  const int code =
      sqlite3_exec(*db, "SELECT count(*) FROM sqlite_master", nullptr, nullptr, nullptr);
  if (code != SQLITE_OK) {
    message = sqlite3_errmsg(*db);
    sqlite3_close(*db);
    *db = nullptr;
  }
  return code;
}

// A process killed while writing leaves its rollback journal ("<file>-journal"): the file is
// intact once the journal is rolled back, but a read-only connection may not do that. Rolls it
// back the way any writer would (SQLite does so only for a journal no live writer holds).
bool rollBackHotJournal(const std::string& path) {
  sqlite3* db = nullptr;
  std::string ignored;
  const bool done = openAndRead(path, SQLITE_OPEN_READWRITE, &db, ignored) == SQLITE_OK;
  sqlite3_close(db);
  return done;
}

}  // namespace

Database::Database(const std::string& path, Mode mode) : path_(path) {
  if (mode == Mode::kReadOnly && !fileExists(path)) {
    throw InputError(path + ": no such file");
  }
  const int flags =
      mode == Mode::kReadOnly ? SQLITE_OPEN_READONLY : SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE;
  std::string message;
  int code = openAndRead(path, flags, &db_, message);
  const std::string journal = path + "-journal";
  // SQLITE_READONLY_ROLLBACK, or SQLITE_READONLY where SQLite cannot tell it apart.
  if ((code & 0xff) == SQLITE_READONLY && fileExists(journal)) {
    if (!rollBackHotJournal(path)) {
      throw InputError(path + ": holds an unfinished write (the rollback journal " + journal +
                       " of a process killed while writing), and this user may not roll it "
                       "back. Keep the journal (deleting it can corrupt the file) and open the "
                       "file once as a user who may write it and its folder, e.g. `sqlite3 " +
                       path + " 'PRAGMA integrity_check'`");
    }
    code = openAndRead(path, flags, &db_, message);
  }
  if (code == SQLITE_CANTOPEN)
    throw InputError(path + ": cannot open as SQLite database: " + message);
  if (code != SQLITE_OK)
    throw InputError(path + ": not an SQLite database (" + message + ")");
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
