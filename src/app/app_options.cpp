#include "app/app_options.h"

#include <QCommandLineParser>
#include <QRegularExpression>

namespace rt::app {

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
  parser.addOptions({lesson, step, scene, screenshot, size, presenter, compare});
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
  options.compare = parser.isSet(compare);
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

}  // namespace rt::app
