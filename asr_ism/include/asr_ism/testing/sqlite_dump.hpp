// Test support for the suite's gtests (needs gtest): whole-file dumps of SQLite databases.
#pragma once

#include <gtest/gtest.h>
#include <sqlite3.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <map>
#include <string>
#include <vector>

namespace asr_ism::testing {

/// One cell as text that tells types apart and keeps doubles bit for bit.
inline std::string cellText(sqlite3_stmt* statement, int column) {
  switch (sqlite3_column_type(statement, column)) {
    case SQLITE_INTEGER:
      return "i" + std::to_string(sqlite3_column_int64(statement, column));
    case SQLITE_FLOAT: {
      const double value = sqlite3_column_double(statement, column);
      std::uint64_t bits;
      std::memcpy(&bits, &value, sizeof bits);
      return "r" + std::to_string(bits);
    }
    case SQLITE_TEXT:
      return "t" +
             std::string(reinterpret_cast<const char*>(sqlite3_column_text(statement, column)));
    case SQLITE_BLOB:
      return "b" + std::string(static_cast<const char*>(sqlite3_column_blob(statement, column)),
                               sqlite3_column_bytes(statement, column));
    default:
      return "n";
  }
}

/// The rows `sql` returns, each as its cells' cellText joined by '\x1f' (one after each cell).
inline std::vector<std::string> queryRows(sqlite3* db, const std::string& sql) {
  sqlite3_stmt* statement = nullptr;
  EXPECT_EQ(sqlite3_prepare_v2(db, sql.c_str(), -1, &statement, nullptr), SQLITE_OK) << sql;
  std::vector<std::string> rows;
  while (sqlite3_step(statement) == SQLITE_ROW) {
    std::string row;
    for (int column = 0; column < sqlite3_column_count(statement); ++column)
      row += cellText(statement, column) + "\x1f";
    rows.push_back(row);
  }
  sqlite3_finalize(statement);
  return rows;
}

/// Every table's rows (sorted, so a comparison does not depend on scan order) and the schema.
struct Dump {
  std::map<std::string, std::vector<std::string>> rows;  // per table, sorted
  std::map<std::string, std::string> schema;             // sqlite_master: name -> sql
};

/// Reads the whole database at `path` (read-only).
inline Dump dumpFile(const std::string& path) {
  sqlite3* db = nullptr;
  EXPECT_EQ(sqlite3_open_v2(path.c_str(), &db, SQLITE_OPEN_READONLY, nullptr), SQLITE_OK);
  Dump dump;
  for (const std::string& entry :
       queryRows(db, "SELECT name, coalesce(sql, '') FROM sqlite_master")) {
    const std::size_t separator = entry.find('\x1f');
    dump.schema[entry.substr(1, separator - 1)] = entry.substr(separator + 1);
  }
  for (const std::string& entry :
       queryRows(db, "SELECT name FROM sqlite_master WHERE type = 'table'")) {
    const std::string table = entry.substr(1, entry.size() - 2);
    auto rows = queryRows(db, "SELECT * FROM \"" + table + "\"");
    std::sort(rows.begin(), rows.end());
    dump.rows[table] = rows;
  }
  sqlite3_close(db);
  return dump;
}

}  // namespace asr_ism::testing
