#include "cli/lesson_rendering.h"

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/cli_common.h"
#include "core/input_error.h"
#include "homework/handout.h"
#include "lesson/book_index.h"
#include "lesson/citations.h"
#include "lesson/glossary.h"
#include "lesson/step_numbers.h"
#include "lesson/step_runner.h"
#include "lesson/text_apparatus.h"
#ifdef RT_HAVE_VIZ
#include "viz/lesson_figures.h"
#endif
#ifdef RT_HAVE_TYPESET
#include "typeset/typesetter.h"
#endif

namespace rt::cli {
namespace {

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

// One more chapter after the last, in the book's Appendix part.
void appendChapter(std::vector<lesson::RenderedLesson>& book, const std::string& id, const std::string& title,
                   const std::string& summary, std::string body) {
  lesson::RenderedLesson chapter;
  chapter.id = id;
  chapter.title = title;
  chapter.chapter = "Appendix";
  chapter.summary = summary;
  chapter.order = book.back().order + 1;
  chapter.intro = std::move(body);
  book.push_back(std::move(chapter));
}

}  // namespace

lesson::LessonFolders LessonArguments::folders() const {
  return root.empty() ? lesson::defaultFolders() : lesson::foldersUnder(root);
}

void LessonArguments::add(CLI::App* command) {
  command->add_option("lessons", ids, "Lesson ids (file names in lessons/ without .md)");
  command->add_flag("--all", all, "Every lesson in lessons/");
  command->add_option("--root", root, "Folder holding lessons/ and scenes/ (default: the current folder)");
}

std::vector<std::string> LessonArguments::files() const {
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

std::vector<lesson::RenderedLesson> renderLessons(const std::vector<std::string>& files,
                                                  const lesson::LessonFolders& folders,
                                                  const std::string& output, const RenderSettings& settings) {
#ifndef RT_HAVE_VIZ
  std::cerr << "radiosity: this build has no viz library: writing the text without figures\n";
#endif
  lesson::RunOptions options;
  options.quick = settings.quick;
  std::vector<lesson::RenderedLesson> rendered;
  std::vector<homework::AppendixEntry> appendix;  // the exercises, answered at the back of the book
  std::vector<std::string> cited;                 // the works the lessons cite, for the references
  lesson::Bibliography bibliography;
  std::vector<lesson::Lesson> loaded;  // for the glossary's first uses
  ProgressLine progress(true);
  std::filesystem::create_directories(output);
  std::ofstream skipped(std::filesystem::path(output) / "skipped.txt");  // figures this build could not draw
  for (const auto& file : files) {
    const lesson::Lesson l = lesson::loadLesson(file, folders.scenes);
    lesson::TextApparatus apparatus = lesson::lessonApparatus(l);
    apparatus.lessonWord = settings.lessonWord;
    bibliography = apparatus.bibliography;  // one file beside the lessons
    options.outputDir = (std::filesystem::path(output) / l.id).string();
    lesson::StepRunner runner(folders.scenes, options);
    lesson::RenderedLesson page = renderedHeader(l);
    if (settings.prepareText) {
      page.intro = lesson::prepareText(l.intro, l.introLine, l.file, apparatus);
      page.furtherReading = lesson::furtherReading(lesson::citedKeys(l), apparatus.bibliography, 0);
    }
    for (const auto& key : lesson::citedKeys(l))
      if (std::find(cited.begin(), cited.end(), key) == cited.end()) cited.push_back(key);
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
      std::string text = lesson::resolvedText(l, step, result);
      if (settings.prepareText) text = lesson::prepareText(text, step.textLine, l.file, apparatus);
      if (result.exercise) {
        text += homework::exerciseBookText(*result.exercise);
        appendix.push_back({std::to_string(l.order) + "." + std::to_string(step.index + 1) + " " + step.title,
                            *result.exercise});
      }
      lesson::RenderedStep s{step.title, text, {}};
      try {
#ifdef RT_HAVE_VIZ
        s.figures = viz::renderStepFigures(l, step, result, options.outputDir,
                                           {settings.width, settings.height, settings.format});
#endif
      } catch (const std::exception& e) {
        throw InputError({l.file, step.line}, "step '" + step.title + "': " + e.what());
      }
      page.steps.push_back(std::move(s));
    }
    numbers << "\n]\n";
    rendered.push_back(std::move(page));
    loaded.push_back(l);
  }
  progress.finish();
  std::stable_sort(rendered.begin(), rendered.end(),
                   [](const auto& x, const auto& y) { return x.order < y.order; });
  const auto glossary = lesson::loadGlossary(lesson::glossaryPath(folders.lessons));
  // The terms' uses in the lessons (not in the appendices), marked for the index and linked to the glossary.
  const auto index =
      settings.prepareText ? lesson::markIndexTerms(rendered, glossary) : std::vector<lesson::IndexEntry>{};
  if (!appendix.empty()) {
    // The answers close the book: one more page after the last lesson, in the Markdown, HTML and PDF.
    appendChapter(rendered, homework::kAnswersAppendixId, "Answers to the exercises",
                  "The answer and the worked solution of every exercise, lesson by lesson.",
                  homework::answersAppendix(appendix));
  }
  if (!cited.empty() && settings.prepareText) {
    // Every work cited in the book, sorted by author, after the last chapter.
    appendChapter(rendered, "references", "References", "Every work the chapters cite, by author.",
                  lesson::furtherReading(cited, bibliography, 0));
  }
  if (!glossary.empty() && settings.prepareText) {
    // Every term defined once, with a link to where the book first uses it.
    std::stable_sort(loaded.begin(), loaded.end(),
                     [](const auto& x, const auto& y) { return x.order < y.order; });
    appendChapter(rendered, "glossary", "Glossary",
                  "The terms of the book, each defined once, with the section that first uses it.",
                  lesson::glossaryHtml(glossary, loaded));
  }
  if (!index.empty()) {
    appendChapter(rendered, "term-index", "Index",
                  "Every term of the glossary, and a few more, with the sections that use it.",
                  lesson::indexHtml(index));
  }
  return rendered;
}

std::vector<std::string> lessonTextProblems(const lesson::Lesson& l) {
  std::vector<std::string> problems = lesson::textProblems(l);
#ifdef RT_HAVE_TYPESET
  for (auto& p : typeset::checkFormulas(lesson::lessonFormulas(l), l.file)) problems.push_back(std::move(p));
  try {
    for (auto& p : typeset::checkFormulas(lesson::algorithmFormulas(l), l.file))
      problems.push_back(std::move(p));
  } catch (const InputError&) {
    // A malformed listing: lesson::textProblems reported it.
  }
#endif
  return problems;
}

}  // namespace rt::cli
