// Progress reporting and cancellation for long computations. The CLI prints a progress line from it, the app
// drives a progress bar with a cancel button; computations poll cancelled() at coarse granularity (per row,
// per iteration).
#pragma once

#include <atomic>
#include <functional>
#include <stdexcept>
#include <string>

namespace rt {

class Progress {
 public:
  virtual ~Progress() = default;
  // fraction in [0,1]; stage is a short human-readable label ("form factors", "solve").
  virtual void report(double fraction, const std::string& stage) {}
  virtual bool cancelled() const { return false; }
};

// Thrown by computations that noticed cancelled(); callers keep their previous result.
class Cancelled : public std::runtime_error {
 public:
  Cancelled() : std::runtime_error("cancelled") {}
};

// A Progress that forwards to a callback and can be cancelled from another thread.
class CallbackProgress : public Progress {
 public:
  explicit CallbackProgress(std::function<void(double, const std::string&)> callback)
      : callback_(std::move(callback)) {}
  void report(double fraction, const std::string& stage) override {
    if (callback_) callback_(fraction, stage);
  }
  bool cancelled() const override { return cancelled_.load(); }
  void cancel() { cancelled_ = true; }

 private:
  std::function<void(double, const std::string&)> callback_;
  std::atomic<bool> cancelled_{false};
};

// Null object for callers that do not care.
inline Progress& noProgress() {
  static Progress none;
  return none;
}

}  // namespace rt
