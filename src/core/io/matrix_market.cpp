// Matrix Market (NIST's text format for matrices), the subset a form-factor matrix needs: real, general,
// coordinate (sparse: "i j value" lines) or array (dense, column by column). Every message names the file
// and the line.
#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <optional>
#include <sstream>
#include <vector>

#include "core/input_error.h"
#include "core/io/matrix_import.h"
#include "core/io/mtl_reader.h"
#include "core/memory_budget.h"

namespace rt {
namespace {

using io_detail::logicalLines;
using io_detail::parseNumber;
using io_detail::splitWords;

std::string lowered(std::string text) {
  for (char& c : text) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return text;
}

// A non-negative integer that is all of `word` and fits in a long long.
bool parseCount(const std::string& word, long long& value) {
  if (word.empty() || word.size() > 18 || word.find_first_not_of("0123456789") != std::string::npos)
    return false;
  value = std::stoll(word);
  return true;
}

}  // namespace

Eigen::MatrixXd parseMatrixMarket(const std::string& text, const std::string& path) {
  const auto lines = logicalLines(text);
  auto fail = [&](int line, const std::string& message) -> void {
    throw InputError({path, line, ""}, message);
  };
  if (lines.empty()) fail(0, "empty file: expected a '%%MatrixMarket matrix ...' banner");
  const std::vector<std::string> banner = splitWords(lowered(lines[0].second));
  if (banner.size() != 5 || banner[0] != "%%matrixmarket" || banner[1] != "matrix")
    fail(1, "not a Matrix Market file: expected '%%MatrixMarket matrix coordinate real general'");
  const bool coordinate = banner[2] == "coordinate";
  if (!coordinate && banner[2] != "array")
    fail(1, "unknown format '" + banner[2] + "' (coordinate or array)");
  if (banner[3] != "real" && banner[3] != "double" && banner[3] != "integer")
    fail(1, "only real matrices are supported, not '" + banner[3] + "'");
  if (banner[4] != "general") fail(1, "only general matrices are supported, not '" + banner[4] + "'");

  std::size_t at = 1;
  while (at < lines.size() &&
         (lines[at].second.empty() || lines[at].second[0] == '%' || splitWords(lines[at].second).empty()))
    ++at;
  if (at == lines.size()) fail(lines.back().first, "the size line is missing");
  const int sizeLine = lines[at].first;
  const std::vector<std::string> size = splitWords(lines[at].second);
  long long rows = 0, cols = 0, entries = 0;
  if (size.size() != (coordinate ? 3u : 2u) || !parseCount(size[0], rows) || !parseCount(size[1], cols) ||
      (coordinate && !parseCount(size[2], entries)))
    fail(sizeLine, coordinate ? "expected the size line 'rows columns entries'"
                              : "expected the size line 'rows columns'");
  // Each dimension alone must fit too: a 0 x 10^13 matrix needs no memory, but every loop over its columns
  // would run for hours.
  const double bytes = 8.0 * std::max({static_cast<double>(rows) * static_cast<double>(cols),
                                       static_cast<double>(rows), static_cast<double>(cols)});
  if (bytes > memoryBudgetBytes())
    fail(sizeLine, "a " + formatCount(static_cast<double>(rows)) + " x " +
                       formatCount(static_cast<double>(cols)) + " matrix is too large: it needs " +
                       formatBytes(bytes) + "; this machine has " + formatBytes(memoryBudgetBytes()));
  if (!coordinate) entries = rows * cols;  // bounded by the memory check above: no overflow
  // Fewer lines than announced entries: refuse before allocating for a count the file cannot hold.
  if (static_cast<double>(entries) > static_cast<double>(lines.size()))
    fail(sizeLine, "announces " + std::to_string(entries) + " entries but the file has only " +
                       std::to_string(lines.size()) + " lines");
  Eigen::MatrixXd m = Eigen::MatrixXd::Zero(rows, cols);
  long long read = 0;
  for (++at; at < lines.size(); ++at) {
    const auto& [line, raw] = lines[at];
    const std::vector<std::string> words = splitWords(raw);
    if (words.empty() || raw[0] == '%') continue;
    if (read == entries) fail(line, "more entries than the " + std::to_string(entries) + " announced");
    long long i = 0, j = 0;
    std::optional<double> value;
    if (coordinate) {
      if (words.size() != 3 || !parseCount(words[0], i) || !parseCount(words[1], j))
        fail(line, "expected an entry 'row column value'");
      if (i < 1 || i > rows || j < 1 || j > cols)
        fail(line, "entry (" + words[0] + ", " + words[1] + ") is outside the " + std::to_string(rows) +
                       " x " + std::to_string(cols) + " matrix (indices start at 1)");
      value = parseNumber(words[2]);
    } else {
      if (words.size() != 1) fail(line, "expected one value per line");
      i = read % rows + 1;
      j = read / rows + 1;
      value = parseNumber(words[0]);
    }
    if (!value) fail(line, "'" + words.back() + "' is not a number");
    if (!std::isfinite(*value)) fail(line, "value '" + words.back() + "' is not finite");
    m(i - 1, j - 1) = *value;
    ++read;
  }
  if (read != entries)
    fail(sizeLine,
         "announces " + std::to_string(entries) + " entries but the file has " + std::to_string(read));
  return m;
}

}  // namespace rt
