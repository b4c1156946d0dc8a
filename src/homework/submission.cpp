#include "homework/submission.h"

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/input_error.h"
#include "core/io/matrix_import.h"

namespace rt::homework {
namespace {

namespace fs = std::filesystem;

std::string trim(const std::string& s) {
  const auto a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return {};
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

bool readFile(const fs::path& path, std::string& bytes) {
  std::ifstream in(path, std::ios::binary);
  if (!in) return false;
  std::ostringstream s;
  s << in.rdbuf();
  bytes = s.str();
  return true;
}

// numpy.save writes a list as a 1-D array, shape (n,); the core's reader takes 2-D arrays only. The header
// is padded with spaces to its announced length, so "(n,)" can become "(n,1)" in place of one space.
std::string asColumn(std::string bytes) {
  const std::size_t limit = std::min<std::size_t>(bytes.size(), 256);
  const std::size_t shape = bytes.find("'shape': (", 0);
  if (shape == std::string::npos || shape > limit) return bytes;
  const std::size_t close = bytes.find(')', shape);
  if (close == std::string::npos || close == 0 || bytes[close - 1] != ',') return bytes;
  const std::size_t newline = bytes.find('\n', close);
  if (newline == std::string::npos || bytes[newline - 1] != ' ') return bytes;
  bytes.erase(newline - 1, 1);
  bytes.insert(close, "1");
  return bytes;
}

}  // namespace

void readAnswerText(const std::string& text, const std::string& file, bool csv, const StudentExercises& key,
                    Submission& into) {
  if (text.find('\0') != std::string::npos) {
    into.problems.push_back(file + ": not a text file (binary data); expected `question = number` lines");
    return;
  }
  std::map<std::string, bool> known;
  for (const Exercise& e : key.exercises)
    for (const Question& q : e.questions) known[e.topic + "." + q.id] = true;
  std::istringstream in(text);
  std::string line;
  int number = 0;
  while (std::getline(in, line)) {
    ++number;
    const std::string where = file + ":" + std::to_string(number) + ": ";
    const std::string content = trim(line.substr(0, line.find('#')));
    if (content.empty()) continue;
    const std::size_t split = content.find(csv ? ',' : '=');
    if (split == std::string::npos) {
      into.problems.push_back(where + "expected `question " + (csv ? "," : "=") + " number`, got '" +
                              content + "'");
      continue;
    }
    const std::string id = trim(content.substr(0, split)), value = trim(content.substr(split + 1));
    if (csv && number == 1 && id == "question") continue;  // the header row
    if (!known.count(id)) {
      into.problems.push_back(where + "unknown question '" + id + "' (ids are listed in the handout)");
      continue;
    }
    if (value.empty()) continue;  // left blank: not answered
    char* end = nullptr;
    const double v = std::strtod(value.c_str(), &end);
    if (end == value.c_str() || trim(end) != "" || !std::isfinite(v)) {
      into.problems.push_back(where + "'" + value + "' is not a number (question " + id + ")");
      continue;
    }
    if (into.values.count(id))
      into.problems.push_back(where + id + " answered twice; the last answer counts");
    into.values[id] = v;
  }
}

void readAnswerNpy(const std::string& bytes, const std::string& file, const Exercise& e, Submission& into) {
  Eigen::MatrixXd m;
  try {
    m = parseNpyMatrix(asColumn(bytes), file);
  } catch (const InputError& error) {
    into.problems.push_back(error.what());
    return;
  }
  if (static_cast<std::size_t>(m.size()) != e.questions.size()) {
    into.problems.push_back(file + ": " + std::to_string(m.size()) + " numbers, but " + e.topic + " has " +
                            std::to_string(e.questions.size()) + " questions (in the handout's order)");
    return;
  }
  for (std::size_t k = 0; k < e.questions.size(); ++k) {
    const double v = m.data()[k];  // a vector: the order is the same in rows or columns
    if (!std::isnan(v)) into.values[e.topic + "." + e.questions[k].id] = v;
  }
}

Submission readSubmission(const std::string& folder, const StudentExercises& student) {
  Submission s;
  const fs::path root(folder);
  auto text = [&](const fs::path& path, bool csv) {
    std::error_code ec;
    if (!fs::exists(path, ec)) return;
    std::string bytes;
    if (!fs::is_regular_file(path, ec) || !readFile(path, bytes)) {
      s.problems.push_back(path.string() + ": cannot read the file");
      return;
    }
    s.files.push_back(path.string());
    readAnswerText(bytes, path.string(), csv, student, s);
  };
  text(root / (student.id + ".txt"), false);
  text(root / (student.id + ".csv"), true);
  text(root / student.id / "answers.txt", false);
  text(root / student.id / "answers.csv", true);
  for (const Exercise& e : student.exercises) {
    const fs::path npy = root / student.id / (e.topic + ".npy");
    std::error_code ec;
    if (!fs::exists(npy, ec)) continue;
    std::string bytes;
    if (!readFile(npy, bytes)) {
      s.problems.push_back(npy.string() + ": cannot read the file");
      continue;
    }
    s.files.push_back(npy.string());
    readAnswerNpy(bytes, npy.string(), e, s);
  }
  return s;
}

}  // namespace rt::homework
