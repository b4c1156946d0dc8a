// radiosity book, headless: the HTML site (a page per lesson, every equation typeset by KaTeX, nothing from
// the network) and the PDF (a page per lesson or more, every lesson's title in its text, figures that show
// something); and a formula that cannot be typeset stops `lesson check` at its file and line.
#include <gtest/gtest.h>

#include <cctype>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
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

// A shipped lesson's chapter number, its `order`: the tests name chapters, listings and equations by it.
int lessonOrder(const std::string& id) {
  std::ifstream in(rt::test::sourcePath("lessons/" + id + ".md"));
  for (std::string line; std::getline(in, line);)
    if (line.rfind("order: ", 0) == 0) return std::stoi(line.substr(7));
  return -1;
}

std::string collapseSpaces(const std::string& text) {
  return std::regex_replace(text, std::regex("\\s+"), " ");
}

// A page rendered by pdftoppm as binary PPM (P6).
struct Picture {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

Picture readPpm(const fs::path& path) {
  Picture p;
  std::ifstream in(path, std::ios::binary);
  std::string magic;
  int maxValue = 0;
  in >> magic >> p.width >> p.height >> maxValue;
  in.get();
  if (magic != "P6") return {};
  p.rgb.resize(static_cast<std::size_t>(p.width) * p.height * 3);
  in.read(reinterpret_cast<char*>(p.rgb.data()), static_cast<std::streamsize>(p.rgb.size()));
  return p;
}

// Not blank, as the lesson figures' own test has it: several colours, none covering almost everything.
bool showsSomething(const Picture& p, int x0, int y0, int x1, int y1, std::string* why) {
  std::map<int, long> counts;
  long total = 0;
  for (int y = std::max(0, y0); y < std::min(p.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(p.width, x1); ++x) {
      const std::size_t i = (static_cast<std::size_t>(y) * p.width + x) * 3;
      ++counts[(p.rgb[i] >> 3) << 10 | (p.rgb[i + 1] >> 3) << 5 | (p.rgb[i + 2] >> 3)];
      ++total;
    }
  long dominant = 0;
  for (const auto& [colour, n] : counts) dominant = std::max(dominant, n);
  *why = std::to_string(counts.size()) + " colours, the commonest on " +
         std::to_string(total ? 100 * dominant / total : 0) + " %";
  return total > 0 && counts.size() > 4 && dominant < total * 0.97;
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
  // Every displayed equation fits the printed page's text width (the printer names those that do not).
  EXPECT_EQ(log.find("wider than the text"), std::string::npos) << log;

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
      if (name != "references.html" && name != "glossary.html" && name != "term-index.html") {
        EXPECT_NE(html.find("class=\"katex\""), std::string::npos) << name << " shows no maths";
      }
      const bool navigation =
          html.find("rel=\"next\"") != std::string::npos || html.find("rel=\"prev\"") != std::string::npos;
      EXPECT_TRUE(navigation) << name << " has no chapter navigation";
    }
  }
  // The lessons' exercises are answered in an appendix page after the last lesson.
  EXPECT_TRUE(fs::exists(out / "exercise-answers.html"));
  // The works the chapters cite are listed at the back, by author.
  EXPECT_TRUE(fs::exists(out / "references.html"));
  EXPECT_TRUE(fs::exists(out / "glossary.html"));
  EXPECT_TRUE(fs::exists(out / "term-index.html"));
  EXPECT_EQ(pages, static_cast<int>(titles.size()) + 5)
      << "index.html, one page per lesson, the answers, the references, the glossary and the index";
  const std::string shooting = readFile(out / "shooting.html");
  EXPECT_NE(shooting.find("<figure class=\"algorithm\" id=\"alg-shooting\">"), std::string::npos)
      << "an algorithm listing";
  const std::string shootingListing = "Algorithm " + std::to_string(lessonOrder("shooting")) + ".1";
  EXPECT_NE(shooting.find(">" + shootingListing + "</a>"), std::string::npos) << "a reference to the listing";
  EXPECT_NE(shooting.find(">Cohen et al. 1988</a>"), std::string::npos) << "citations, author-year";
  EXPECT_NE(shooting.find(">Further reading</h2>"), std::string::npos);
  EXPECT_TRUE(fs::exists(out / "katex" / "katex.min.css"));
  EXPECT_TRUE(fs::exists(out / "katex" / "fonts" / "KaTeX_Main-Regular.woff2"));
  const std::string rendering = readFile(out / "rendering-equation.html");
  EXPECT_NE(rendering.find(".svg\""), std::string::npos) << "figures as SVG";
  EXPECT_NE(rendering.find("(" + std::to_string(lessonOrder("rendering-equation")) + ".1)"),
            std::string::npos)
      << "numbered equations";
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
  EXPECT_NE(flat.find("Chapter " + std::to_string(lessonOrder("two-solutions"))), std::string::npos);
  EXPECT_NE(flat.find("Figure " + std::to_string(lessonOrder("nusselt-analog")) + ".1."), std::string::npos);
  EXPECT_NE(flat.find("Radiosity after 1 bounce"), std::string::npos);
  EXPECT_NE(flat.find(shootingListing + " Progressive refinement"), std::string::npos);
  EXPECT_NE(flat.find("Goral, Cindy M., Kenneth E. Torrance"), std::string::npos) << "the references";
  EXPECT_EQ(flat.find("after 1 bounces"), std::string::npos) << "one bounce is singular";

