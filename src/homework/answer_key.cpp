#include "homework/answer_key.h"

#include <cstdio>
#include <nlohmann/json.hpp>

#include "core/input_error.h"
#include "homework/topic_table.h"

namespace rt::homework {

std::string studentId(int index, int count) {
  const int width = std::max(2, static_cast<int>(std::to_string(count).size()));
  std::string digits = std::to_string(index);
  return "s" +
         std::string(static_cast<std::size_t>(std::max(0, width - static_cast<int>(digits.size()))), '0') +
         digits;
}

Assignment makeAssignment(const std::vector<std::string>& topics, std::uint64_t seed, int count) {
  Assignment a;
  a.seed = seed;
  a.topics = topics;
  for (int s = 1; s <= count; ++s) {
    StudentExercises student{studentId(s, count), {}};
    for (const std::string& id : topics) {
      const Topic* topic = findTopic(id);
      if (!topic) throw std::invalid_argument("unknown homework topic '" + id + "'");
      student.exercises.push_back(generateExercise(*topic, seed, s));
    }
    a.students.push_back(std::move(student));
  }
  return a;
}

std::string keyJson(const Assignment& a) {
  nlohmann::json root;
  root["format"] = "radiosity homework key";
  root["version"] = 1;
  root["seed"] = a.seed;
  root["topics"] = a.topics;
  for (const StudentExercises& s : a.students) {
    nlohmann::json student{{"id", s.id}};
    for (const Exercise& e : s.exercises) {
      nlohmann::json ex{{"topic", e.topic}, {"title", e.title}};
      for (const Question& q : e.questions) {
        nlohmann::json mistakes = nlohmann::json::array();
        for (const Mistake& m : q.mistakes) mistakes.push_back({{"name", m.name}, {"value", m.value}});
        ex["questions"].push_back({{"id", q.id},
                                   {"answer", q.answer},
                                   {"tolerance", q.tolerance},
                                   {"integer", q.integer},
                                   {"mistakes", mistakes}});
      }
      ex["row_checks"] = nlohmann::json::array();
      for (const RowCheck& r : e.rowChecks) {
        nlohmann::json terms = nlohmann::json::array();
        for (const auto& [id, count] : r.terms) terms.push_back({{"id", id}, {"count", count}});
        ex["row_checks"].push_back({{"row", r.row}, {"known", r.known}, {"terms", terms}});
      }
      student["exercises"].push_back(ex);
    }
    root["students"].push_back(student);
  }
  return root.dump(1) + "\n";
}

namespace {

// Reads a field, turning nlohmann's exceptions into an InputError at the field's JSON path.
template <typename T>
T field(const nlohmann::json& object, const std::string& key, const std::string& path,
        const std::string& file) {
  if (!object.is_object() || !object.contains(key))
    throw InputError({file, 0, path + "/" + key}, "missing field '" + key + "'");
  try {
    return object.at(key).get<T>();
  } catch (const nlohmann::json::exception&) {
    throw InputError({file, 0, path + "/" + key}, "field '" + key + "' has the wrong type");
  }
}

const nlohmann::json& array(const nlohmann::json& object, const std::string& key, const std::string& path,
                            const std::string& file) {
  if (!object.is_object() || !object.contains(key) || !object.at(key).is_array())
    throw InputError({file, 0, path + "/" + key}, "missing array '" + key + "'");
  return object.at(key);
}

}  // namespace

// The key from its parsed JSON; nlohmann's type errors escape to parseKeyJson, which names the file.
static Assignment keyFromJson(const nlohmann::json& root, const std::string& file);

Assignment parseKeyJson(const std::string& text, const std::string& file) {
  nlohmann::json root;
  try {
    root = nlohmann::json::parse(text);
  } catch (const nlohmann::json::exception& e) {  // a syntax error, or a number too large for a double
    throw InputError({file, 0, {}}, std::string("not a key file (JSON): ") + e.what());
  }
  try {
    return keyFromJson(root, file);
  } catch (const nlohmann::json::exception& e) {  // a field of the wrong type that value() read
    throw InputError({file, 0, {}}, std::string("malformed key: ") + e.what());
  }
}

static Assignment keyFromJson(const nlohmann::json& root, const std::string& file) {
  if (!root.is_object() || root.value("format", "") != "radiosity homework key")
    throw InputError({file, 0, "/format"},
                     "not a radiosity homework key (written by `radiosity homework new`)");
  Assignment a;
  a.seed = field<std::uint64_t>(root, "seed", "", file);
  a.topics = field<std::vector<std::string>>(root, "topics", "", file);
  const auto& students = array(root, "students", "", file);
  for (std::size_t s = 0; s < students.size(); ++s) {
    const std::string sp = "/students/" + std::to_string(s);
    StudentExercises student{field<std::string>(students[s], "id", sp, file), {}};
    const auto& exercises = array(students[s], "exercises", sp, file);
    for (std::size_t k = 0; k < exercises.size(); ++k) {
      const std::string ep = sp + "/exercises/" + std::to_string(k);
      Exercise e;
      e.topic = field<std::string>(exercises[k], "topic", ep, file);
      e.title = exercises[k].value("title", e.topic);
      const auto& questions = array(exercises[k], "questions", ep, file);
      for (std::size_t q = 0; q < questions.size(); ++q) {
        const std::string qp = ep + "/questions/" + std::to_string(q);
        Question question{field<std::string>(questions[q], "id", qp, file),
                          "",
                          field<double>(questions[q], "answer", qp, file),
                          field<double>(questions[q], "tolerance", qp, file),
                          questions[q].value("integer", false),
                          {}};
        if (questions[q].contains("mistakes"))
          for (const auto& m : array(questions[q], "mistakes", qp, file))
            question.mistakes.push_back({field<std::string>(m, "name", qp + "/mistakes", file),
                                         field<double>(m, "value", qp + "/mistakes", file)});
        e.questions.push_back(std::move(question));
      }
      if (exercises[k].contains("row_checks"))
        for (const auto& r : array(exercises[k], "row_checks", ep, file)) {
          RowCheck check{field<std::string>(r, "row", ep + "/row_checks", file),
                         {},
                         field<double>(r, "known", ep + "/row_checks", file)};
          for (const auto& t : array(r, "terms", ep + "/row_checks", file))
            check.terms.emplace_back(field<std::string>(t, "id", ep + "/row_checks", file),
                                     field<double>(t, "count", ep + "/row_checks", file));
          e.rowChecks.push_back(std::move(check));
        }
      student.exercises.push_back(std::move(e));
    }
    a.students.push_back(std::move(student));
  }
  return a;
}

std::string keyMarkdown(const Assignment& a) {
  std::string out = "# Answer key\n\nSeed " + std::to_string(a.seed) + ", " +
                    std::to_string(a.students.size()) +
                    " students. Each answer is right within the tolerance given in brackets.\n";
  for (const StudentExercises& s : a.students) {
    out += "\n## Student " + s.id + "\n";
    for (std::size_t k = 0; k < s.exercises.size(); ++k) {
      const Exercise& e = s.exercises[k];
      out += "\n### " + std::to_string(k + 1) + ". " + e.title + " (`" + e.topic + "`)\n\n";
      for (const std::string& step : e.solution) out += "- " + step + "\n";
      out += "\n| answer id | answer | tolerance |\n|---|---|---|\n";
      for (const Question& q : e.questions)
        out += "| `" + e.topic + "." + q.id + "` | $" + num(q.answer, 6) + "$ | $" + num(q.tolerance, 2) +
               "$ |\n";
    }
  }
  return out;
}

std::string answersText(const StudentExercises& s, bool filled) {
  std::string out = "# Answers of student " + s.id +
                    ": one `question = number` per line (docs/homework.md); yes/no as 1/0.\n";
  for (const Exercise& e : s.exercises) {
    out += "\n# " + e.title + "\n";
    for (const Question& q : e.questions) {
      char value[40] = "";
      if (filled) std::snprintf(value, sizeof value, " %.17g", q.answer);
      out += e.topic + "." + q.id + " =" + value + "\n";
    }
  }
  return out;
}

}  // namespace rt::homework
