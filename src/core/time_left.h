// "about 3 min left" from the time a long computation has taken and the fraction it has done, for the CLI's
// progress line and the app's progress strip. Linear extrapolation: rows, pairs and shots are reported as
// fractions of the work, not of the count, so the rate is roughly steady.
#pragma once

#include <string>

namespace rt {

// Empty while the estimate would be noise (under 5 s elapsed or under 1 % done) and once done; otherwise
// "about 40 s left", "about 12 min left", "about 2 h 5 min left".
std::string describeTimeLeft(double elapsedSeconds, double fraction);

}  // namespace rt
