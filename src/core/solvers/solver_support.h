// Pieces shared by the solver implementations: input checks, the per-iteration record of gathering methods, a
// clock, a portable random generator, and the Solver class that wraps a free algorithm function.
#pragma once

#include <chrono>
#include <cstdint>
#include <random>
#include <string>

#include "core/check.h"
#include "core/solvers/solver.h"

namespace rt::solver_detail {

// InvalidInput unless sizes agree, rho is in [0,1], E >= 0, areas > 0 and everything is finite.
// needMatrix: the method walks system.F (every method except shooting with a row provider).
SolverStatus validate(const RadiositySystem& system, bool needMatrix);

// The record of an iteration for methods that keep no unshot radiosity (exact residual and power balance
// of B), at the cost of the product F B the residual needs (a Jacobi sweep reuses it): what the absorbed and
// escaped power weigh B by does not change with B, so it is computed once per solve, in one pass over F.
// Each record otherwise took four passes over F (the residual, the incident irradiance F^T A B, the row
// sums, the sweep), and F of 5,000 elements is 200 MB.
class GatherRecorder {
 public:
  explicit GatherRecorder(const RadiositySystem& system);
  // The record of B after `iteration`, FB = F B.
  IterationRecord operator()(const RgbField& B, const RgbField& FB, int iteration, double seconds) const;

 private:
  const RadiositySystem& system_;
  // Per element and channel, A_i sum_j F_ij (1 - rho_j): the absorbed power is sum_i B_i of it (energy.h's
  // sum over j of (1 - rho_j) A_j H_j, with A_j H_j = sum_i B_i A_i F_ij).
  RgbField absorbing_;
  Eigen::VectorXd escaping_;  // A_i (1 - sum_j F_ij)
  double emitted_ = 0;
};

// Sum over channels of E_i A_i.
double totalEmittedPower(const RadiositySystem& system);

// sqrt(sum_i A_i |error_i|^2 / sum_i A_i |B_i|^2) (|.| over the channels; the absolute area-weighted RMS when
// B is zero): how every solver's estimated error is reported, and the measure the benchmarks apply to the
// actual error (scenes/tools/radiosity_error.py). Unweighted, each element would count the same whatever its
// size, and on an unevenly meshed scene the many small, noisy elements would stand in for the few large ones
// that hold most of the area: on the museum that reported two thirds of the error measured by area.
double relativeAreaRms(const RgbField& error, const RgbField& B, const Eigen::VectorXd& areas);

// True when element i reflects nothing in any channel: it gathers nothing and never needs updating.
inline bool isBlack(const RadiositySystem& system, Eigen::Index i) {
  return (system.reflectance.row(i).array() == 0.0).all();
}

class Stopwatch {
 public:
  Stopwatch() : start_(std::chrono::steady_clock::now()) {}
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start_).count();
  }

 private:
  std::chrono::steady_clock::time_point start_;
};

// mt19937_64 is specified bit for bit by the standard; the conversion to [0,1) is ours, so a seed gives the
// same numbers with every standard library (std::uniform_real_distribution does not promise that).
class Random {
 public:
  explicit Random(std::uint64_t seed) : engine_(seed) {}
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

 private:
  std::mt19937_64 engine_;
};

// Index k with cumulative[k-1] <= u * total < cumulative[k] (cumulative is an inclusive running sum).
// Returns cumulative.size() when u * total lies beyond the last entry (used for "escaped" in sub-stochastic
// rows).
std::size_t sampleCumulative(const std::vector<double>& cumulative, double target);

using Algorithm = SolverStatus (*)(const RadiositySystem&, RgbField&, const SolverOptions&,
                                   const IterationSink&);

// Runs an algorithm function: keeps the iteration count and final error, forwards records to record()
// (history, observer, cancellation), reports progress.
class AlgorithmSolver : public Solver {
 public:
  AlgorithmSolver(std::string name, Algorithm algorithm) : name_(std::move(name)), algorithm_(algorithm) {}
  std::string name() const override { return name_; }
  RgbField solve() override;

 protected:
  // Runs `body` (which calls the algorithm) with the bookkeeping shared by every solver.
  template <typename Body>
  RgbField run(Body&& body);
  void onRecord(IterationRecord r);

 private:
  std::string name_;
  Algorithm algorithm_;
};

template <typename Body>
RgbField AlgorithmSolver::run(Body&& body) {
  history_.clear();
  standardError_.resize(0, 3);
  iterations_ = 0;
  error_ = 0;
  RgbField B;
  if (!system_) {
    status_ = SolverStatus::InvalidInput;
    return B;
  }
  try {
    status_ = body(B);
  } catch (const Cancelled&) {
    status_ = SolverStatus::Cancelled;
    throw;
  }
  // A solver that has not reported a numerical issue returns a finite B (rho < 1 and row sums <= 1 make the
  // system's iteration a contraction).
  RT_CHECK((status_ != SolverStatus::Success && status_ != SolverStatus::NoConvergence) || B.allFinite(),
           name_ + ": B is not finite after a solve that reported " + toString(status_));
  return B;
}

}  // namespace rt::solver_detail
