// The results of the steps the reader saw last, kept in memory by their settings, so that going back and
// forth between steps shows each one again at once instead of computing it again (a meshing, benchmark or
// two-pass step takes seconds). The most recently seen first; the oldest go when there are more than
// `capacity` or their matrices and meshes pass `budgetBytes`.
#pragma once

#include <QString>
#include <list>
#include <memory>
#include <utility>

#include "app/pipeline.h"

namespace rt::app {

class RecentResults {
 public:
  explicit RecentResults(std::size_t capacity = 16, double budgetBytes = 1.5e9);

  // The result kept under `key`, which becomes the most recent; null when none is.
  std::shared_ptr<const PipelineResult> find(const QString& key);
  // Keeps `result` under `key` (replacing what was kept there) and lets the oldest go past the limits.
  void keep(const QString& key, std::shared_ptr<const PipelineResult> result);
  void clear() { entries_.clear(); }
  std::size_t size() const { return entries_.size(); }

  // What a result holds that counts against the budget: its form factors, mesh and B, and the compared
  // pane's.
  static double bytesOf(const PipelineResult& result);

 private:
  using Entry = std::pair<QString, std::shared_ptr<const PipelineResult>>;
  std::list<Entry> entries_;  // most recent first
  std::size_t capacity_;
  double budgetBytes_;
};

}  // namespace rt::app
