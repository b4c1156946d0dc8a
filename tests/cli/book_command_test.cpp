// radiosity book, headless: the HTML site (a page per lesson, every equation typeset by KaTeX, nothing from
// the network) and the PDF (a page per lesson or more, every lesson's title in its text, figures that show
// something); and a formula that cannot be typeset stops `lesson check` at its file and line.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "support/test_paths.h"

namespace {

namespace fs = std::filesystem;
using rt::test::runCommand;

std::string readFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

std::string withoutComments(std::string html) {
  for (std::size_t at; (at = html.find("<!--")) != std::string::npos;) {
    const std::size_t end = html.find("-->", at);
    html.erase(at, end == std::string::npos ? std::string::npos : end + 3 - at);
  }
  return html;
}

// Lesson titles as the repository's lessons declare them (the book must print each).
std::vector<std::string> lessonTitles() {
  std::vector<std::string> titles;
  for (const auto& entry : fs::directory_iterator(rt::test::sourcePath("lessons"))) {
    std::ifstream in(entry.path());
    for (std::string line; std::getline(in, line);)
      if (line.rfind("title: ", 0) == 0) {
        titles.push_back(line.substr(7));
        break;
      }
  }
  return titles;
}

std::string collapseSpaces(const std::string& text) {
  return std::regex_replace(text, std::regex("\\s+"), " ");
}

// The share of clearly coloured pixels in a binary PPM (P6) picture: figures are in colour, text is not.
double colouredFraction(const fs::path& ppm) {
  std::ifstream in(ppm, std::ios::binary);
  std::string magic;
  int width = 0, height = 0, maxValue = 0;
  in >> magic >> width >> height >> maxValue;
  in.get();
  if (magic != "P6" || width <= 0 || height <= 0) return -1;
  std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 3);
  in.read(reinterpret_cast<char*>(pixels.data()), static_cast<std::streamsize>(pixels.size()));
  long coloured = 0;
  for (std::size_t i = 0; i + 2 < pixels.size(); i += 3) {
    const int r = pixels[i], g = pixels[i + 1], b = pixels[i + 2];
    if (std::max({r, g, b}) - std::min({r, g, b}) > 60) ++coloured;
  }
  return static_cast<double>(coloured) / (static_cast<double>(width) * height);
}

std::string displayPrefix() {
  if (std::getenv("DISPLAY")) return "";
  return "xvfb-run -a -s '-screen 0 1280x1024x24 -noreset' ";
}

