#include "lesson/exercise_topics.h"

#include "homework/topic_table.h"

namespace rt::lesson {

std::vector<std::string> exerciseTopicProblems(const Lesson& lesson) {
  std::vector<std::string> problems;
  for (const Step& step : lesson.steps) {
    if (step.stage != Stage::Exercise || step.parameters.topic.empty()) continue;
    const homework::Topic* topic = homework::findTopic(step.parameters.topic);
    if (!topic || homework::topicFitsLesson(*topic, lesson.id)) continue;
    const auto field = step.fields.find("topic");
    const int line = field == step.fields.end() ? step.line : field->second.line;
    std::string fitting;
    for (const homework::Topic& t : homework::topicTable())
      if (homework::topicFitsLesson(t, lesson.id)) fitting += std::string(fitting.empty() ? "" : ", ") + t.id;
    problems.push_back(lesson.file + ":" + std::to_string(line) + ": topic '" + topic->id +
                       "' does not practise lesson '" + lesson.id + "' (its row lists " + topic->lessons +
                       "); topics that do: " + (fitting.empty() ? "none yet" : fitting));
  }
  return problems;
}

}  // namespace rt::lesson
