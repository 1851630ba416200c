#include "report/sqlite_export.hpp"

#include <sqlite3.h>

#include <array>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <optional>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

#include "core/config_error.hpp"
#include "core/csv_reader.hpp"
#include "core/files.hpp"
#include "core/io_error.hpp"
#include "core/shard_dirs.hpp"
#include "report/runs_schema.hpp"

namespace fsweep {
inline namespace report {
namespace {

namespace fs = std::filesystem;

enum class SqlType { Integer, Real, Text };

std::string_view sql_name(SqlType t) {
  switch (t) {
    case SqlType::Integer:
      return "INTEGER";
    case SqlType::Real:
      return "REAL";
    case SqlType::Text:
      break;
  }
  return "TEXT";
}

std::string_view role_name(ColumnRole r) {
  switch (r) {
    case ColumnRole::Identity:
      return "identity";
    case ColumnRole::Instance:
      return "instance";
    case ColumnRole::Config:
      return "config";
    case ColumnRole::Outcome:
      return "outcome";
    case ColumnRole::Metric:
      return "metric";
    case ColumnRole::Other:
      break;
  }
  return "other";
}

/// `cell` as a 64-bit integer, when it is one whole.
std::optional<std::int64_t> parse_integer(std::string_view cell) {
  std::int64_t v = 0;
  const auto res = std::from_chars(cell.data(), cell.data() + cell.size(), v);
  if (res.ec != std::errc() || res.ptr != cell.data() + cell.size()) return std::nullopt;
  return v;
}

/// A config column's type from its cells: REAL when there is a non-empty cell and every one is a
/// number, else TEXT.
class TypeVote {
 public:
  void see(std::string_view cell) {
    if (cell.empty()) return;
    seen_ = true;
    numbers_ = numbers_ && parse_number(cell).has_value();
  }
  [[nodiscard]] SqlType type() const { return seen_ && numbers_ ? SqlType::Real : SqlType::Text; }

 private:
  bool seen_ = false;
  bool numbers_ = true;
};

/// `name` as an SQL identifier.
std::string sql_identifier(std::string_view name) {
  std::string out = "\"";
  for (const char c : name) out += c == '"' ? std::string("\"\"") : std::string(1, c);
  return out + "\"";
}

/// An SQLite connection that closes itself; its errors are ConfigErrors at its file, but for a
/// file the machine does not let it write (a full disk, a file size limit): IoError.
class Database {
 public:
  explicit Database(std::string path) : path_(std::move(path)) {
    if (sqlite3_open_v2(path_.c_str(), &db_, SQLITE_OPEN_READWRITE | SQLITE_OPEN_CREATE, nullptr) !=
        SQLITE_OK) {
      const std::string why = db_ != nullptr ? sqlite3_errmsg(db_) : "out of memory";
      sqlite3_close(db_);
      throw ConfigError(path_, "cannot create the database: " + why);
    }
  }
  Database(const Database&) = delete;
  Database& operator=(const Database&) = delete;
  ~Database() { sqlite3_close(db_); }

  void exec(const std::string& sql) {
    if (sqlite3_exec(db_, sql.c_str(), nullptr, nullptr, nullptr) != SQLITE_OK) fail();
  }
  [[noreturn]] void fail() const {
    const std::string what = std::string("SQLite: ") + sqlite3_errmsg(db_);
    const int code = sqlite3_errcode(db_) & 0xff;  // the primary code of an extended one
    int os_error = 0;  // of the database file's last failed call (sqlite3_system_errno() had 0 for EFBIG)
    (void)sqlite3_file_control(db_, "main", SQLITE_FCNTL_LAST_ERRNO, &os_error);
    if (code == SQLITE_FULL && os_error == 0) os_error = ENOSPC;  // a short write: full, as SQLite says
    if ((code == SQLITE_FULL || code == SQLITE_IOERR) && os_error != 0) throw IoError(path_, what, os_error);
    throw ConfigError(path_, what);
  }
  [[nodiscard]] sqlite3* handle() const { return db_; }

 private:
  std::string path_;
  sqlite3* db_ = nullptr;
};

/// A prepared INSERT of `columns` values into `table`, bound cell by cell and run by insert().
class Insert {
 public:
  Insert(Database& db, const std::string& table, std::size_t columns) : db_(db) {
    std::string sql = "INSERT INTO " + table + " VALUES (";
    for (std::size_t i = 0; i < columns; ++i) sql += i == 0 ? "?" : ",?";
    sql += ")";
    if (sqlite3_prepare_v2(db.handle(), sql.c_str(), -1, &stmt_, nullptr) != SQLITE_OK) db.fail();
  }
  Insert(const Insert&) = delete;
  Insert& operator=(const Insert&) = delete;
  ~Insert() { sqlite3_finalize(stmt_); }

  /// Binds `cell` to the column at `index` (from 0) as `type`: empty (and NaN) is NULL; the
  /// cell was checked to be of its type.
  void bind(std::size_t index, SqlType type, const std::string& cell) {
    const int i = static_cast<int>(index) + 1;
    int rc = SQLITE_OK;
    if (cell.empty()) {
      rc = sqlite3_bind_null(stmt_, i);
    } else if (type == SqlType::Integer) {
      rc = sqlite3_bind_int64(stmt_, i, *parse_integer(cell));
    } else if (type == SqlType::Real) {
      const double v = *parse_number(cell);
      rc = std::isnan(v) ? sqlite3_bind_null(stmt_, i) : sqlite3_bind_double(stmt_, i, v);
    } else {
      rc = sqlite3_bind_text(stmt_, i, cell.data(), static_cast<int>(cell.size()), SQLITE_TRANSIENT);
    }
    if (rc != SQLITE_OK) db_.fail();
  }
  void bind_integer(std::size_t index, std::int64_t v) {
    if (sqlite3_bind_int64(stmt_, static_cast<int>(index) + 1, v) != SQLITE_OK) db_.fail();
  }
  void insert() {
    if (sqlite3_step(stmt_) != SQLITE_DONE) db_.fail();
    if (sqlite3_reset(stmt_) != SQLITE_OK) db_.fail();
  }

 private:
  Database& db_;
  sqlite3_stmt* stmt_ = nullptr;
};

/// runs.csv's header, column types and run keys (the first pass over it).
struct RunsLayout {
  std::optional<RunsHeader> header;
  std::vector<SqlType> types;
  /// run_key -> line of its row.
  std::unordered_map<std::string, std::size_t> keys;
};

RunsLayout read_runs_layout(const std::string& path) {
  RunsLayout layout;
  CsvReader in(path);
  layout.header.emplace(in.header(), path);
  const RunsHeader& header = *layout.header;
  const int run_index = header.column(kRunIndexColumn);
  std::vector<TypeVote> votes(header.names().size());
  while (in.next()) {
    const std::vector<std::string>& f = in.fields();
    for (std::size_t c = 0; c < f.size(); ++c) {
      if (header.role(c) == ColumnRole::Metric) (void)metric_value(f[c], header.names()[c], in);
      if (header.role(c) == ColumnRole::Config) votes[c].see(f[c]);
    }
    if (run_index >= 0 && !parse_integer(f[static_cast<std::size_t>(run_index)])) {
      throw ConfigError(in.where(), std::string("column 'run_index': '") +
                                        f[static_cast<std::size_t>(run_index)] + "' is not an integer");
    }
    const auto [it, fresh] = layout.keys.emplace(f[header.run_key()], in.line());
    if (!fresh) {
      throw ConfigError(in.where(),
                        "run_key " + it->first + " is also on line " + std::to_string(it->second));
    }
  }
  for (std::size_t c = 0; c < votes.size(); ++c) {
    const ColumnRole role = header.role(c);
    if (static_cast<int>(c) == run_index) {
      layout.types.push_back(SqlType::Integer);
    } else if (role == ColumnRole::Metric) {
      layout.types.push_back(SqlType::Real);
    } else if (role == ColumnRole::Config) {
      layout.types.push_back(votes[c].type());
    } else {
      layout.types.push_back(SqlType::Text);
    }
  }
  return layout;
}

/// True when `path` is an SQLite database with this export's application_id.
bool is_export(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::array<char, 72> head{};
  if (!in.read(head.data(), head.size())) return false;
  if (std::memcmp(head.data(), "SQLite format 3", 16) != 0) return false;  // with its NUL
  std::uint32_t id = 0;
  for (int i = 68; i < 72; ++i)
    id = (id << 8U) | static_cast<unsigned char>(head[static_cast<std::size_t>(i)]);
  return id == static_cast<std::uint32_t>(kSqliteApplicationId);
}

/// Throws unless `out` is free or an export of ours (which is replaced).
void check_replaceable(const std::string& out) {
  std::error_code ec;
  const fs::file_status st = fs::status(out, ec);
  if (!fs::exists(st)) return;
  if (!fs::is_regular_file(st) || !is_export(out)) {
    throw ConfigError(out,
                      "exists and is not a database written by fsweep export-sqlite; remove it or choose "
                      "another --out (an export replaces only its own files)");
  }
}

/// The checks of the result directory `dir` (the file comment's errors).
void check_result_dir(const std::string& dir) {
  std::error_code ec;
  if (!fs::is_directory(dir, ec)) throw ConfigError(dir, "no such result directory");
  if (fs::exists(dir + "/runs.csv", ec)) {
    if (!fs::exists(dir + "/progress.csv", ec)) {
      throw ConfigError(dir + "/progress.csv", "missing: a result directory has runs.csv and progress.csv");
    }
    return;
  }
  throw ConfigError(dir, std::string("not a result directory: no runs.csv") +
                             (!shard_dirs(dir).empty()
                                  ? " (a sharded run's results are in its shard-i-of-n/ directories until "
                                    "`fsweep merge`)"
                                  : ""));
}

/// Fills `runs` and `configurations` from runs.csv (the second pass); returns the counts.
std::pair<std::uint64_t, std::uint64_t> write_runs(Database& db, const std::string& path,
                                                   const RunsLayout& layout) {
  const RunsHeader& header = *layout.header;
  const std::vector<std::string>& names = header.names();
  const std::vector<std::size_t>& config = header.config();
  std::string runs_sql = "CREATE TABLE runs (config_id INTEGER NOT NULL REFERENCES configurations(config_id)";
  std::string configs_sql = "CREATE TABLE configurations (config_id INTEGER PRIMARY KEY";
  for (std::size_t c = 0; c < names.size(); ++c) {
    ((runs_sql += ", ") += sql_identifier(names[c]) + " ") += sql_name(layout.types[c]);
  }
  for (const std::size_t c : config)
    ((configs_sql += ", ") += sql_identifier(names[c]) + " ") += sql_name(layout.types[c]);
  db.exec(configs_sql + ")");
  db.exec(runs_sql + ")");
  db.exec("CREATE TABLE columns (name TEXT, position INTEGER, role TEXT, type TEXT)");
  Insert column_row(db, "columns", 4);
  for (std::size_t c = 0; c < names.size(); ++c) {
    column_row.bind(0, SqlType::Text, names[c]);
    column_row.bind_integer(1, static_cast<std::int64_t>(c));
    column_row.bind(2, SqlType::Text, std::string(role_name(header.role(c))));
    column_row.bind(3, SqlType::Text, std::string(sql_name(layout.types[c])));
    column_row.insert();
  }

  Insert run_row(db, "runs", names.size() + 1);
  Insert config_row(db, "configurations", config.size() + 1);
  std::unordered_map<std::string, std::int64_t> config_ids;
  std::uint64_t runs = 0;
  CsvReader in(path);
  while (in.next()) {
    const std::vector<std::string>& f = in.fields();
    const auto [it, fresh] =
        config_ids.emplace(header.config_key(f), static_cast<std::int64_t>(config_ids.size()));
    if (fresh) {
      config_row.bind_integer(0, it->second);
      for (std::size_t k = 0; k < config.size(); ++k)
        config_row.bind(k + 1, layout.types[config[k]], f[config[k]]);
      config_row.insert();
    }
    run_row.bind_integer(0, it->second);
    for (std::size_t c = 0; c < f.size(); ++c) run_row.bind(c + 1, layout.types[c], f[c]);
    run_row.insert();
    ++runs;
  }
  return {runs, config_ids.size()};
}

/// Fills `progress` from progress.csv: run_index INTEGER, run_key TEXT, the samples REAL.
std::uint64_t write_progress(Database& db, const std::string& path, const RunsLayout& layout) {
  CsvReader in(path);
  const std::vector<std::string>& names = in.header();
  std::vector<SqlType> types;
  int run_key = -1;
  std::string sql = "CREATE TABLE progress (";
  for (std::size_t c = 0; c < names.size(); ++c) {
    types.push_back(names[c] == kRunKeyColumn     ? SqlType::Text
                    : names[c] == kRunIndexColumn ? SqlType::Integer
                                                  : SqlType::Real);
    if (names[c] == kRunKeyColumn) run_key = static_cast<int>(c);
    ((sql += c == 0 ? "" : ", ") += sql_identifier(names[c]) + " ") += sql_name(types.back());
  }
  if (run_key < 0) throw ConfigError(path + ":1", "no column 'run_key' in the header");
  db.exec(sql + ")");
  db.exec("CREATE INDEX progress_run_key ON progress (run_key)");
  Insert row(db, "progress", names.size());
  std::uint64_t rows = 0;
  while (in.next()) {
    const std::vector<std::string>& f = in.fields();
    for (std::size_t c = 0; c < f.size(); ++c) {
      const bool ok = types[c] == SqlType::Text ||
                      (types[c] == SqlType::Integer ? parse_integer(f[c]).has_value()
                                                    : f[c].empty() || parse_number(f[c]).has_value());
      if (!ok) {
        throw ConfigError(in.where(), "column '" + names[c] + "': '" + f[c] + "' is not " +
                                          (types[c] == SqlType::Integer ? "an integer" : "a number"));
      }
    }
    if (layout.keys.count(f[static_cast<std::size_t>(run_key)]) == 0) continue;  // no runs.csv row
    for (std::size_t c = 0; c < f.size(); ++c) row.bind(c, types[c], f[c]);
    row.insert();
    ++rows;
  }
  return rows;
}

/// Builds the whole database in the new file `path`.
SqliteExport build(const std::string& path, const std::string& dir) {
  const RunsLayout layout = read_runs_layout(dir + "/runs.csv");
  SqliteExport report;
  Database db(path);
  db.exec("PRAGMA journal_mode = OFF; PRAGMA synchronous = OFF; PRAGMA application_id = " +
          std::to_string(kSqliteApplicationId) +
          "; PRAGMA user_version = " + std::to_string(kSqliteSchemaVersion) + "; BEGIN");
  std::tie(report.runs, report.configurations) = write_runs(db, dir + "/runs.csv", layout);
  report.progress_rows = write_progress(db, dir + "/progress.csv", layout);
  db.exec("CREATE TABLE manifest (json TEXT)");
  if (std::ifstream manifest(dir + "/manifest.json", std::ios::binary); manifest) {
    const std::string text((std::istreambuf_iterator<char>(manifest)), std::istreambuf_iterator<char>());
    Insert row(db, "manifest", 1);
    row.bind(0, SqlType::Text, text);
    row.insert();
  }
  db.exec("COMMIT");
  return report;
}

}  // namespace

std::string describe_export(const SqliteExport& e) {
  return e.path + " (" + std::to_string(e.runs) + " runs, " + std::to_string(e.configurations) +
         " configurations, " + std::to_string(e.progress_rows) + " progress rows)";
}

SqliteExport export_sqlite(const std::string& dir, const std::string& out) {
  check_result_dir(dir);
  const std::string path = out.empty() ? dir + "/" + kSqliteFileName : out;
  check_replaceable(path);
  const std::string tmp = temp_path(path);
  std::error_code ec;
  fs::remove(tmp, ec);
  SqliteExport report;
  try {
    report = build(tmp, dir);
  } catch (...) {
    fs::remove(tmp, ec);
    throw;
  }
  fs::rename(tmp, path, ec);
  if (ec) {
    const std::string why = ec.message();
    fs::remove(tmp, ec);
    throw ConfigError(path, "cannot replace: " + why);
  }
  report.path = path;
  return report;
}

}  // namespace report
}  // namespace fsweep
