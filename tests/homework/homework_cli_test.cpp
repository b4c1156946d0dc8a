// The homework commands end to end: `homework new` writes handouts, data and key; `homework check` grades a
// folder (the key handed in scores 100 %, a missing student is listed, a broken file is named on stderr) and
// a broken key is an input error naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>

#include "homework/answer_key.h"
#include "support/test_paths.h"

namespace rt::test {
namespace {

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(HomeworkCli, NewWritesHandoutsDataAndKeyAndCheckGradesTheClass) {
  const std::string dir = scratchDir("homework-cli");
  std::string log;
  ASSERT_EQ(runCommand(
                cliPath() + " homework new --topics all --seed 9 --count 3 --no-pdf --output " + dir + "/out",
                &log),
            0)
      << log;
  namespace fs = std::filesystem;
  for (const char* file :
       {"key.json", "key.md", "key.tex", "s01/handout.md", "s01/handout.tex", "s01/answers.txt",
        "s02/data/assemble-k-F.csv", "s02/data/assemble-k-F.mtx", "s02/data/assemble-k-F.npy",
        "s03/data/rectangles.json", "s03/data/rectangles.obj", "s03/figures/hemicube.svg"})
    EXPECT_TRUE(fs::exists(dir + "/out/" + file)) << file;
  EXPECT_NE(readText(dir + "/out/s01/handout.md").find("$F_{12}$"), std::string::npos);
  // Same seed, same handout; another seed, other numbers.
  ASSERT_EQ(
      runCommand(cliPath() + " homework new --seed 9 --count 3 --no-pdf --output " + dir + "/again", &log),
      0);
  EXPECT_EQ(readText(dir + "/out/s02/handout.md"), readText(dir + "/again/s02/handout.md"));
  ASSERT_EQ(
      runCommand(cliPath() + " homework new --seed 10 --count 3 --no-pdf --output " + dir + "/other", &log),
      0);
  EXPECT_NE(readText(dir + "/out/s02/handout.md"), readText(dir + "/other/s02/handout.md"));

  const homework::Assignment key = homework::parseKeyJson(readText(dir + "/out/key.json"), "key.json");
  fs::create_directories(dir + "/in");
  std::ofstream(dir + "/in/s01.txt") << homework::answersText(key.students[0], true);
  std::ofstream(dir + "/in/s02.txt") << "rectangles.F12 = zero\n";
  ASSERT_EQ(
      runCommand(cliPath() + " homework check --key " + dir + "/out/key.json --submissions " + dir + "/in",
                 &log),
      0)
      << log;
  EXPECT_NE(log.find("s02.txt:1: 'zero' is not a number (question rectangles.F12)"), std::string::npos)
      << log;
  const std::string book = readText(dir + "/in/gradebook.csv");
  EXPECT_NE(book.find(",100.0,graded\n"), std::string::npos) << book;
  EXPECT_NE(book.find("s03,"), std::string::npos) << book;
  EXPECT_NE(book.find("missing: no submission found"), std::string::npos) << book;
  EXPECT_TRUE(fs::exists(dir + "/in/feedback/s02.md"));

  std::ofstream(dir + "/bad-key.json") << "{\"format\": \"radiosity homework key\", \"seed\": 1}";
  EXPECT_EQ(
      runCommand(cliPath() + " homework check --key " + dir + "/bad-key.json --submissions " + dir + "/in",
                 &log),
      3);
  EXPECT_NE(log.find("bad-key.json at /topics: error: missing field 'topics'"), std::string::npos) << log;
  EXPECT_EQ(runCommand(cliPath() + " homework new --topics no-such --output " + dir + "/x", &log), 2) << log;
}

#ifdef RT_HAVE_TYPESET
// A class typeset to PDF (30 students take about a minute: docs/benchmarks.md) by the book's typesetter:
// every handout and the key are PDFs whose text has the exercises with their maths set (KaTeX writes F12 as
// "F", "12" in separate runs, so the text of a formula is checked by its parts), and a formula that fails to
// typeset would fail the command.
TEST(HomeworkCli, EveryHandoutAndTheKeyAreTypesetToPdf) {
  const std::string dir = scratchDir("homework-pdf");
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " homework new --seed 2026 --count 6 --output " + dir, &log), 0) << log;
  EXPECT_EQ(log.find("error"), std::string::npos) << log;
  for (int s = 1; s <= 6; ++s) {
    const std::string id = homework::studentId(s, 6);
    const std::string pdf = dir + "/" + id + "/handout.pdf";
    ASSERT_TRUE(std::filesystem::exists(pdf)) << id;
    EXPECT_EQ(readText(pdf).rfind("%PDF-", 0), 0u) << id;
  }
  std::string text;
  ASSERT_EQ(runCommand("pdftotext -layout " + dir + "/s05/handout.pdf -", &text), 0) << text;
  EXPECT_NE(text.find("Radiosity homework, student s05"), std::string::npos) << text;
  EXPECT_NE(text.find("Exercise 12"), std::string::npos) << text;
  EXPECT_EQ(text.find('$'), std::string::npos) << "raw maths left in the PDF:\n" << text;
  // An instructor edits a handout and typesets it again.
  std::ofstream(dir + "/s02/handout.md", std::ios::app)
      << "\nBonus: show that $F_{ii} = 0$ for a flat patch.\n";
  ASSERT_EQ(runCommand(cliPath() + " homework pdf " + dir + "/s02/handout.md", &log), 0) << log;
  ASSERT_EQ(runCommand("pdftotext " + dir + "/s02/handout.pdf -", &text), 0);
  EXPECT_NE(text.find("Bonus: show that"), std::string::npos) << text;
  std::string info;
  ASSERT_EQ(runCommand("pdfinfo " + dir + "/key.pdf", &info), 0) << info;
  EXPECT_NE(info.find("(A4)"), std::string::npos) << info;
  ASSERT_EQ(runCommand("pdftotext " + dir + "/key.pdf -", &text), 0);
  EXPECT_NE(text.find("Student s06"), std::string::npos) << text;
  // Nothing is cut off at a page's foot: every answer of every student is in the key's text.
  const homework::Assignment key = homework::parseKeyJson(readText(dir + "/key.json"), "key.json");
  std::map<std::string, std::size_t> expected;
  for (const homework::StudentExercises& student : key.students)
    for (const homework::Exercise& e : student.exercises)
      for (const homework::Question& q : e.questions) ++expected[e.topic + "." + q.id];
  for (const auto& [id, students] : expected) {
    std::size_t count = 0;
    for (std::size_t at = text.find(id); at != std::string::npos; at = text.find(id, at + 1)) ++count;
    EXPECT_GE(count, students) << id;
  }
}
#endif

}  // namespace
}  // namespace rt::test
