// radiosity lesson list | check | render: the lessons in lessons/ without the app.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "cli/lesson_rendering.h"
#include "core/input_error.h"
#include "lesson/book.h"
#include "lesson/exercise_topics.h"
#include "lesson/lesson_loader.h"
#include "lesson/step_keys.h"
#include "lesson/step_numbers.h"
#include "lesson/step_runner.h"
#ifdef RT_HAVE_TYPESET
#include "typeset/web_engine.h"
#endif

namespace rt::cli {
namespace {

void list(const LessonArguments& a) {
  for (const auto& l : lesson::loadCatalogue(a.folders()))
    std::cout << l.order << "\t" << l.id << "\t" << l.title << " (" << l.steps.size() << " steps)\n";
}

// Checks every named lesson and reports all problems (not just the first) before failing.
void check(const LessonArguments& a, bool run) {
  const auto folders = a.folders();
  std::vector<std::string> files;
  if (a.all) {
    files = lesson::lessonFiles(folders.lessons);
  } else {
    files = a.files();
  }
  int failures = 0;
  lesson::RunOptions options;
  options.quick = true;
  lesson::StepRunner runner(folders.scenes, options);
#ifdef RT_HAVE_TYPESET
  const typeset::WebSession session;  // KaTeX checks the formulas
#endif
  for (const auto& file : files) {
    try {
      const lesson::Lesson l = lesson::loadLesson(file, folders.scenes);
      lesson::checkAgainstScenes(l, folders.scenes);
      auto problems = lessonTextProblems(l);
      for (auto& p : lesson::exerciseTopicProblems(l)) problems.push_back(std::move(p));
      if (!problems.empty()) {
        for (const auto& problem : problems) std::cerr << problem << "\n";
        throw InputError({l.file, 0}, std::to_string(problems.size()) + " problem(s) in its text");
      }
      if (run) {
        for (const auto& step : l.steps) {
          try {
            const lesson::StepResult result = runner.run(l, step);
            lesson::resolvedText(l, step, result);
            lesson::resolvedCaption(l, step, result);
          } catch (const lesson::MethodUnavailable& e) {
            std::cerr << e.what() << " (not run)\n";  // an optional library, not a mistake in the lesson
          }
        }
      }
      std::cout << "ok      " << l.id << " (" << l.steps.size() << " steps)\n";
    } catch (const std::exception& e) {
      ++failures;
      std::cerr << e.what() << "\n";
    }
  }
  // Errors in lesson files are input errors (exit code 3), as a broken scene is.
  if (failures > 0) throw InputError({}, std::to_string(failures) + " lesson(s) have errors (listed above)");
}

}  // namespace

void addLessonCommand(CLI::App& app) {
  auto* command =
      app.add_subcommand("lesson", "List, check and render the lessons (figures and a Markdown book)");
  command->require_subcommand(1);

  auto listArgs = std::make_shared<LessonArguments>();
  auto* listCommand = command->add_subcommand("list", "The lessons in book order: order, id, title");
  listCommand->add_option("--root", listArgs->root, "Folder holding lessons/ and scenes/");
  listCommand->callback([listArgs] { list(*listArgs); });

  auto* keysCommand = command->add_subcommand(
      "keys",
      "The table of step keys (type, range, default, control, stages) as Markdown, as the docs show it");
  keysCommand->callback([] { std::cout << lesson::stepKeyTableMarkdown(); });
  auto* stagesCommand = command->add_subcommand(
      "stages",
      "The table of stages (what each computes, the views it can show) as Markdown, as the docs show it");
  stagesCommand->callback([] { std::cout << lesson::stageTableMarkdown(); });

  auto checkArgs = std::make_shared<LessonArguments>();
  auto run = std::make_shared<bool>(false);
  auto* checkCommand = command->add_subcommand("check", "Validate lessons: format, scenes, surface names");
  checkArgs->add(checkCommand);
  checkCommand->add_flag("--run", *run,
                         "Also run every step (quick parameters) and resolve its placeholders");
  checkCommand->callback([checkArgs, run] { check(*checkArgs, *run); });

  auto renderArgs = std::make_shared<LessonArguments>();
  auto output = std::make_shared<std::string>();
  auto quick = std::make_shared<bool>(false);
  auto figures = std::make_shared<RenderSettings>();
  auto* renderCommand = command->add_subcommand(
      "render",
      "Run every step, write its figures (DIR/<lesson>/<figure>.png) and the book (DIR/<lesson>.md, "
      "DIR/index.md)");
  renderArgs->add(renderCommand);
  renderCommand->add_option("--output,-o", *output, "Output folder")->required();
  renderCommand->add_flag("--quick", *quick, "Small meshes, resolutions and images (for tests)");
  renderCommand->add_option("--width", figures->width, "Figure width in pixels")->check(CLI::Range(64, 8192));
  renderCommand->add_option("--height", figures->height, "Figure height in pixels")
      ->check(CLI::Range(64, 8192));
  renderCommand->callback([=] {
    RenderSettings settings = *figures;
    settings.quick = *quick;
    settings.prepareText = true;  // numbered equations and listings, linked references in the Markdown too
    if (*quick) {
      settings.width = std::min(settings.width, 320);
      settings.height = std::min(settings.height, 240);
    }
    const auto rendered = renderLessons(renderArgs->files(), renderArgs->folders(), *output, settings);
    for (std::size_t i = 0; i < rendered.size(); ++i) {
      const auto* previous = i > 0 ? &rendered[i - 1] : nullptr;
      const auto* next = i + 1 < rendered.size() ? &rendered[i + 1] : nullptr;
      std::cout << lesson::writeLessonPage(rendered[i], *output, previous, next) << "\n";
    }
    std::cout << lesson::writeBookIndex(rendered, *output) << "\n";
  });
}

}  // namespace rt::cli
