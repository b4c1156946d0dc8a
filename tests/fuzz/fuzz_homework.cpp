// libFuzzer target: what `radiosity homework check` reads from strangers, a student's answers (text, CSV,
// NPY) and a key. Answers never throw (every problem becomes a message naming the file); a key is valid or an
// InputError that says where.
#include <cstddef>
#include <cstdint>

#include "fuzz_support.h"
#include "homework/answer_key.h"
#include "homework/submission.h"
#include "homework/topic_table.h"

extern "C" int LLVMFuzzerInitialize(int*, char***) {
  rt::fuzz::limitMemory();
  return 0;
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rt::homework::StudentExercises student =
      rt::homework::makeAssignment(rt::homework::topicIds(), 1, 1).students.front();
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  rt::homework::Submission submission;
  rt::homework::readAnswerText(bytes, "fuzz.txt", false, student, submission);
  rt::homework::readAnswerText(bytes, "fuzz.csv", true, student, submission);
  for (const auto& exercise : student.exercises)
    rt::homework::readAnswerNpy(bytes, "fuzz.npy", exercise, submission);
  for (const std::string& problem : submission.problems)
    if (problem.rfind("fuzz.", 0) != 0) rt::fuzz::broken("a problem that names no file: " + problem);
  rt::fuzz::expectValidOrInputError([&] { rt::homework::parseKeyJson(bytes, "fuzz.json"); });
  return 0;
}
