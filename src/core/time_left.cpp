#include "core/time_left.h"

#include <algorithm>
#include <cmath>

namespace rt {

std::string describeTimeLeft(double elapsedSeconds, double fraction) {
  if (!(elapsedSeconds >= 5) || !(fraction >= 0.01) || fraction >= 1) return {};
  const double left = elapsedSeconds * (1 - fraction) / fraction;
  if (left < 90) {
    const long seconds = std::max(5L, std::lround(left / 5) * 5);  // a countdown in 5 s steps
    return "about " + std::to_string(seconds) + " s left";
  }
  const long minutes = std::lround(left / 60);
  if (minutes < 90) return "about " + std::to_string(minutes) + " min left";
  return "about " + std::to_string(minutes / 60) + " h " + std::to_string(minutes % 60) + " min left";
}

}  // namespace rt
