// The homework commands end to end: `homework new` writes handouts, data and key; `homework check` grades a
// folder (the key handed in scores 100 %, a missing student is listed, a broken file is named on stderr) and
// a broken key is an input error naming the file.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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
  ASSERT_EQ(
      runCommand(cliPath() + " homework new --topics all --seed 9 --count 3 --output " + dir + "/out", &log),
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
  ASSERT_EQ(runCommand(cliPath() + " homework new --seed 9 --count 3 --output " + dir + "/again", &log), 0);
  EXPECT_EQ(readText(dir + "/out/s02/handout.md"), readText(dir + "/again/s02/handout.md"));
  ASSERT_EQ(runCommand(cliPath() + " homework new --seed 10 --count 3 --output " + dir + "/other", &log), 0);
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

// The LaTeX sources typeset for a whole class: a figure or a number that TeX cannot take fails here. Skipped
// where pdflatex is not installed (it is optional: the handouts are complete without a PDF).
TEST(HomeworkCli, EveryHandoutAndTheKeyTypesetWithPdflatex) {
  if (runCommand("command -v pdflatex") != 0) GTEST_SKIP() << "pdflatex is not installed";
  const std::string dir = scratchDir("homework-pdf");
  std::string log;
  ASSERT_EQ(runCommand(cliPath() + " homework new --seed 2026 --count 30 --pdf --output " + dir, &log), 0)
      << log;
  EXPECT_EQ(log.find("pdflatex failed"), std::string::npos) << log;
  for (int s = 1; s <= 30; ++s) {
    const std::string id = homework::studentId(s, 30);
    EXPECT_TRUE(std::filesystem::exists(dir + "/" + id + "/handout.pdf")) << id;
  }
  EXPECT_TRUE(std::filesystem::exists(dir + "/key.pdf"));
}

}  // namespace
}  // namespace rt::test
