// Checks an output file of test2 / test8 (Test2_output.txt, Test8_output.txt)
// independently of the program that wrote it:
//
//   check_output_file FILE --columns NAME,NAME,... --interval SECONDS --rows N [--complete]
//
// It must start with "# key: value" header lines naming every setting in
// force (ode_version, ode_precision, step_seconds, erp, cfm, solver,
// iterations at least), then a line of tab-separated column names (the
// first line not starting with '#') with exactly the given names, then
// tab-separated rows of that many finite numbers. Row i must be
// at time i * SECONDS within half a step (the step is read from the header),
// and there must be exactly N rows. Lines starting with "# t=" (F-key changes)
// may appear between rows. The last line may be "# complete: ..." or
// "# incomplete: ..." (the run's end, and nothing after it); with
// --complete it must be "# complete: ...". Exit status 0 when all holds, 1
// otherwise.
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "check_cli.h"

namespace {

std::vector<std::string> split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::stringstream in(text);
  std::string part;
  while (std::getline(in, part, separator)) parts.push_back(part);
  return parts;
}

bool parseNumber(const std::string& text, double& value) {
  char* end = nullptr;
  value = std::strtod(text.c_str(), &end);
  return !text.empty() && end && *end == '\0' && std::isfinite(value);
}

struct Expected {
  std::string file;
  std::vector<std::string> columns;
  double interval = 0;
  long rows = -1;
  bool complete = false;  // the file must end with "# complete: ..."
};

}  // namespace

int main(int argc, char** argv) {
  Expected expected;
  CLI::App app{"Checks an output file of test2 / test8 (Test2_output.txt, Test8_output.txt): its header, its "
               "columns, N rows at the interval, and how it ends. Exit 0 when all holds, 1 otherwise.",
               "check_output_file"};
  app.add_option("file", expected.file, "the output file")->required();
  app.add_option("--columns", expected.columns, "the column names, in order: NAME,NAME,...")
      ->required()
      ->delimiter(',')
      ->allow_extra_args(false);  // one comma-separated value: FILE may follow it
  app.add_option("--interval", expected.interval, "row i is at time i x SECONDS")
      ->required()
      ->check(CLI::PositiveNumber);
  app.add_option("--rows", expected.rows, "exactly N rows")->required()->transform(checks::decimal())->check(CLI::NonNegativeNumber);
  app.add_flag("--complete", expected.complete, "the file must end with \"# complete: ...\"");
  if (auto status = checks::parse(app, argc, argv)) return *status;
  std::ifstream in(expected.file);
  if (!in) {
    std::cout << "FAIL: cannot read " << expected.file << '\n';
    return 1;
  }

  std::map<std::string, std::string> header;
  std::vector<std::string> columns;
  std::vector<std::string> failures;
  long rows = 0, comments = 0, lineNumber = 0;
  double step = NAN;
  std::string line, ending;
  while (std::getline(in, line)) {
    ++lineNumber;
    const std::string where = "line " + std::to_string(lineNumber) + ": ";
    if (!ending.empty()) failures.push_back(where + "a line after the end marker '" + ending + "'");
    if ((line.rfind("# complete: ", 0) == 0 || line.rfind("# incomplete: ", 0) == 0) && !columns.empty()) {
      ending = line;
      continue;
    }
    if (line.rfind("# t=", 0) == 0 && !columns.empty()) {
      ++comments;  // an F-key change between rows
      continue;
    }
    if (line.rfind("# ", 0) == 0) {
      if (rows > 0) failures.push_back(where + "header line after the first row: " + line);
      const auto colon = line.find(": ");
      if (colon != std::string::npos) header[line.substr(2, colon - 2)] = line.substr(colon + 2);
      if (header.count("step_seconds")) parseNumber(header["step_seconds"], step);
      continue;
    }
    if (columns.empty()) {
      columns = split(line, '\t');  // the first line that is not a comment names the columns
      continue;
    }
    const auto fields = split(line, '\t');
    if (fields.size() != columns.size()) {
      failures.push_back(where + std::to_string(fields.size()) + " fields, expected " + std::to_string(columns.size()));
      continue;
    }
    std::vector<double> values(fields.size());
    bool numeric = true;
    for (size_t i = 0; i < fields.size(); ++i) numeric = numeric && parseNumber(fields[i], values[i]);
    if (!numeric) {
      failures.push_back(where + "not all fields are finite numbers: " + line);
      continue;
    }
    const double due = rows * expected.interval;
    // Rows are written when the simulated time (a sum of steps) reaches the
    // grid point within half a step; without a step in the header nothing fits.
    if (!(std::fabs(values[0] - due) <= 0.5 * step + 1e-12))
      failures.push_back(where + "time " + fields[0] + " is not the grid point " + std::to_string(due));
    ++rows;
    if (failures.size() > 10) break;
  }

  for (const char* key : {"ode_version", "ode_precision", "step_seconds", "erp", "cfm", "solver", "iterations"})
    if (!header.count(key)) failures.push_back(std::string("header lacks '# ") + key + ": ...'");
  if (columns != expected.columns) {
    std::string got;
    for (const auto& c : columns) got += c + " ";
    failures.push_back("columns are '" + got + "'");
  }
  if (expected.complete && ending.rfind("# complete: ", 0) != 0)
    failures.push_back("the file does not end with '# complete: ...'" + (ending.empty() ? "" : ": " + ending));
  if (rows != expected.rows)
    failures.push_back(std::to_string(rows) + " rows, expected " + std::to_string(expected.rows));

  std::cout << expected.file << ": " << header.size() << " header entries, " << rows << " rows, " << comments
            << " comment lines" << (ending.empty() ? std::string() : ", ending '" + ending + "'") << '\n';
  for (const auto& failure : failures) std::cout << "FAIL: " << failure << '\n';
  if (failures.empty()) std::cout << "ok: header, columns, " << rows << " rows on the " << expected.interval << " s grid\n";
  return failures.empty() ? 0 : 1;
}
