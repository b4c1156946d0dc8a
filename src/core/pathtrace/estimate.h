// Monte Carlo estimates with their standard errors. Samples are drawn in independent batches, each
// stratified over its own samples: the batch means are independent and identically distributed, so their
// spread gives an honest standard error for the stratified estimator (the naive per-sample variance would
// overstate it, because stratification makes the error fall faster than the samples' spread says).
#pragma once

#include <cmath>

#include "core/vec.h"

namespace rt {

// Irradiance H (the power arriving per unit area, sum_j F_ij B_j) and radiosity B = E + rho H leaving a
// point, per RGB channel, in W/m^2, each with its standard error.
struct PointEstimate {
  Rgb H = Rgb::Zero();
  Rgb HError = Rgb::Zero();
  Rgb B = Rgb::Zero();
  Rgb BError = Rgb::Zero();
  // The two-pass method's estimate of the error its radiosity solution's mesh brings in (a bound, not a
  // standard error: see meshErrorEstimate in cli/solution.h); zero for the path tracer, which has no mesh.
  Rgb HMeshError = Rgb::Zero();
  Rgb BMeshError = Rgb::Zero();
  // H by the bounces its light took since leaving an emitter: none (the direct light) and one (the light the
  // first surfaces reflect); the rest is H less both. The path tracer counts a path's bounces; the two-pass
  // method's first bounce is the direct light taken at its gather hits, and its rest what the solution adds.
  // A breakdown against a path-traced reference tells which part an error comes from.
  Rgb HDirect = Rgb::Zero();
  Rgb HDirectError = Rgb::Zero();
  Rgb HBounce = Rgb::Zero();
  Rgb HBounceError = Rgb::Zero();
  int element = -1;  // the surface the point lies on (-1: none, and B is 0)
};

// The error a point query reports beside H: two standard errors (a two-sided 95 % interval for its noise)
// plus the estimated bound on its mesh's error, per channel.
inline Rgb errorEstimate(const PointEstimate& e) {
  return 2.0 * e.HError + e.HMeshError;
}

// Mean and standard error of the mean of independent RGB values (Welford's update: no cancellation).
class RgbMean {
 public:
  void add(const Rgb& x) {
    ++count_;
    const Rgb delta = x - mean_;
    mean_ += delta / static_cast<double>(count_);
    squares_ += delta * (x - mean_);
  }
  int count() const { return count_; }
  Rgb mean() const { return mean_; }
  // Zero for fewer than two values (no spread to measure).
  Rgb standardError() const {
    if (count_ < 2) return Rgb::Zero();
    return (squares_ / (static_cast<double>(count_) * (count_ - 1))).sqrt();
  }

 private:
  int count_ = 0;
  Rgb mean_ = Rgb::Zero();
  Rgb squares_ = Rgb::Zero();
};

}  // namespace rt
