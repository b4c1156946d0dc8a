#include "core/formfactor/line_sampling.h"

#include <algorithm>
#include <boost/random/sobol.hpp>

#include "core/formfactor/sampling.h"

namespace rt {

const std::vector<std::string>& lineSamplingNames() {
  static const std::vector<std::string> names{"random", "sobol"};
  return names;
}

std::string toString(LineSampling sampling) {
  return lineSamplingNames()[static_cast<std::size_t>(sampling)];
}

std::optional<LineSampling> parseLineSampling(const std::string& name) {
  if (name == "random") return LineSampling::Random;
  if (name == "sobol") return LineSampling::Sobol;
  return std::nullopt;
}

struct ScrambledSobol::Engine {
  explicit Engine(int dimensions) : sobol(static_cast<std::size_t>(dimensions)) {}
  boost::random::sobol_engine<std::uint32_t, 32> sobol;
};

ScrambledSobol::ScrambledSobol(int dimensions, std::uint64_t seed, std::uint64_t stream)
    : dimensions_(std::clamp(dimensions, 1, kMaxDimensions)) {
  engine_ = std::make_unique<Engine>(dimensions_);
  PairRandom random(seed, stream, 0x736f626f6cull);
  for (int d = 0; d < dimensions_; ++d) shift_[d] = static_cast<std::uint32_t>(random.next() >> 32);
}

ScrambledSobol::~ScrambledSobol() = default;

// Boost's generator leaves out the sequence's first point, 0 (after seed(k) it gives point k + 1), but the
// first 2^m points are an evenly spread net only with it: point 0 is made here, the rest come from Boost.
void ScrambledSobol::start(std::uint64_t index) {
  // The generator's states are 32-bit Gray codes: the last point is 2^32 - 1.
  index_ = std::min<std::uint64_t>(index, 0xfffffffeull);
  engine_->sobol.seed(static_cast<std::uint32_t>(index_ > 0 ? index_ - 1 : 0));
}

void ScrambledSobol::next(double* point) {
  const bool origin = index_ == 0;
  for (int d = 0; d < dimensions_; ++d)
    point[d] = static_cast<double>((origin ? 0u : engine_->sobol()) ^ shift_[d]) * 0x1.0p-32;
  ++index_;
}

}  // namespace rt
