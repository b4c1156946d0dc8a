// radiosity lesson list | check | render: the lessons in lessons/ without the app.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <memory>

#include "cli/cli_common.h"
#include "cli/commands.h"
#include "core/input_error.h"
#include "homework/handout.h"
#include "lesson/book.h"
#include "lesson/lesson_loader.h"
#include "lesson/step_keys.h"
#include "lesson/step_numbers.h"
#include "lesson/step_runner.h"
#ifdef RT_HAVE_VIZ
#include "viz/lesson_figures.h"
#endif

namespace rt::cli {
namespace {

struct FigureSettings {
  int width = 900;
  int height = 700;
};

struct LessonArguments {
  std::vector<std::string> ids;
  bool all = false;
  std::string root;  // repository root holding lessons/ and scenes/; empty = the default
  lesson::LessonFolders folders() const {
    return root.empty() ? lesson::defaultFolders() : lesson::foldersUnder(root);
  }
  void add(CLI::App* command) {
    command->add_option("lessons", ids, "Lesson ids (file names in lessons/ without .md)");
    command->add_flag("--all", all, "Every lesson in lessons/");
    command->add_option("--root", root, "Folder holding lessons/ and scenes/ (default: the current folder)");
  }
  // The lesson files to work on, in book order.
  std::vector<std::string> files() const {
    const auto f = folders();
    if (all == !ids.empty()) throw CLI::ValidationError("name lessons or give --all (not both)");
    std::vector<std::string> out;
    if (all) {
      for (const auto& l : lesson::loadCatalogue(f)) out.push_back(l.file);
    } else {
      for (const auto& id : ids) out.push_back(lesson::lessonPath(f, id));
    }
    return out;
  }
};

lesson::RenderedLesson renderedHeader(const lesson::Lesson& l) {
  lesson::RenderedLesson r;
  r.id = l.id;
  r.title = l.title;
  r.chapter = l.chapter;
  r.summary = l.summary;
  r.order = l.order;
  r.intro = l.intro;
  return r;
}

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
  for (const auto& file : files) {
    try {
      const lesson::Lesson l = lesson::loadLesson(file, folders.scenes);
      lesson::checkAgainstScenes(l, folders.scenes);
      if (run) {
        for (const auto& step : l.steps) {
          try {
            lesson::resolvedText(l, step, runner.run(l, step));
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

void render(const LessonArguments& a, const std::string& output, bool quick, const FigureSettings& figures) {
  if (output.empty()) throw CLI::ValidationError("--output", "an output folder is required");
  const auto folders = a.folders();
#ifndef RT_HAVE_VIZ
  std::cerr << "radiosity: this build has no viz library: writing the text without figures\n";
#endif
  lesson::RunOptions options;
  options.quick = quick;
  std::vector<lesson::RenderedLesson> rendered;
  std::vector<homework::AppendixEntry> appendix;  // the exercises, answered at the back of the book
  ProgressLine progress(true);
  std::filesystem::create_directories(output);
  std::ofstream skipped(std::filesystem::path(output) / "skipped.txt");  // figures this build could not draw
  for (const auto& file : a.files()) {
    const lesson::Lesson l = lesson::loadLesson(file, folders.scenes);
    options.outputDir = (std::filesystem::path(output) / l.id).string();
    lesson::StepRunner runner(folders.scenes, options);
    lesson::RenderedLesson page = renderedHeader(l);
    // The numbers behind every step, for checking against the app and for answer keys.
    std::filesystem::create_directories(options.outputDir);
    std::ofstream numbers(std::filesystem::path(options.outputDir) / "numbers.json");
    numbers << "[\n";
    bool firstNumbers = true;
    for (const auto& step : l.steps) {
      progress.report(static_cast<double>(step.index) / static_cast<double>(l.steps.size()), l.id);
      lesson::StepResult result;
      try {
        result = runner.run(l, step, progress);
      } catch (const lesson::MethodUnavailable& e) {
        // Built without an optional library: say so on the page and in skipped.txt, keep going.
        std::cerr << "radiosity: " << e.what() << " (step skipped)\n";
        page.steps.push_back({step.title, "*" + e.message() + ": this step was not computed.*\n", {}});
        for (const auto& f : step.figureFiles()) skipped << l.id << "/" << f << "\n";
        continue;
      }
      numbers << (firstNumbers ? "" : ",\n") << "{\"step\": " << step.index
              << ", \"numbers\": " << lesson::stepNumbersJson(result) << "}";
      firstNumbers = false;
      lesson::RenderedStep s{step.title, lesson::resolvedText(l, step, result), {}};
      if (result.exercise) {
        s.text += homework::exerciseBookText(*result.exercise);
        appendix.push_back({std::to_string(l.order) + "." + std::to_string(step.index + 1) + " " + step.title,
                            *result.exercise});
      }
      try {
#ifdef RT_HAVE_VIZ
        s.figures =
            viz::renderStepFigures(l, step, result, options.outputDir, {figures.width, figures.height});
#else
        (void)figures;
#endif
      } catch (const std::exception& e) {
        throw InputError({l.file, step.line}, "step '" + step.title + "': " + e.what());
      }
      page.steps.push_back(std::move(s));
    }
    numbers << "\n]\n";
    rendered.push_back(std::move(page));
  }
  progress.finish();
  std::stable_sort(rendered.begin(), rendered.end(),
                   [](const auto& x, const auto& y) { return x.order < y.order; });
  for (std::size_t i = 0; i < rendered.size(); ++i) {
    const auto* previous = i > 0 ? &rendered[i - 1] : nullptr;
    const auto* next = i + 1 < rendered.size() ? &rendered[i + 1] : nullptr;
    std::cout << lesson::writeLessonPage(rendered[i], output, previous, next) << "\n";
  }
  std::cout << lesson::writeBookIndex(rendered, output) << "\n";
  if (!appendix.empty()) {
    const std::string path = (std::filesystem::path(output) / "exercise-answers.md").string();
    std::ofstream(path, std::ios::binary) << homework::answersAppendix(appendix);
    std::cout << path << "\n";
  }
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
  auto figures = std::make_shared<FigureSettings>();
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
    FigureSettings settings = *figures;
    if (*quick) {
      settings.width = std::min(settings.width, 320);
      settings.height = std::min(settings.height, 240);
    }
    render(*renderArgs, *output, *quick, settings);
  });
}

}  // namespace rt::cli
