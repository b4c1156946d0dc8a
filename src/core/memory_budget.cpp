#include "core/memory_budget.h"

#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>

namespace rt {

double memoryBudgetBytes() {
  const long pages = sysconf(_SC_PHYS_PAGES), pageSize = sysconf(_SC_PAGE_SIZE);
  double bytes = pages > 0 && pageSize > 0 ? static_cast<double>(pages) * static_cast<double>(pageSize) : 8e9;
  if (const char* limit = std::getenv("RT_MEMORY_LIMIT_MB")) {
    const double mb = std::strtod(limit, nullptr);
    if (mb > 0) bytes = std::min(bytes, mb * 1024.0 * 1024.0);
  }
  return bytes;
}

std::string formatBytes(double bytes) {
  const char* units[] = {"bytes", "KB", "MB", "GB", "TB", "PB", "EB"};
  int unit = 0;
  while (bytes >= 1024.0 && unit < 6) {
    bytes /= 1024.0;
    ++unit;
  }
  std::ostringstream out;
  out.precision(bytes < 10 && unit > 0 ? 2 : 3);
  out << bytes << " " << units[unit];
  return out.str();
}

std::string formatCount(double count) {
  if (!std::isfinite(count) || count >= 1e15) {
    std::ostringstream out;
    out.precision(3);
    out << count;
    return out.str();
  }
  std::string digits = std::to_string(static_cast<long long>(std::llround(count)));
  for (int at = static_cast<int>(digits.size()) - 3; at > 0; at -= 3) digits.insert(at, ",");
  return digits;
}

}  // namespace rt