  // The index: every link of the site's Index chapter lands on a marked use of its term in a chapter, and a
  // chapter's first use of a defined term links to its definition in the Glossary.
  const std::string termIndex = readFile(out / "term-index.html");
  const std::regex indexRef("<a class=\"index-ref\" href=\"([a-z0-9-]+\\.html)#([^\"]+)\">");
  int indexLinks = 0;
  for (std::sregex_iterator it(termIndex.begin(), termIndex.end(), indexRef), end; it != end;
       ++it, ++indexLinks)
    EXPECT_NE(readFile(out / (*it)[1].str()).find("id=\"" + (*it)[2].str() + "\""), std::string::npos)
        << (*it)[1] << "#" << (*it)[2] << " is not there";
  EXPECT_GT(indexLinks, 100);
  EXPECT_NE(readFile(out / "form-factor.html").find("href=\"glossary.html#gl-form-factor\""),
            std::string::npos);
  EXPECT_NE(readFile(out / "glossary.html").find("id=\"gl-form-factor\""), std::string::npos);
  // In the PDF the index gives page numbers, and each page it names has the term on it. pdftotext ends every
  // page with a form feed.
  std::vector<std::string> pageTexts;
  for (std::size_t from = 0, at; (at = text.find('\f', from)) != std::string::npos; from = at + 1)
    pageTexts.push_back(collapseSpaces(text.substr(from, at - from)));
  ASSERT_EQ(static_cast<int>(pageTexts.size()), pdfPages);
  const std::size_t indexStart = flat.rfind("Index Every term of the glossary");
  ASSERT_NE(indexStart, std::string::npos) << "the PDF has no Index chapter";
  const std::string indexText = flat.substr(indexStart);
  // Letters only, in lower case: the PDF's text breaks a term across lines and pages (with a zero-width
  // space between) and drops the hyphen of a word it hyphenated ("Gauss-Seidel" reads "GaussSeidel").
  auto lower = [](const std::string& t) {
    std::string letters;
    for (char c : t)
      if (std::isalpha(static_cast<unsigned char>(c)))
        letters += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    return letters;
  };
  const std::string glossaryFile = readFile(rt::test::sourcePath("lessons/glossary.json"));
  const std::regex termEntry("\"term\": \"([^\"]+)\"");
  const std::regex pageNumber("\\d+");
  int checkedTerms = 0;
  for (std::sregex_iterator it(glossaryFile.begin(), glossaryFile.end(), termEntry), end; it != end; ++it) {
    const std::string term = (*it)[1];
    // An entry follows a page number or the letter heading: "delta form factor 23" is not "form factor".
    // (Terms are letters, spaces, hyphens and apostrophes: literal in a regular expression.)
    const std::regex entry("(?:\\d |\\b[A-Z] )" + term + " (\\d+(?:, \\d+)*)");
    std::smatch m;
    if (!std::regex_search(indexText, m, entry)) continue;
    ++checkedTerms;
    const std::string pagesOfTerm = m[1];
    for (std::sregex_iterator p(pagesOfTerm.begin(), pagesOfTerm.end(), pageNumber), none; p != none; ++p) {
      const int page = std::stoi(p->str());
      ASSERT_GE(page, 1);
      ASSERT_LE(page, pdfPages);
      EXPECT_NE(lower(pageTexts[page - 1]).find(lower(term)), std::string::npos)
          << "the index sends '" << term << "' to page " << page << ", which does not show it";
    }
  }
  EXPECT_GT(checkedTerms, 30) << "terms found with page numbers in the PDF's index";

