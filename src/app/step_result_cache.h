// What a long lesson step (a benchmark, or anything that took more than a few seconds) showed the last time
// it ran: its text with the numbers filled in and its figures. A restored session shows it at once, marked
// with the date, instead of recomputing for a minute before the reader asks. Kept on disk per step and per
// set of parameters, in the user's cache folder.
#pragma once

#include <QDateTime>
#include <QString>
#include <QStringList>
#include <QVariantMap>
#include <optional>

namespace rt::app {

struct CachedStepResult {
  QString markdown;  // the step's text as it was shown, numbers filled in
  QStringList figures, captions;
  QDateTime computed;
};

class StepResultCache {
 public:
  // `folder` empty: the user's cache location (QStandardPaths::CacheLocation)/"steps".
  explicit StepResultCache(QString folder = {});

  // Keeps the text and copies of the figure files; replaces what was kept for this step before. Returns
  // false when the folder cannot be written (the cache is a convenience: nothing else depends on it).
  bool store(const QString& lesson, int step, const QVariantMap& parameters, const CachedStepResult& result);
  // What was kept for this step with exactly these parameters, if anything.
  std::optional<CachedStepResult> load(const QString& lesson, int step, const QVariantMap& parameters) const;

  const QString& folder() const { return folder_; }

 private:
  QString stepFolder(const QString& lesson, int step) const;
  QString folder_;
};

}  // namespace rt::app
