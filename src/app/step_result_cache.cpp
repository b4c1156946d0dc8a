#include "app/step_result_cache.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QStandardPaths>

namespace rt::app {
namespace {

// The parameters as one canonical text: the map's keys are sorted, so equal maps give equal texts.
QString parameterText(const QVariantMap& parameters) {
  return QString::fromUtf8(
      QJsonDocument(QJsonObject::fromVariantMap(parameters)).toJson(QJsonDocument::Compact));
}

QJsonArray arrayOf(const QStringList& list) {
  QJsonArray out;
  for (const QString& s : list) out.append(s);
  return out;
}

QStringList listOf(const QJsonValue& value) {
  QStringList out;
  for (const QJsonValue& v : value.toArray()) out.push_back(v.toString());
  return out;
}

}  // namespace

StepResultCache::StepResultCache(QString folder) : folder_(std::move(folder)) {
  if (folder_.isEmpty())
    folder_ = QDir(QStandardPaths::writableLocation(QStandardPaths::CacheLocation)).filePath("steps");
}

QString StepResultCache::stepFolder(const QString& lesson, int step) const {
  return QDir(folder_).filePath(lesson + "/" + QString::number(step));
}

bool StepResultCache::store(const QString& lesson, int step, const QVariantMap& parameters,
                            const CachedStepResult& result) {
  const QString dir = stepFolder(lesson, step);
  QDir(dir).removeRecursively();  // one result per step: the figures of another parameter set go
  if (!QDir().mkpath(dir)) return false;
  QStringList kept;
  for (qsizetype k = 0; k < result.figures.size(); ++k) {
    const QString name = QString("figure-%1.%2").arg(k).arg(QFileInfo(result.figures[k]).suffix());
    if (!QFile::copy(result.figures[k], QDir(dir).filePath(name))) return false;
    kept.push_back(name);
  }
  QJsonObject meta;
  meta["parameters"] = parameterText(parameters);
  meta["markdown"] = result.markdown;
  meta["figures"] = arrayOf(kept);
  meta["captions"] = arrayOf(result.captions);
  meta["computed"] = result.computed.toString(Qt::ISODate);
  QFile file(QDir(dir).filePath("result.json"));
  if (!file.open(QIODevice::WriteOnly | QIODevice::Truncate)) return false;
  return file.write(QJsonDocument(meta).toJson()) > 0;
}

std::optional<CachedStepResult> StepResultCache::load(const QString& lesson, int step,
                                                      const QVariantMap& parameters) const {
  const QString dir = stepFolder(lesson, step);
  QFile file(QDir(dir).filePath("result.json"));
  if (!file.open(QIODevice::ReadOnly)) return std::nullopt;
  const QJsonObject meta = QJsonDocument::fromJson(file.readAll()).object();
  if (meta["parameters"].toString() != parameterText(parameters)) return std::nullopt;
  CachedStepResult out;
  out.markdown = meta["markdown"].toString();
  out.captions = listOf(meta["captions"]);
  out.computed = QDateTime::fromString(meta["computed"].toString(), Qt::ISODate);
  for (const QString& name : listOf(meta["figures"])) {
    const QString path = QDir(dir).filePath(name);
    if (!QFileInfo::exists(path)) return std::nullopt;  // a damaged cache is no cache
    out.figures.push_back(path);
  }
  return out;
}

}  // namespace rt::app