TEST(BookCommand, WritesATypesetSiteAndAPdfOfEveryLesson) {
  if (runCommand("command -v pdftotext && command -v pdftoppm && command -v pdfinfo") != 0)
    GTEST_SKIP() << "poppler-utils (pdftotext, pdftoppm) are needed to read the PDF";
  if (!std::getenv("DISPLAY") && runCommand("command -v xvfb-run") != 0) GTEST_SKIP() << "no X server";
  const fs::path out = rt::test::scratchDir("book");
  std::string log;
  const std::string command = displayPrefix() + rt::test::cliPath() + " book --all --quick --root " +
                              rt::test::sourcePath("") + " --output " + out.string();
  int status = runCommand(command, &log);
  if (status != 0 && log.find("bad X server connection") != std::string::npos)
    status = runCommand(command, &log);
  if (status != 0 && log.find("no typesetting") != std::string::npos)
    GTEST_SKIP() << "built without typesetting";
  ASSERT_EQ(status, 0) << log;

  // The site: an index and one page per lesson, everything typeset, no address outside the site.
  const auto titles = lessonTitles();
  int pages = 0;
  for (const auto& entry : fs::directory_iterator(out)) {
    if (entry.path().extension() != ".html") continue;
    ++pages;
    const std::string html = readFile(entry.path());
    const std::string name = entry.path().filename().string();
    EXPECT_EQ(withoutComments(html).find("http://"), std::string::npos) << name;
    EXPECT_EQ(withoutComments(html).find("https://"), std::string::npos) << name;
    EXPECT_EQ(html.find("<x-equation"), std::string::npos) << name << ": maths not typeset";
    EXPECT_EQ(html.find("katex-error"), std::string::npos) << name << ": a formula failed";
    EXPECT_EQ(html.find("<script"), std::string::npos) << name << ": the pages need no script";
    if (name != "index.html") {
      EXPECT_NE(html.find("class=\"katex\""), std::string::npos) << name << " shows no maths";
      EXPECT_NE(html.find("rel=\"next\""), std::string::npos) << name;  // chapter navigation
    }
  }
  EXPECT_EQ(pages, static_cast<int>(titles.size()) + 1) << "index.html and one page per lesson";
  EXPECT_TRUE(fs::exists(out / "katex" / "katex.min.css"));
  EXPECT_TRUE(fs::exists(out / "katex" / "fonts" / "KaTeX_Main-Regular.woff2"));
  const std::string rendering = readFile(out / "rendering-equation.html");
  EXPECT_NE(rendering.find(".svg\""), std::string::npos) << "figures as SVG";
  EXPECT_NE(rendering.find("(2.1)"), std::string::npos) << "numbered equations";
  EXPECT_NE(rendering.find("href=\"#eq-rendering\""), std::string::npos) << "equation references";

  // The PDF: a page per lesson or more, every title in its text, numbered chapters.
  ASSERT_TRUE(fs::exists(out / "book.pdf"));
  std::string info;
  ASSERT_EQ(runCommand("pdfinfo " + (out / "book.pdf").string(), &info), 0) << info;
  std::smatch m;
  ASSERT_TRUE(std::regex_search(info, m, std::regex("Pages:\\s+(\\d+)"))) << info;
  const int pdfPages = std::stoi(m[1]);
  EXPECT_GE(pdfPages, static_cast<int>(titles.size()));
  std::string text;
  ASSERT_EQ(runCommand("pdftotext " + (out / "book.pdf").string() + " -", &text), 0);
  const std::string flat = collapseSpaces(text);
  for (const auto& title : titles)
    EXPECT_NE(flat.find(title), std::string::npos) << "the PDF lacks " << title;
  EXPECT_NE(flat.find("Contents"), std::string::npos);
  EXPECT_NE(flat.find("Chapter 17"), std::string::npos);
  EXPECT_NE(flat.find("Figure 5.1."), std::string::npos);

  // Its figures are not blank: every page with a figure caption has colour on it.
  const fs::path images = out / "pages";
  fs::create_directories(images);
  ASSERT_EQ(runCommand("pdftoppm -r 30 " + (out / "book.pdf").string() + " " + (images / "p").string()), 0);
  std::vector<std::string> pageTexts;
  std::stringstream pagesText(text);
  for (std::string page; std::getline(pagesText, page, '\f');) pageTexts.push_back(page);
  int figurePages = 0;
  for (std::size_t k = 0; k < pageTexts.size() && k < static_cast<std::size_t>(pdfPages); ++k) {
    if (!std::regex_search(pageTexts[k], std::regex("Figure \\d+\\.\\d+\\."))) continue;
    ++figurePages;
    char name[32];
    std::snprintf(name, sizeof name, pdfPages >= 100 ? "p-%03zu.ppm" : "p-%02zu.ppm", k + 1);
    const double coloured = colouredFraction(images / name);
    EXPECT_GT(coloured, 0.002) << "page " << k + 1 << " has a figure caption but hardly any colour";
  }
  EXPECT_GT(figurePages, static_cast<int>(titles.size()));
}

TEST(BookCommand, AFormulaThatCannotBeTypesetIsAnErrorAtItsLine) {
  const fs::path root = rt::test::scratchDir("book-bad-formula");
  fs::create_directories(root / "lessons");
  fs::create_directory_symlink(rt::test::sourcePath("scenes"), root / "scenes");
  std::ofstream(root / "lessons" / "bad.md")
      << "---\ntitle: Bad\norder: 1\n---\n\n## One\n\n```step\nstage: text\n"
         "```\n\nFine $a^2$ here.\n\nBroken $\\frac{1}{2$ here.\n";
  std::string log;
  const int status = runCommand(rt::test::cliPath() + " lesson check bad --root " + root.string(), &log);
  if (log.find("KaTeX") == std::string::npos && status == 0) GTEST_SKIP() << "built without typesetting";
  EXPECT_EQ(status, 3) << log;
  EXPECT_NE(log.find("lessons/bad.md:14: error: formula does not typeset"), std::string::npos) << log;
}

}  // namespace
