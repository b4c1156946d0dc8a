#include "lesson/text_apparatus.h"

#include <filesystem>

#include "core/input_error.h"
#include "lesson/citations.h"

namespace rt::lesson {

TextApparatus lessonApparatus(const Lesson& lesson) {
  TextApparatus a;
  a.equations = numberEquations(lesson);
  a.algorithms = numberAlgorithms(lesson);
  const std::string folder = std::filesystem::path(lesson.file).parent_path().string();
  a.bibliography = loadBibliography(bibliographyPath(folder));
  a.lessons = lessonNumbers(folder);
  a.glossary = loadGlossary(glossaryPath(folder));
  return a;
}

std::string prepareText(const std::string& markdown, int firstLine, const std::string& file,
                        const TextApparatus& apparatus) {
  // Citations and maths keep the text's lines; the listings, set last, do not.
  std::string text = prepareCitations(markdown, firstLine, file, apparatus.bibliography);
  text = prepareLessonReferences(text, firstLine, file, apparatus.lessons, apparatus.lessonWord);
  text = prepareMaths(text, firstLine, file, apparatus.equations);
  return preparePseudocode(text, firstLine, file, apparatus.algorithms);
}

std::string furtherReading(const std::vector<std::string>& keys, const Bibliography& bibliography,
                           int level) {
  const std::string list = referenceListHtml(sortedEntries(bibliography, keys));
  if (list.empty() || level == 0) return list;
  const std::string h = "h" + std::to_string(level);
  return "<" + h + " class=\"further-reading\">Further reading</" + h + ">\n\n" + list;
}

std::vector<std::string> textProblems(const Lesson& lesson) {
  std::vector<std::string> problems;
  TextApparatus apparatus;
  try {
    apparatus = lessonApparatus(lesson);
  } catch (const InputError& e) {
    return {e.what()};
  }
  // Each kind of mistake is looked for on its own, so that one does not hide another in the same text.
  auto check = [&](const std::string& text, int firstLine) {
    auto attempt = [&](const auto& prepare) {
      try {
        prepare();
      } catch (const InputError& e) {
        problems.push_back(e.what());
      }
    };
    attempt([&] { prepareCitations(text, firstLine, lesson.file, apparatus.bibliography); });
    attempt([&] { prepareLessonReferences(text, firstLine, lesson.file, apparatus.lessons); });
    attempt([&] { prepareMaths(text, firstLine, lesson.file, apparatus.equations); });
    attempt([&] { preparePseudocode(text, firstLine, lesson.file, apparatus.algorithms); });
  };
  check(lesson.intro, lesson.introLine);
  for (const Step& step : lesson.steps) check(step.text, step.textLine);
  return problems;
}

std::string apparatusStyleSheet() {
  return R"(/* Algorithm listings, citations and reference lists. */
figure.algorithm { margin: 1.2em 0; text-align: left; border-top: 2px solid currentColor;
                   border-bottom: 2px solid currentColor; padding: 0.2em 0; break-inside: avoid; }
figure.algorithm figcaption { border-bottom: 1px solid currentColor; padding: 0.2em 0 0.3em; margin: 0;
                              text-align: left; font-size: 1em; }
table.algorithm-lines { border-collapse: collapse; margin: 0.2em 0 0; width: 100%; }
table.algorithm-lines td { border: none; padding: 0.05em 0.4em; vertical-align: baseline; }
td.alg-number { width: 1.6em; text-align: right; color: #777; font-size: 0.8em; }
td.alg-code { text-indent: -1em; }
td.alg-source { width: 13em; text-align: right; color: #888; font-size: 0.68em; line-height: 1.2;
                font-family: "DejaVu Sans Mono", monospace; overflow-wrap: break-word; }
@media (max-width: 30em) { td.alg-source { display: none; } }
p.reference, p.glossary { padding-left: 1.5em; text-indent: -1.5em; margin: 0.35em 0; }
/* A term's first use links to its definition (the definition on hover); the definition reached is marked. */
a.term { color: inherit; text-decoration: none; border-bottom: 1px dotted #777; }
p.glossary:target, p.reference:target { outline: 1px dotted #777; outline-offset: 2px; }
)";
}

}  // namespace rt::lesson
