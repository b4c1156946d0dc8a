// radiosity homework new: a variant of each chosen topic per student, with handouts, data files and the
// instructor's key (src/homework). The topics are the rows of the homework table; --pdf runs pdflatex on the
// LaTeX sources when it is installed.
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <iostream>

#include "cli/commands.h"
#include "homework/handout.h"
#include "homework/topic_table.h"

namespace rt::cli {
namespace {

struct HomeworkNewArguments {
  std::vector<std::string> topics{"all"};
  std::uint64_t seed = 1;
  int count = 1;
  std::string output;
  bool pdf = false;
};

bool havePdflatex() {
  return std::system("command -v pdflatex > /dev/null 2>&1") == 0;
}

// pdflatex writes beside the source; a failure is reported and the LaTeX source stays usable.
void makePdf(const std::string& tex) {
  const std::filesystem::path path(tex);
  const std::string command = "cd '" + path.parent_path().string() +
                              "' && pdflatex -interaction=nonstopmode -halt-on-error '" +
                              path.filename().string() + "' > /dev/null 2>&1";
  if (std::system(command.c_str()) != 0)
    std::cerr << "radiosity: pdflatex failed on " << tex
              << " (see the .log beside it); the .tex is complete\n";
}

void run(const HomeworkNewArguments& a) {
  const auto start = std::chrono::steady_clock::now();
  std::vector<std::string> topics;
  for (const std::string& t : a.topics) {
    if (t == "all") {
      const auto all = homework::topicIds();
      topics.insert(topics.end(), all.begin(), all.end());
    } else {
      topics.push_back(t);
    }
  }
  const homework::Assignment assignment = homework::makeAssignment(topics, a.seed, a.count);
  const std::vector<std::string> latex = homework::writeAssignment(assignment, a.output);
  if (a.pdf) {
    if (havePdflatex()) {
      for (const std::string& tex : latex) makePdf(tex);
    } else {
      std::cerr << "radiosity: pdflatex is not installed: wrote the LaTeX sources (.tex) only\n";
    }
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << a.count << " students x " << topics.size() << " topics written to " << a.output << " in "
            << seconds << " s (key: " << (std::filesystem::path(a.output) / "key.json").string() << ")\n";
}

}  // namespace

void addHomeworkNewCommand(CLI::App& homework) {
  auto a = std::make_shared<HomeworkNewArguments>();
  auto* command = homework.add_subcommand(
      "new", "Write a variant of each topic per student: handouts (Markdown, LaTeX), data files and the key");
  std::vector<std::string> choices = homework::topicIds();
  choices.push_back("all");
  command->add_option("--topics", a->topics, "Comma-separated topics, or all")
      ->delimiter(',')
      ->check(CLI::IsMember(choices))
      ->capture_default_str();
  command->add_option("--seed", a->seed, "Seed of the variants: the same seed gives the same numbers")
      ->capture_default_str();
  command->add_option("--count", a->count, "Number of students")
      ->check(CLI::Range(1, 10000))
      ->capture_default_str();
  command->add_option("--output", a->output, "Folder to write (created)")->required();
  command->add_flag("--pdf", a->pdf, "Also typeset handout.pdf and key.pdf with pdflatex, when installed");
  command->callback([a] { run(*a); });
}

}  // namespace rt::cli
