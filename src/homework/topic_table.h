// The one table of homework topics: each row names a topic, says what it practises and which lessons it
// belongs to, and holds its generator. `radiosity homework new --topics` offers the ids, docs/homework.md
// prints the table, the lessons' exercise steps name a topic, and the tests walk every row.
//
// A generator draws a variant's numbers, checks that they are well-posed (a reflectance below 1, a
// non-singular K, a hemicube footprint inside the field of view...) and returns nullopt when they are not, so
// that generateExercise() draws again; otherwise it solves the variant and returns the exercise with its key
// and worked solution.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "core/formfactor/sampling.h"
#include "homework/exercise.h"

namespace rt::homework {

// The random numbers of one variant, with the roundings that keep the printed numbers exact: a generator
// draws "nice" values and computes the key from exactly what the student reads.
class Draw {
 public:
  Draw(std::uint64_t seed, std::uint64_t student, std::uint64_t topic) : random_(seed, student, topic) {}
  double uniform() { return random_.uniform(); }
  // Uniform in [lo, hi], rounded to a multiple of `step`.
  double value(double lo, double hi, double step);
  int integer(int lo, int hi);  // inclusive

 private:
  PairRandom random_;
};

using Generator = std::optional<Exercise> (*)(Draw& draw);

struct Topic {
  const char* id;
  const char* title;
  const char* practises;  // one line for the docs and --help
  // The lessons whose own topic it practises (comma-separated ids): the one place that says which topics fit
  // a lesson. A lesson's exercise steps may name only topics whose row lists it (a test checks every step).
  const char* lessons;
  Generator generate;
};

const std::vector<Topic>& topicTable();
const Topic* findTopic(const std::string& id);
std::vector<std::string> topicIds();
// Whether `lessonId` is one of the lessons the topic's row lists.
bool topicFitsLesson(const Topic& topic, const std::string& lessonId);

// The variant of `topic` for `student` (0 = a lesson's exercise): the same (seed, student) always gives the
// same numbers. Draws again while the generator rejects a draw; throws std::runtime_error after 1000.
Exercise generateExercise(const Topic& topic, std::uint64_t seed, int student);

// Problems with an exercise that a generator must never produce (non-finite answers, tolerances <= 0, no
// questions, duplicate ids); empty when it is fine.
std::vector<std::string> exerciseProblems(const Exercise& exercise);

// The table as Markdown (docs/homework.md holds it; a test keeps the two equal).
std::string topicTableMarkdown();

}  // namespace rt::homework
