/// @file export_sqlite_command.cpp
/// `fsweep export-sqlite DIR [--out FILE]`: a result directory's runs.csv and progress.csv as one
/// SQLite database (report/sqlite_export.hpp; default DIR/results.sqlite).

#include <iostream>
#include <memory>

#include "cli/commands.hpp"
#include "report/sqlite_export.hpp"

namespace fsweep::cli {
namespace {

struct ExportSqliteOptions {
  std::string dir;
  std::string out;
};

int run_export_sqlite(const ExportSqliteOptions& o) {
  const SqliteExport e = export_sqlite(o.dir, o.out);
  std::cout << "wrote " << describe_export(e) << '\n';
  return 0;
}

}  // namespace

Command add_export_sqlite_command(CLI::App& app) {
  auto o = std::make_shared<ExportSqliteOptions>();
  CLI::App* sub = app.add_subcommand(
      "export-sqlite",
      "Write a result directory's runs.csv and progress.csv as one SQLite database (tables runs, "
      "configurations, progress, columns, manifest)");
  sub->add_option("DIR", o->dir, "Result directory (holding runs.csv and progress.csv)")->required();
  sub->add_option("--out", o->out,
                  "Database file (default: DIR/results.sqlite; an existing file is replaced only if it is "
                  "such an export)");
  return [o] { return run_export_sqlite(*o); };
}

}  // namespace fsweep::cli
