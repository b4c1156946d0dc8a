// libFuzzer target: the lesson parser, then the placeholders of every step's text resolved against a lookup
// that knows a few names. Both must give a lesson or an InputError naming the file.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <optional>

#include "fuzz_support.h"
#include "lesson/lesson_parser.h"
#include "lesson/placeholders.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  rt::fuzz::expectValidOrInputError([&] {
    const rt::lesson::Lesson lesson = rt::lesson::parseLesson(text, "fuzz", "fuzz.md");
    const rt::lesson::ValueLookup lookup = [](const std::string& name) -> std::optional<double> {
      if (name == "iterations") return 12;
      if (name == "F.floor.light") return 0.123456789;
      if (name == "huge") return 1e308;
      if (name == "nan") return std::nan("");
      return std::nullopt;
    };
    for (const auto& step : lesson.steps)
      rt::lesson::resolvePlaceholders(step.text, step.textLine, "fuzz.md", lookup,
                                      {"iterations", "F.floor.light"});
  });
  return 0;
}
