#include "core/formfactor/formfactor_cache.h"

#include <algorithm>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace rt {

FormFactorCache::FormFactorCache(std::size_t capacity, std::string diskDirectory)
    : capacity_(std::max<std::size_t>(1, capacity)), directory_(std::move(diskDirectory)) {}

std::string FormFactorCache::key(const std::string& method, const Mesh& mesh,
                                 const FormFactorOptions& asked) {
  // Every option that can change the matrix; `threads` cannot (per-pair seeding), so it is left out, and so
  // are the options the method does not read.
  const FormFactorOptions options = makeFormFactorMethod(method)->significantOptions(asked);
  char buffer[160];
  std::snprintf(buffer, sizeof buffer, "%016llx-%zu-r%d-s%d-seed%llu-tol%.3g-%s",
                static_cast<unsigned long long>(mesh.geometryHash()), mesh.size(), options.hemicubeResolution,
                options.samples, static_cast<unsigned long long>(options.seed), options.tolerance,
                toString(options.sampling).c_str());
  return method + "-" + buffer;
}

std::shared_ptr<const CachedFormFactors> FormFactorCache::get(const std::string& method, const Mesh& mesh,
                                                              const FormFactorOptions& options,
                                                              Progress& progress, bool* hit) {
  const std::string k = key(method, mesh, options);
  {
    std::lock_guard lock(mutex_);
    for (auto it = entries_.begin(); it != entries_.end(); ++it)
      if (it->first == k) {
        entries_.splice(entries_.begin(), entries_, it);
        ++hits_;
        if (hit) *hit = true;
        return entries_.front().second;
      }
  }
  std::shared_ptr<const CachedFormFactors> value = loadFromDisk(k, mesh.size());
  const bool fromDisk = value != nullptr;
  if (!value) {
    auto computed = std::make_shared<CachedFormFactors>();
    computed->F = makeFormFactorMethod(method)->compute(mesh, options, progress, computed->stats);
    saveToDisk(k, *computed);
    value = computed;
  }
  std::lock_guard lock(mutex_);
  if (fromDisk)
    ++hits_;
  else
    ++misses_;
  if (hit) *hit = fromDisk;
  entries_.emplace_front(k, value);
  while (entries_.size() > capacity_) entries_.pop_back();
  return value;
}

bool FormFactorCache::holds(const std::string& method, const Mesh& mesh,
                            const FormFactorOptions& options) const {
  const std::string k = key(method, mesh, options);
  std::lock_guard lock(mutex_);
  return std::any_of(entries_.begin(), entries_.end(), [&k](const auto& entry) { return entry.first == k; });
}

void FormFactorCache::put(const std::string& method, const Mesh& mesh, const FormFactorOptions& options,
                          std::shared_ptr<const CachedFormFactors> value) {
  const std::string k = key(method, mesh, options);
  std::lock_guard lock(mutex_);
  entries_.remove_if([&k](const auto& entry) { return entry.first == k; });
  entries_.emplace_front(k, std::move(value));
  ++misses_;  // a computation, though not this process's
  while (entries_.size() > capacity_) entries_.pop_back();
}

void FormFactorCache::clear() {
  std::lock_guard lock(mutex_);
  entries_.clear();
}

std::shared_ptr<const CachedFormFactors> FormFactorCache::loadFromDisk(const std::string& key,
                                                                       std::size_t n) const {
  if (directory_.empty()) return nullptr;
  std::ifstream in(std::filesystem::path(directory_) / (key + ".f64"), std::ios::binary);
  if (!in) return nullptr;
  auto value = std::make_shared<CachedFormFactors>();
  value->F.resize(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(n));
  in.read(reinterpret_cast<char*>(value->F.data()), static_cast<std::streamsize>(n * n * sizeof(double)));
  if (!in) return nullptr;  // truncated: recompute
  value->stats.elements = n;
  value->stats.notes = "from the form-factor cache";
  return value;
}

void FormFactorCache::saveToDisk(const std::string& key, const CachedFormFactors& value) const {
  if (directory_.empty()) return;
  std::error_code error;
  std::filesystem::create_directories(directory_, error);
  const auto path = std::filesystem::path(directory_) / (key + ".f64");
  const auto partial = path.string() + ".partial";
  {
    std::ofstream out(partial, std::ios::binary);
    if (!out) return;  // a cache that cannot be written is only slower, never wrong
    out.write(reinterpret_cast<const char*>(value.F.data()),
              static_cast<std::streamsize>(value.F.size() * sizeof(double)));
    if (!out) return;
  }
  std::filesystem::rename(partial, path, error);
}

}  // namespace rt
