// radiosity homework check: grades a folder of submissions against key.json, writes the gradebook (CSV) and
// one feedback file per student, and reports every missing or malformed file on stderr without stopping.
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>

#include "cli/commands.h"
#include "core/input_error.h"
#include "homework/grader.h"
#include "homework/topic_table.h"

namespace rt::cli {
namespace {

struct HomeworkCheckArguments {
  std::string key, submissions, gradebook, feedback;
};

void writeText(const std::filesystem::path& path, const std::string& text) {
  std::ofstream out(path, std::ios::binary);
  out << text;
  if (!out) throw InputError({path.string(), 0, {}}, "cannot write the file");
}

void run(const HomeworkCheckArguments& a) {
  std::ifstream in(a.key, std::ios::binary);
  if (!in) throw InputError({a.key, 0, {}}, "cannot open the key");
  std::stringstream text;
  text << in.rdbuf();
  const homework::Assignment key = homework::parseKeyJson(text.str(), a.key);
  if (!std::filesystem::is_directory(a.submissions))
    throw InputError({a.submissions, 0, {}}, "not a folder of submissions");
  std::vector<std::string> unmatched;
  const auto grades = homework::gradeClass(key, a.submissions, unmatched);
  const std::filesystem::path gradebook = a.gradebook.empty()
                                              ? std::filesystem::path(a.submissions) / "gradebook.csv"
                                              : std::filesystem::path(a.gradebook);
  const std::filesystem::path feedback = a.feedback.empty()
                                             ? std::filesystem::path(a.submissions) / "feedback"
                                             : std::filesystem::path(a.feedback);
  std::filesystem::create_directories(feedback);
  writeText(gradebook, homework::gradebookCsv(key, grades));
  for (const auto& g : grades) {
    writeText(feedback / (g.id + ".md"), homework::feedbackMarkdown(g));
    std::printf("%s  %3d/%-3d %5.1f %%%s\n", g.id.c_str(), g.right, g.total, g.percent(),
                g.submission.found() ? "" : "  (no submission)");
    for (const std::string& p : g.submission.problems) std::cerr << "radiosity: " << p << "\n";
  }
  for (const std::string& p : unmatched) std::cerr << "radiosity: " << p << "\n";
  std::cout << "gradebook: " << gradebook.string() << ", feedback: " << feedback.string() << "\n";
}

}  // namespace

void addHomeworkCheckCommand(CLI::App& homework) {
  auto a = std::make_shared<HomeworkCheckArguments>();
  auto* command = homework.add_subcommand(
      "check", "Grade submissions against a key: gradebook CSV and feedback naming recognised mistakes");
  command->add_option("--key", a->key, "key.json written by `radiosity homework new`")
      ->required()
      ->check(CLI::ExistingFile);
  command
      ->add_option("--submissions", a->submissions,
                   "Folder with s01.txt, s01/answers.csv, s01/<topic>.npy ...")
      ->required();
  command->add_option("--gradebook", a->gradebook, "CSV to write (default: <submissions>/gradebook.csv)");
  command->add_option("--feedback", a->feedback, "Folder for <student>.md (default: <submissions>/feedback)");
  command->callback([a] { run(*a); });
}

void addHomeworkTopicsCommand(CLI::App& homework) {
  auto* command =
      homework.add_subcommand("topics", "The table of homework topics as Markdown, as the docs show it");
  command->callback([] { std::cout << homework::topicTableMarkdown(); });
}

}  // namespace rt::cli
