#pragma once
/// @file sqlite_test_db.hpp
/// Reads an SQLite database in tests (fsweep export-sqlite's, Planner Arena's): each query's
/// rows as typed values.

#include <sqlite3.h>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

namespace fsweep::testing {

/// One SQL value: NULL, INTEGER, REAL or TEXT.
using SqlValue = std::variant<std::nullptr_t, std::int64_t, double, std::string>;
using SqlRow = std::vector<SqlValue>;

/// A database opened read-only; throws std::runtime_error on any SQLite error.
class SqliteTestDb {
 public:
  explicit SqliteTestDb(const std::string& path) {
    if (sqlite3_open_v2(path.c_str(), &db_, SQLITE_OPEN_READONLY, nullptr) != SQLITE_OK) {
      const std::string why = db_ != nullptr ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      throw std::runtime_error(path + ": " + why);
    }
  }
  SqliteTestDb(const SqliteTestDb&) = delete;
  SqliteTestDb& operator=(const SqliteTestDb&) = delete;
  ~SqliteTestDb() { sqlite3_close(db_); }

  /// Every row of `sql`.
  [[nodiscard]] std::vector<SqlRow> rows(const std::string& sql) const {
    sqlite3_stmt* stmt = nullptr;
    if (sqlite3_prepare_v2(db_, sql.c_str(), -1, &stmt, nullptr) != SQLITE_OK) {
      throw std::runtime_error(sql + ": " + sqlite3_errmsg(db_));
    }
    std::vector<SqlRow> out;
    int rc = SQLITE_ROW;
    while ((rc = sqlite3_step(stmt)) == SQLITE_ROW) {
      SqlRow& row = out.emplace_back();
      for (int c = 0; c < sqlite3_column_count(stmt); ++c) {
        switch (sqlite3_column_type(stmt, c)) {
          case SQLITE_INTEGER:
            row.emplace_back(static_cast<std::int64_t>(sqlite3_column_int64(stmt, c)));
            break;
          case SQLITE_FLOAT:
            row.emplace_back(sqlite3_column_double(stmt, c));
            break;
          case SQLITE_NULL:
            row.emplace_back(nullptr);
            break;
          default:
            row.emplace_back(std::string(reinterpret_cast<const char*>(sqlite3_column_text(stmt, c)),
                                         static_cast<std::size_t>(sqlite3_column_bytes(stmt, c))));
        }
      }
    }
    sqlite3_finalize(stmt);
    if (rc != SQLITE_DONE) throw std::runtime_error(sql + ": " + sqlite3_errmsg(db_));
    return out;
  }

  /// The one value of `sql` (first column of the first row).
  [[nodiscard]] SqlValue value(const std::string& sql) const {
    const std::vector<SqlRow> r = rows(sql);
    if (r.empty() || r[0].empty()) throw std::runtime_error(sql + ": no value");
    return r[0][0];
  }

  /// The column names of table `table`, in order.
  [[nodiscard]] std::vector<std::string> columns(const std::string& table) const {
    std::vector<std::string> names;
    for (const SqlRow& r : rows("PRAGMA table_info(" + table + ")"))
      names.push_back(std::get<std::string>(r[1]));
    return names;
  }

 private:
  sqlite3* db_ = nullptr;
};

/// The number in `v` (INTEGER or REAL); throws std::bad_variant_access for NULL or TEXT.
inline double number(const SqlValue& v) {
  if (const auto* i = std::get_if<std::int64_t>(&v)) return static_cast<double>(*i);
  return std::get<double>(v);
}

}  // namespace fsweep::testing
