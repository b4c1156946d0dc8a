#include "viz/timing_table.h"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <sstream>

#include "core/input_error.h"

namespace rt::viz {
namespace {

std::vector<std::string> splitFields(const std::string& line) {
  std::vector<std::string> fields;
  std::stringstream stream(line);
  std::string field;
  while (std::getline(stream, field, ',')) {
    field.erase(0, field.find_first_not_of(" \t"));
    field.erase(field.find_last_not_of(" \t\r") + 1);
    fields.push_back(field);
  }
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

double number(const std::string& text, const SourceLocation& where, const std::string& column) {
  char* end = nullptr;
  const double value = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size())
    throw InputError(where, "column '" + column + "': '" + text + "' is not a number");
  return value;
}

}  // namespace

TimingTable readTimingTable(const std::string& path) {
  std::ifstream file(path);
  if (!file) throw InputError({path}, "cannot read the timing table");
  std::string line;
  int lineNumber = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(file, line)) {
    ++lineNumber;
    if (line.find_first_not_of(" \t\r") != std::string::npos) header = splitFields(line);
  }
  if (header.empty()) throw InputError({path, lineNumber}, "the timing table is empty");
  auto column = [&](const std::string& name) {
    return static_cast<int>(std::find(header.begin(), header.end(), name) - header.begin());
  };
  const int seconds = column("seconds");
  if (seconds >= static_cast<int>(header.size()))
    throw InputError({path, lineNumber}, "the header has no 'seconds' column");
  TimingTable table;
  int error = static_cast<int>(header.size());
  for (const char* name : {"rms_error", "relative_error", "error", "residual"})
    if (column(name) < static_cast<int>(header.size())) {
      error = column(name);
      table.errorColumn = name;
      break;
    }
  if (table.errorColumn.empty())
    throw InputError({path, lineNumber},
                     "the header has none of the error columns rms_error, relative_error, error, residual");

  while (std::getline(file, line)) {
    ++lineNumber;
    if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
    const std::vector<std::string> fields = splitFields(line);
    const SourceLocation where{path, lineNumber};
    if (fields.size() != header.size())
      throw InputError(
          where, std::to_string(fields.size()) + " fields, the header has " + std::to_string(header.size()));
    // Rows of one series may be interleaved with others': look the series up by name.
    auto series = std::find_if(table.series.begin(), table.series.end(),
                               [&](const Series& s) { return s.name == fields[0]; });
    if (series == table.series.end())
      series = table.series.insert(table.series.end(), Series{fields[0], {}, {}});
    series->x.push_back(number(fields[seconds], where, "seconds"));
    series->y.push_back(number(fields[error], where, table.errorColumn));
  }
  if (table.series.empty()) throw InputError({path, lineNumber}, "the timing table has no rows");
  return table;
}

}  // namespace rt::viz
