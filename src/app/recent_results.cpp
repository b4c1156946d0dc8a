#include "app/recent_results.h"

#include <algorithm>

namespace rt::app {

RecentResults::RecentResults(std::size_t capacity, double budgetBytes)
    : capacity_(std::max<std::size_t>(1, capacity)), budgetBytes_(budgetBytes) {}

std::shared_ptr<const PipelineResult> RecentResults::find(const QString& key) {
  const auto it =
      std::find_if(entries_.begin(), entries_.end(), [&](const Entry& e) { return e.first == key; });
  if (it == entries_.end()) return nullptr;
  entries_.splice(entries_.begin(), entries_, it);
  return entries_.front().second;
}

void RecentResults::keep(const QString& key, std::shared_ptr<const PipelineResult> result) {
  if (!result) return;
  entries_.remove_if([&](const Entry& e) { return e.first == key; });
  entries_.emplace_front(key, std::move(result));
  double bytes = 0;
  std::size_t kept = 0;
  for (auto it = entries_.begin(); it != entries_.end(); ++it) {
    bytes += bytesOf(*it->second);
    // The newest always stays, whatever its size: it is on screen.
    if (kept > 0 && (kept >= capacity_ || bytes > budgetBytes_)) {
      entries_.erase(it, entries_.end());
      return;
    }
    ++kept;
  }
}

double RecentResults::bytesOf(const PipelineResult& r) {
  double bytes = 0;
  if (r.F) bytes += 8.0 * static_cast<double>(r.F->size());
  // A mesh keeps about 200 bytes an element (vertices, indices, normals, materials, adjacency).
  if (r.mesh) bytes += 200.0 * static_cast<double>(r.mesh->size());
  bytes += 8.0 * static_cast<double>(r.B.size()) * static_cast<double>(r.history.size() + 1);
  if (r.compared && r.compared.get() != &r && r.compared->F != r.F) bytes += bytesOf(*r.compared);
  return bytes;
}

}  // namespace rt::app
