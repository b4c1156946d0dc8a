#include "app/app_options.h"

#include <QCommandLineParser>
#include <QRegularExpression>

#include "app/compare_choice.h"

namespace rt::app {
namespace {

QStringList meshChoices() {
  QStringList out;
  for (const std::string& choice : compareMeshChoices()) out << QString::fromStdString(choice);
  return out;
}

}  // namespace

AppOptions parseAppOptions(const QStringList& arguments, QString* error) {
  QCommandLineParser parser;
  parser.setApplicationDescription("An interactive, step-by-step visual textbook of the radiosity method.");
  parser.addHelpOption();
  parser.addVersionOption();
  const QCommandLineOption lesson("lesson", "Open the lesson with this id (the file name in lessons/).",
                                  "id");
  const QCommandLineOption step("step", "Open this step of the lesson (1-based).", "n");
  const QCommandLineOption scene("scene", "Open a scene file (.json or .obj) and solve it.", "file");
  const QCommandLineOption screenshot("screenshot", "Render the window into this PNG and exit.", "file");
  const QCommandLineOption size("size", "Window size for --screenshot (default 1600x1000).", "WxH");
  const QCommandLineOption presenter("presenter", "Start in presenter mode (full screen, large fonts).");
  const QCommandLineOption compare("compare", "Start in compare mode (two synchronised views).");
  const QCommandLineOption compareSolver("compare-solver", "Compare mode, the right pane with this solver.",
                                         "name");
  const QCommandLineOption compareMethod(
      "compare-method", "Compare mode, the right pane with this form-factor method.", "name");
  const QCommandLineOption compareMesh(
      "compare-mesh", "Compare mode, the right pane with this mesh: " + meshChoices().join(", ") + ".",
      "name");
  parser.addOptions(
      {lesson, step, scene, screenshot, size, presenter, compare, compareSolver, compareMethod, compareMesh});
  if (!parser.parse(arguments)) {
    *error = parser.errorText();
    return {};
  }
  if (parser.isSet("help")) parser.showHelp(0);
  if (parser.isSet("version")) parser.showVersion();
  if (!parser.positionalArguments().isEmpty()) {
    *error = "unexpected argument '" + parser.positionalArguments().first() + "'";
    return {};
  }

  AppOptions options;
  options.lesson = parser.value(lesson);
  options.scene = parser.value(scene);
  options.screenshot = parser.value(screenshot);
  options.presenter = parser.isSet(presenter);
  options.compareSolver = parser.value(compareSolver);
  options.compareMethod = parser.value(compareMethod);
  options.compareMesh = parser.value(compareMesh);
  options.compare = parser.isSet(compare) || parser.isSet(compareSolver) || parser.isSet(compareMethod) ||
                    parser.isSet(compareMesh);
  if (parser.isSet(compareMesh) && !meshChoices().contains(options.compareMesh)) {
    *error =
        "--compare-mesh must be one of " + meshChoices().join(", ") + ", not '" + options.compareMesh + "'";
    return {};
  }
  if (parser.isSet(step)) {
    bool ok = false;
    options.step = parser.value(step).toInt(&ok);
    if (!ok || options.step < 1) {
      *error = "--step needs a positive step number, not '" + parser.value(step) + "'";
      return {};
    }
  }
  if (parser.isSet(size)) {
    static const QRegularExpression pattern("^(\\d+)x(\\d+)$");
    const auto match = pattern.match(parser.value(size));
    const int w = match.hasMatch() ? match.captured(1).toInt() : 0;
    const int h = match.hasMatch() ? match.captured(2).toInt() : 0;
    if (w < 320 || h < 240 || w > 8192 || h > 8192) {
      *error = "--size must be WxH between 320x240 and 8192x8192, not '" + parser.value(size) + "'";
      return {};
    }
    options.size = QSize(w, h);
  }
  if (!options.scene.isEmpty() && !options.lesson.isEmpty()) {
    *error = "--scene and --lesson cannot be combined";
    return {};
  }
  if (!options.screenshot.isEmpty() && !options.screenshot.endsWith(".png", Qt::CaseInsensitive)) {
    *error = "--screenshot writes PNG: the file name must end in .png";
    return {};
  }
  return options;
}

bool asksForHelpOrVersion(int argc, const char* const* argv) {
  for (int k = 1; k < argc; ++k) {
    const QString argument = QString::fromLocal8Bit(argv[k]);
    if (argument == "--") break;
    for (const char* option : {"-h", "--help", "-?", "--help-all", "-v", "--version"})
      if (argument == QLatin1String(option)) return true;
  }
  return false;
}

}  // namespace rt::app
