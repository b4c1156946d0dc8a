#include "typeset/typesetter.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QUrl>
#include <stdexcept>

#include "typeset/web_engine.h"

namespace rt::typeset {
namespace {

MathsReport reportFrom(const QVariant& json) {
  MathsReport report;
  const QJsonObject o = QJsonDocument::fromJson(json.toString().toUtf8()).object();
  report.formulas = o.value("formulas").toInt();
  for (const auto& e : o.value("errors").toArray()) report.errors.push_back(e.toString().toStdString());
  return report;
}

}  // namespace

std::vector<std::string> checkFormulas(const std::vector<lesson::Formula>& formulas,
                                       const std::string& file) {
  if (formulas.empty()) return {};
  SyncPage page;
  page.setHtml("<!DOCTYPE html><html><body></body></html>", QUrl::fromLocalFile(katexDirectory() + "/"));
  page.loadKatex();
  if (!page.run("typeof katex !== 'undefined'").toBool())
    return {file + ": error: KaTeX could not be loaded from " + katexDirectory().toStdString() +
            " (install libjs-katex)"};
  QJsonArray input;
  for (const auto& f : formulas)
    input.append(QJsonObject{{"tex", QString::fromStdString(f.tex)}, {"display", f.display}});
  const QString script = "JSON.stringify(" +
                         QString::fromUtf8(QJsonDocument(input).toJson(QJsonDocument::Compact)) +
                         ".map(function (f) { try { katex.renderToString(f.tex, {displayMode: f.display, "
                         "throwOnError: true}); return ''; } catch (e) { return String(e.message); } }))";
  const QJsonArray results = QJsonDocument::fromJson(page.run(script).toString().toUtf8()).array();
  std::vector<std::string> errors;
  for (std::size_t k = 0; k < formulas.size(); ++k) {
    const QString message = results.at(static_cast<qsizetype>(k)).toString();
    if (message.isEmpty()) continue;
    errors.push_back(file + ":" + std::to_string(formulas[k].line) +
                     ": error: formula does not typeset: " + message.toStdString());
  }
  return errors;
}

MathsReport typesetHtmlFile(const QString& path) {
  SyncPage page;
  if (!page.load(QUrl::fromLocalFile(path)))
    throw std::runtime_error(path.toStdString() + ": cannot load the page");
  page.loadKatex();
  const MathsReport report = reportFrom(page.run(typesetScript()));
  const QString html = "<!DOCTYPE html>\n" + page.run("document.documentElement.outerHTML").toString() + "\n";
  QFile out(path);
  if (!out.open(QIODevice::WriteOnly | QIODevice::Truncate) || out.write(html.toUtf8()) < 0)
    throw std::runtime_error(path.toStdString() + ": cannot write the page");
  return report;
}

}  // namespace rt::typeset
