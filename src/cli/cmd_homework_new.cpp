// radiosity homework new: a variant of each chosen topic per student, with handouts, data files and the
// instructor's key (src/homework). The topics are the rows of the homework table. The PDFs are typeset from
// the Markdown by the book's typesetter; the LaTeX sources are there for instructors who edit them.
#include <algorithm>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iostream>

#include "cli/commands.h"
#include "core/input_error.h"
#include "homework/handout.h"
#include "homework/topic_table.h"
#ifdef RT_HAVE_TYPESET
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QString>
#include <QUrl>

#include "lesson/book_html.h"
#include "typeset/book_printer.h"
#include "typeset/web_engine.h"
#endif

namespace rt::cli {
namespace {

namespace fs = std::filesystem;

struct HomeworkNewArguments {
  std::vector<std::string> topics{"all"};
  std::uint64_t seed = 1;
  int count = 1;
  std::string output;
  bool pdf = true;
};

#ifdef RT_HAVE_TYPESET
// Each handout.md and the key.md typeset as the book is (maths by KaTeX, A4 pages) into a PDF beside it. The
// print document is written beside the Markdown so that its figure paths resolve, and removed afterwards.
void printPdfs(const std::vector<std::string>& markdownFiles) {
  const typeset::WebSession session;
  const std::string katexStyle =
      QUrl::fromLocalFile(typeset::katexDirectory() + "/katex.min.css").toString().toStdString();
  std::vector<std::string> problems;
  for (const std::string& file : markdownFiles) {
    const fs::path md(file);
    std::ifstream in(md, std::ios::binary);
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    const fs::path print = md.parent_path() / (md.stem().string() + "-print.html");
    const fs::path pdf = fs::path(md).replace_extension(".pdf");
    // A class's key is long and consulted, not read through: it is set dense.
    std::ofstream(print, std::ios::binary)
        << lesson::printDocumentHtml(md.stem().string(), text, katexStyle, md.stem() == "key");
    const auto printed =
        typeset::printBook(QString::fromStdString(print.string()), QString::fromStdString(pdf.string()));
    fs::remove(print);
    for (const std::string& e : printed.maths.errors) problems.push_back(md.string() + ": error: " + e);
  }
  if (!problems.empty()) {
    for (const std::string& p : problems) std::cerr << p << "\n";
    throw InputError({}, std::to_string(problems.size()) + " formula(s) did not typeset (listed above)");
  }
}

// The documents split in two of about equal size (the key weighs as much as many handouts), one half
// typeset by a second process of this program (`homework pdf`) while this one does the other: a web engine
// lays out and prints on one core, and a class's PDFs take half the time on two.
void printPdfsOnTwoCores(const std::vector<std::string>& markdownFiles) {
  std::vector<std::pair<std::uintmax_t, std::string>> bySize;
  for (const std::string& f : markdownFiles) bySize.emplace_back(fs::file_size(f), f);
  std::sort(bySize.begin(), bySize.end(), std::greater<>());
  std::vector<std::string> mine, theirs;
  std::uintmax_t mineBytes = 0, theirBytes = 0;
  for (const auto& [bytes, file] : bySize) {
    (mineBytes <= theirBytes ? mine : theirs).push_back(file);
    (mineBytes <= theirBytes ? mineBytes : theirBytes) += bytes;
  }
  char self[4096];
  const ssize_t length = readlink("/proc/self/exe", self, sizeof self - 1);
  pid_t child = -1;
  if (length > 0 && !theirs.empty()) {
    self[length] = '\0';
    std::vector<std::string> words{self, "homework", "pdf"};
    words.insert(words.end(), theirs.begin(), theirs.end());
    std::vector<char*> argv;
    for (std::string& w : words) argv.push_back(w.data());
    argv.push_back(nullptr);
    if (posix_spawn(&child, self, nullptr, nullptr, argv.data(), environ) != 0) child = -1;
  }
  if (child < 0) mine.insert(mine.end(), theirs.begin(), theirs.end());  // no second process: all here
  printPdfs(mine);
  if (child < 0) return;
  int status = 0;
  waitpid(child, &status, 0);
  if (!WIFEXITED(status) || WEXITSTATUS(status) != 0)
    throw InputError({}, "typesetting the other half of the PDFs failed (see above)");
}
#endif

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
  const std::vector<std::string> markdown = homework::writeAssignment(assignment, a.output);
#ifdef RT_HAVE_TYPESET
  if (a.pdf) printPdfsOnTwoCores(markdown);
#else
  if (a.pdf)
    std::cerr << "radiosity: built without the typesetter: wrote the Markdown and LaTeX sources only\n";
#endif
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::cout << a.count << " students x " << topics.size() << " topics written to " << a.output << " in "
            << seconds << " s (key: " << (std::filesystem::path(a.output) / "key.json").string() << ")\n";
}

}  // namespace

void addHomeworkPdfCommand(CLI::App& homework) {
  auto files = std::make_shared<std::vector<std::string>>();
  auto* command = homework.add_subcommand(
      "pdf", "Typeset Markdown handouts or keys (edited or written by `homework new`) to PDF beside them");
  command->add_option("files", *files, "Markdown files (.md)")->required()->check(CLI::ExistingFile);
  command->callback([files] {
#ifdef RT_HAVE_TYPESET
    printPdfs(*files);
#else
    throw std::runtime_error("homework pdf needs the typesetter (configure with RT_BUILD_TYPESET=ON)");
#endif
  });
}

void addHomeworkNewCommand(CLI::App& homework) {
  auto a = std::make_shared<HomeworkNewArguments>();
  auto* command = homework.add_subcommand(
      "new",
      "Write a variant of each topic per student: handouts (PDF, Markdown, LaTeX), data files and the key "
      "(run it under xvfb-run without a display: the PDFs are typeset by a web engine)");
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
  command->add_flag(
      "!--no-pdf", a->pdf,
      "Write the sources (Markdown, LaTeX) only, not handout.pdf and key.pdf (typeset as the book is)");
  command->callback([a] { run(*a); });
}

}  // namespace rt::cli