  // Its figures are not blank: the area just above every caption "Figure N.M." (where the figure is) shows
  // something on the rendered page. Word positions come from pdftotext -bbox, in points.
  const fs::path images = out / "pages";
  fs::create_directories(images);
  const int dpi = 36;
  ASSERT_EQ(runCommand("pdftoppm -r " + std::to_string(dpi) + " " + (out / "book.pdf").string() + " " +
                       (images / "p").string()),
            0);
  std::string boxes;
  ASSERT_EQ(runCommand("pdftotext -bbox " + (out / "book.pdf").string() + " -", &boxes), 0);
  const std::regex word(
      "<word xMin=\"([0-9.]+)\" yMin=\"([0-9.]+)\" xMax=\"([0-9.]+)\" yMax=\"([0-9.]+)\">([^<]*)</word>");
  int page = 0, figures = 0;
  std::string previous;
  double previousTop = 0;
  // Per page: its first word and how far down its text reaches (the page number at the foot aside).
  std::vector<std::string> firstWords;
  std::vector<double> textBottoms;
  const double footer = 297 / 25.4 * 72 - 24 / 25.4 * 72;  // A4, 24 mm bottom margin, in points
  const std::regex tokens("<page [^>]*>|<word [^>]*>[^<]*</word>");
  for (std::sregex_iterator it(boxes.begin(), boxes.end(), tokens), end; it != end; ++it) {
    const std::string token = it->str();
    if (token.rfind("<page", 0) == 0) {
      ++page;
      firstWords.emplace_back();
      textBottoms.push_back(0);
      continue;
    }
    std::smatch w;
    if (!std::regex_match(token, w, word)) continue;
    const std::string text = w[5];
    const double top = std::stod(w[2]);
    if (firstWords.back().empty()) firstWords.back() = text;
    if (std::stod(w[4]) < footer) textBottoms.back() = std::max(textBottoms.back(), std::stod(w[4]));
    if (previous == "Figure" && std::regex_match(text, std::regex("\\d+\\.\\d+\\.")) &&
        std::abs(top - previousTop) < 1) {
      ++figures;
      char name[32];
      std::snprintf(name, sizeof name, pdfPages >= 100 ? "p-%03d.ppm" : "p-%02d.ppm", page);
      const Picture picture = readPpm(images / name);
      ASSERT_GT(picture.width, 0) << name;
      // The figure sits centred above its caption: --quick figures are 480 x 360 CSS pixels, 360 x 270
      // points.
      const double scale = dpi / 72.0;
      std::string why;
      EXPECT_TRUE(showsSomething(
          picture, static_cast<int>(picture.width / 2 - 170 * scale), static_cast<int>((top - 270) * scale),
          static_cast<int>(picture.width / 2 + 170 * scale), static_cast<int>((top - 8) * scale), &why))
          << "figure " << text << " on page " << page << " looks blank: " << why;
    }
    previous = text;
    previousTop = top;
  }
  EXPECT_GT(figures, static_cast<int>(titles.size())) << "figure captions found in the PDF";

  // No page inside a chapter is left nearly empty: a page the chapter goes on after is filled at least a
  // third of the way down (a figure too tall for the rest of a page may leave up to about half empty).
  const double bodyTop = 20 / 25.4 * 72;
  bool inChapters = false;
  for (std::size_t p = 0; p + 1 < textBottoms.size(); ++p) {
    inChapters = inChapters || firstWords[p] == "Chapter";
    if (!inChapters || firstWords[p + 1] == "Chapter" || firstWords[p + 1].empty()) continue;
    EXPECT_GT((textBottoms[p] - bodyTop) / (footer - bodyTop), 1.0 / 3)
        << "page " << p + 1 << " is nearly empty though its chapter goes on (its text ends at "
        << textBottoms[p] << " pt)";
  }
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
