#include "homework/handout.h"

#include "homework/conceptual.h"

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "core/io/matrix_export.h"
#include "homework/latex_text.h"

namespace rt::homework {
namespace {

namespace fs = std::filesystem;

void writeText(const fs::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw InputError({path.string(), 0, {}}, "cannot write the file");
}

std::string exerciseHeading(std::size_t k, const Exercise& e) {
  return "## Exercise " + std::to_string(k + 1) + ": " + e.title + "\n\n";
}

std::string dataList(const Exercise& e) {
  std::string out;
  for (const DataFile& d : e.data) out += "`data/" + e.topic + "-" + d.name + ".csv` (also `.mtx`, `.npy`) ";
  if (!e.sceneJson.empty()) out += "`data/" + e.topic + ".json` (also `.obj`)";
  return out.empty() ? out : "Data: " + out + "\n\n";
}

std::string questionList(const Exercise& e) {
  std::string out = "Answer ids (in `answers.txt`):\n\n";
  for (const Question& q : e.questions) out += "- `" + e.topic + "." + q.id + "`: " + q.label + "\n";
  return out + "\n";
}

}  // namespace

std::string handoutMarkdown(const StudentExercises& s, std::uint64_t seed) {
  std::string out =
      "# Radiosity homework, student " + s.id + "\n\nVariant seed " + std::to_string(seed) +
      ". Write every answer in `answers.txt` (one `question = number` per line) and hand in that "
      "file.\n\n";
  for (std::size_t k = 0; k < s.exercises.size(); ++k) {
    const Exercise& e = s.exercises[k];
    out += exerciseHeading(k, e) + e.statement + "\n\n";
    if (e.figure) out += "![" + e.figure->caption + "](figures/" + e.topic + ".svg)\n\n";
    out += dataList(e) + questionList(e) + "Hint: " + e.hint + "\n\n";
  }
  return out;
}

std::string exerciseBookText(const Exercise& e) {
  std::string out = "\n" + e.statement + "\n\n";
  for (const Question& q : e.questions) {
    if (q.choices.empty()) out += "- " + q.label + "\n";
    for (std::size_t k = 0; k < q.choices.size(); ++k)
      out += "- " + choiceLetter(k) + " " + q.choices[k] + "\n";
  }
  return out + "\n" + answerInstruction(e, Frame::Book) + "\n";
}

std::string answersAppendix(const std::vector<AppendixEntry>& entries) {
  std::string out;
  for (const AppendixEntry& entry : entries) {
    out += "\n### " + entry.where + "\n\n";
    for (const Question& q : entry.exercise.questions) {
      // A multiple-choice answer is the choice's number from 1; any other answer (a numeric one may be
      // negative) is printed as a number.
      const bool choice = q.answer >= 1 && q.answer <= static_cast<double>(q.choices.size());
      const std::size_t k = choice ? static_cast<std::size_t>(q.answer) - 1 : 0;
      out += choice ? "- " + choiceLetter(k) + " " + q.choices[k] + "\n"
                    : "- " + q.label + ": $" + num(q.answer, 6) + "$\n";
    }
    out += "\nWorked solution:\n\n";
    for (const std::string& step : entry.exercise.solution) out += "- " + step + "\n";
  }
  return out;
}

std::vector<std::string> writeAssignment(const Assignment& a, const std::string& directory) {
  std::vector<std::string> markdown;
  const fs::path root(directory);
  std::error_code ec;
  fs::create_directories(root, ec);
  if (ec) throw InputError({directory, 0, {}}, "cannot create the folder: " + ec.message());
  for (const StudentExercises& s : a.students) {
    const fs::path dir = root / s.id;
    fs::create_directories(dir / "figures", ec);
    fs::create_directories(dir / "data", ec);
    if (ec) throw InputError({dir.string(), 0, {}}, "cannot create the folder: " + ec.message());
    std::string tex;
    for (std::size_t k = 0; k < s.exercises.size(); ++k) {
      const Exercise& e = s.exercises[k];
      for (const DataFile& d : e.data) {
        const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> m = d.matrix;
        for (const char* ext : {".csv", ".mtx", ".npy"})
          writeMatrix(m, (dir / "data" / (e.topic + "-" + d.name + ext)).string());
      }
      if (!e.sceneJson.empty()) {
        writeText(dir / "data" / (e.topic + ".json"), e.sceneJson);
        writeText(dir / "data" / (e.topic + ".obj"), e.sceneObj);
      }
      if (e.figure) writeText(dir / "figures" / (e.topic + ".svg"), toSvg(*e.figure));
      tex += markdownToLatex(exerciseHeading(k, e) + e.statement + "\n");
      if (e.figure)
        tex += "\n\\begin{center}\n" + toLatexPicture(*e.figure) + "\n\\small " +
               markdownToLatex(e.figure->caption) + "\\end{center}\n";
      tex += markdownToLatex("\n" + dataList(e) + questionList(e) + "Hint: " + e.hint + "\n");
    }
    writeText(dir / "handout.md", handoutMarkdown(s, a.seed));
    writeText(dir / "handout.tex", latexDocument("Radiosity homework, student " + s.id, tex));
    writeText(dir / "answers.txt", answersText(s, false));
    markdown.push_back((dir / "handout.md").string());
  }
  writeText(root / "key.json", keyJson(a));
  const std::string key = keyMarkdown(a);
  writeText(root / "key.md", key);
  writeText(root / "key.tex", latexDocument("Radiosity homework: answer key", markdownToLatex(key)));
  markdown.push_back((root / "key.md").string());
  return markdown;
}

}  // namespace rt::homework
