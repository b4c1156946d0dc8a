#include "lesson/lesson_references.h"

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "core/input_error.h"
#include "lesson/lesson_loader.h"
#include "lesson/lesson_parser.h"
#include "lesson/maths.h"

namespace rt::lesson {

LessonNumbers lessonNumbers(const std::string& lessonsDir) {
  LessonNumbers numbers;
  if (lessonsDir.empty() || !std::filesystem::is_directory(lessonsDir)) return numbers;
  for (const std::string& path : lessonFiles(lessonsDir)) {
    std::ifstream in(path);
    std::stringstream text;
    text << in.rdbuf();
    const std::string id = std::filesystem::path(path).stem().string();
    try {
      numbers[id] = parseLesson(text.str(), id, path).order;
    } catch (const InputError&) {
      // Reported with its line when that lesson is loaded; references to it are then unknown here.
    }
  }
  return numbers;
}

std::string prepareLessonReferences(const std::string& markdown, int firstLine, const std::string& file,
                                    const LessonNumbers& numbers, const std::string& word) {
  struct Edit {
    LabelReference reference;
    std::string word;
  };
  std::vector<Edit> edits;
  for (const char* kind : {"lesson", "Lesson"})
    for (const LabelReference& r : findReferences(markdown, firstLine, kind)) edits.push_back({r, kind});
  std::sort(edits.begin(), edits.end(),
            [](const Edit& a, const Edit& b) { return a.reference.begin > b.reference.begin; });
  std::string out = markdown;
  for (const Edit& e : edits) {
    const auto number = numbers.find(e.reference.label);
    if (number == numbers.end()) {
      std::string known;
      for (const auto& [id, order] : numbers) known += (known.empty() ? "" : ", ") + id;
      throw InputError({file, e.reference.line}, "reference to an unknown lesson '@" + e.word + ":" +
                                                     e.reference.label + "' (known: " + known + ")");
    }
    std::string shown = word;
    if (e.word == "Lesson" && !shown.empty()) shown[0] = static_cast<char>(std::toupper(shown[0]));
    out.replace(e.reference.begin, e.reference.end - e.reference.begin,
                "[" + shown + " " + std::to_string(number->second) + "](" + e.reference.label + ".html#top)");
  }
  return out;
}

}  // namespace rt::lesson
