// Form factors depend on geometry only: one matrix serves all three colour channels and survives every
// material change. The cache keys a computed matrix by (mesh.geometryHash(), method name, the options that
// change the result); a material-only edit therefore never recomputes F. In memory (least recently used first
// out), optionally mirrored on disk as raw little-endian doubles under a cache folder.
#pragma once

#include <cstdint>
#include <list>
#include <memory>
#include <mutex>
#include <string>

#include "core/formfactor/formfactor_method.h"

namespace rt {

struct CachedFormFactors {
  FormFactorMatrix F;
  FormFactorStats stats;  // of the run that computed it
};

class FormFactorCache {
 public:
  // capacity: matrices kept in memory. diskDirectory: empty = memory only.
  explicit FormFactorCache(std::size_t capacity = 4, std::string diskDirectory = {});

  // The matrix of `method` for this mesh and options: from memory, then disk, else computed (and stored).
  // `hit` (optional) tells whether it was reused. Throws what the method throws (Cancelled included).
  std::shared_ptr<const CachedFormFactors> get(const std::string& method, const Mesh& mesh,
                                               const FormFactorOptions& options,
                                               Progress& progress = noProgress(), bool* hit = nullptr);
  static std::string key(const std::string& method, const Mesh& mesh, const FormFactorOptions& options);
  // True when get() would answer from memory without computing.
  bool holds(const std::string& method, const Mesh& mesh, const FormFactorOptions& options) const;
  // Keeps a matrix computed elsewhere (rows spread over processes: FormFactorMethod::fromRows) as get()
  // keeps its own, so that the next get() for this mesh and options answers with it.
  void put(const std::string& method, const Mesh& mesh, const FormFactorOptions& options,
           std::shared_ptr<const CachedFormFactors> value);

  std::size_t hits() const { return hits_; }
  std::size_t misses() const { return misses_; }
  void clear();

 private:
  std::shared_ptr<const CachedFormFactors> loadFromDisk(const std::string& key, std::size_t n) const;
  void saveToDisk(const std::string& key, const CachedFormFactors& value) const;

  std::size_t capacity_;
  std::string directory_;
  mutable std::mutex mutex_;
  std::list<std::pair<std::string, std::shared_ptr<const CachedFormFactors>>> entries_;  // most recent first
  std::size_t hits_ = 0, misses_ = 0;
};

}  // namespace rt
