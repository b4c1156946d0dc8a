// The book's apparatus: the bibliography (CSL-JSON), citations [@key] rendered author-year with the full
// entry on hover, and ```pseudocode listings numbered per chapter and referred to as @alg:id. Every mistake
// is reported at its line; the shipped bibliography is all cited, every citation resolves, and every listing
// line that names the code names a function that is there.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

#include "core/input_error.h"
#include "lesson/book_html.h"
#include "lesson/citations.h"
#include "lesson/glossary.h"
#include "lesson/markdown_html.h"
#include "lesson/pseudocode.h"
#include "lesson/text_apparatus.h"
#include "lesson_test_support.h"
#include "support/test_paths.h"

namespace rt::lesson {
namespace {

const char* kSmallBibliography = R"json([
 {"id": "kajiya1986", "type": "paper-conference", "author": [{"family": "Kajiya", "given": "James T."}],
  "issued": {"date-parts": [[1986]]}, "title": "The rendering equation",
  "container-title": "Computer Graphics (Proceedings of SIGGRAPH 86)", "volume": "20", "issue": "4",
  "page": "143-150", "DOI": "10.1145/15922.15902"},
 {"id": "cohen1993", "type": "book", "author": [{"family": "Cohen", "given": "Michael F."},
  {"family": "Wallace", "given": "John R."}], "issued": {"date-parts": [[1993]]},
  "title": "Radiosity and Realistic Image Synthesis", "publisher": "Academic Press Professional"},
 {"id": "goral1984", "type": "paper-conference", "author": [{"family": "Goral"}, {"family": "Torrance"},
  {"family": "Greenberg"}], "issued": {"date-parts": [[1984]]}, "title": "Modeling \"light\""},
 {"id": "sbert1997", "type": "thesis", "author": [{"family": "Sbert"}], "issued": {"date-parts": [[1997]]},
  "title": "B title"},
 {"id": "sbert1997b", "type": "thesis", "author": [{"family": "Sbert"}], "issued": {"date-parts": [[1997]]},
  "title": "A title"}
])json";

TEST(Bibliography, LabelsAreAuthorYearAndEntriesAreComplete) {
  const Bibliography b = parseBibliography(kSmallBibliography, "refs.json");
  ASSERT_EQ(b.entries.size(), 5u);
  EXPECT_EQ(b.find("kajiya1986")->label, "Kajiya 1986");
  EXPECT_EQ(b.find("cohen1993")->label, "Cohen and Wallace 1993");
  EXPECT_EQ(b.find("goral1984")->label, "Goral et al. 1984");
  // Two entries that would read alike get a letter, in the order of their titles.
  EXPECT_EQ(b.find("sbert1997b")->label, "Sbert 1997a");
  EXPECT_EQ(b.find("sbert1997")->label, "Sbert 1997b");
  EXPECT_EQ(
      entryText(*b.find("kajiya1986")),
      "Kajiya, James T. 1986. The rendering equation. In Computer Graphics (Proceedings of SIGGRAPH 86) "
      "20(4): 143\u2013150. doi:10.1145/15922.15902");
  EXPECT_EQ(entryText(*b.find("cohen1993")),
            "Cohen, Michael F. and John R. Wallace. 1993. Radiosity and Realistic Image Synthesis. Academic "
            "Press Professional.");
  const std::string html = entryHtml(*b.find("kajiya1986"));
  EXPECT_NE(html.find("<i>Computer Graphics (Proceedings of SIGGRAPH 86)</i>"), std::string::npos) << html;
  EXPECT_NE(html.find("doi:10.1145/15922.15902"), std::string::npos) << html;
  EXPECT_EQ(html.find("http"), std::string::npos) << "the book links to nothing outside it";
  EXPECT_NE(entryHtml(*b.find("goral1984")).find("Modeling &quot;light&quot;"), std::string::npos);
}

TEST(Bibliography, ReferenceListsAreSortedByAuthorAndAnchored) {
  const Bibliography b = parseBibliography(kSmallBibliography, "refs.json");
  const auto sorted = sortedEntries(b, {"kajiya1986", "goral1984", "cohen1993", "unknown", "goral1984"});
  ASSERT_EQ(sorted.size(), 3u);
  EXPECT_EQ(sorted[0]->key, "cohen1993");
  EXPECT_EQ(sorted[1]->key, "goral1984");
  EXPECT_EQ(sorted[2]->key, "kajiya1986");
  const std::string list = referenceListHtml(sorted);
  EXPECT_EQ(list.find("\n\n"), std::string::npos) << "a blank line would end the HTML block";
  EXPECT_NE(list.find("<p class=\"reference\" id=\"ref-cohen1993\">"), std::string::npos) << list;
}

TEST(Bibliography, MistakesNameTheFileAndTheEntry) {
  EXPECT_NE(test::inputErrorOf([] {
              parseBibliography("[{\"id\": \"x\", \"title\": \"t\", \"author\": [{\"family\": \"A\"}]}]",
                                "r.json");
            }).find("r.json at /0: error: no year"),
            std::string::npos);
  EXPECT_NE(test::inputErrorOf([] { parseBibliography("[\n{\"id\": }\n]", "r.json"); }).find("r.json:2:"),
            std::string::npos);
  EXPECT_NE(test::inputErrorOf([] {
              parseBibliography("[{\"id\": \"x\", \"title\": \"t\", \"issued\": {\"date-parts\": [[1990]]}}]",
                                "r.json");
            }).find("has no \"author\""),
            std::string::npos);
}

TEST(Citations, AreFoundInTextButNotInCodeOrMaths) {
  const std::string text =
      "As shown [@kajiya1986] and [@goral1984, p. 215; @cohen1993].\n\nCode `[@nope]` and $[@x]$ are not.\n";
  const auto found = findCitations(text, 20, "l.md");
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].line, 20);
  ASSERT_EQ(found[1].works.size(), 2u);
  EXPECT_EQ(found[1].works[0].key, "goral1984");
  EXPECT_EQ(found[1].works[0].locator, "p. 215");
  EXPECT_EQ(found[1].works[1].key, "cohen1993");
}

TEST(Citations, BecomeAuthorYearLinksWithTheEntryAsTitle) {
  const Bibliography b = parseBibliography(kSmallBibliography, "refs.json");
  const std::string prepared = prepareCitations("See [@goral1984, p. 215; @cohen1993].\n", 1, "l.md", b);
  EXPECT_NE(prepared.find("See ([Goral et al. 1984, p. 215](#ref-goral1984 \"Goral, Torrance and Greenberg. "
                          "1984. Modeling \\\"light\\\".\"); [Cohen and Wallace 1993](#ref-cohen1993 "),
            std::string::npos)
      << prepared;
  const std::string html = markdownToHtml(prepared);
  EXPECT_NE(html.find("<a href=\"#ref-cohen1993\" title=\"Cohen, Michael F. and John R. Wallace. 1993."),
            std::string::npos)
      << html;
  EXPECT_NE(html.find(">Goral et al. 1984, p. 215</a>"), std::string::npos) << html;
}

TEST(Citations, UnknownOrMalformedOnesAreErrorsAtTheirLines) {
  const Bibliography b = parseBibliography(kSmallBibliography, "refs.json");
  EXPECT_NE(test::inputErrorOf([&] {
              prepareCitations("One.\n\nSee [@whitted1980].\n", 7, "l.md", b);
            }).find("l.md:9: error: citation of an unknown work '@whitted1980'"),
            std::string::npos);
  EXPECT_NE(test::inputErrorOf([&] { findCitations("x [@a; b] y\n", 3, "l.md"); }).find("l.md:3:"),
            std::string::npos);
  EXPECT_NE(test::inputErrorOf([&] { findCitations("x [@a\ny]\n", 3, "l.md"); }).find("not closed"),
            std::string::npos);
}

const std::string kListing =
    "Text, see @alg:sweep.\n\n```pseudocode\nid: sweep\ncaption: One sweep of $B$\n"
    "$B \\gets E$   // core/solvers/gathering_solvers.cpp: iterate()\n"
    "for each element $i$ do\n  $B_i \\gets E_i$\nreturn $B$\n```\n\nAfter.\n";

TEST(Pseudocode, ListingsAreParsedWithTheirLinesIndentationAndSources) {
  const auto listings = findPseudocode(kListing, 10, "l.md");
  ASSERT_EQ(listings.size(), 1u);
  const Pseudocode& p = listings[0];
  EXPECT_EQ(p.id, "sweep");
  EXPECT_EQ(p.caption, "One sweep of $B$");
  EXPECT_EQ(p.line, 12);
  ASSERT_EQ(p.lines.size(), 4u);
  EXPECT_EQ(p.lines[0].source, "core/solvers/gathering_solvers.cpp: iterate()");
  EXPECT_EQ(p.lines[0].code, "$B \\gets E$");
  EXPECT_EQ(p.lines[0].line, 15);
  EXPECT_EQ(p.lines[2].indent, 1);
  EXPECT_EQ(p.lines[2].code, "$B_i \\gets E_i$");
}

TEST(Pseudocode, ListingsAreNumberedAndReferencesBecomeLinks) {
  const Lesson l = test::oneStepLesson(kListing);
  const AlgorithmNumbers numbers = numberAlgorithms(l);
  EXPECT_EQ(numbers.at("sweep"), "4.1");
  const std::string prepared = preparePseudocode(kListing, 10, l.file, numbers);
  EXPECT_NE(prepared.find("Text, see [Algorithm 4.1](#alg-sweep)."), std::string::npos) << prepared;
  const std::string html = markdownToHtml(prepared);
  EXPECT_NE(html.find("<figure class=\"algorithm\" id=\"alg-sweep\"><figcaption><b>Algorithm 4.1</b> One "
                      "sweep of <x-equation>B</x-equation></figcaption>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("<td class=\"alg-number\">4</td>"), std::string::npos) << html;
  EXPECT_NE(html.find("<b>for</b> <b>each</b> element <x-equation>i</x-equation> <b>do</b>"),
            std::string::npos)
      << html;
  EXPECT_NE(html.find("padding-left: calc(1 * 1.5em + 1em)"), std::string::npos);
  EXPECT_NE(
      html.find(
          // The narrow column of notes breaks a name after an underscore or between camel-case words only.
          "title=\"src/core/solvers/gathering_solvers.cpp: "
          "iterate()\">gathering_<wbr>solvers.cpp<br>iterate()"),
      std::string::npos)
      << html;
  EXPECT_NE(html.find("<p>After.</p>"), std::string::npos) << "the text after the listing is Markdown again";
  const auto formulas = algorithmFormulas(l);
  ASSERT_EQ(formulas.size(), 5u);  // the caption's and the lines'
  EXPECT_EQ(formulas[1].tex, "B \\gets E");
  EXPECT_EQ(formulas[1].line, 15);
}

TEST(Pseudocode, MistakesAreErrorsAtTheirLines) {
  const Lesson l = test::oneStepLesson(kListing);
  EXPECT_NE(test::inputErrorOf([&] {
              preparePseudocode("See @alg:other.\n", 10, l.file, numberAlgorithms(l));
            }).find("lessons/x.md:10: error: reference to an unknown algorithm '@alg:other'"),
            std::string::npos);
  EXPECT_NE(test::inputErrorOf([] {
              findPseudocode("\n```pseudocode\ncaption: c\nx\n```\n", 1, "l.md");
            }).find("l.md:2: error: a ```pseudocode block starts with 'id: name'"),
            std::string::npos);
  EXPECT_NE(test::inputErrorOf([] {
              findPseudocode("```pseudocode\nid: a\ncaption: c\nx $y\n```\n", 1, "l.md");
            }).find("l.md:4:"),
            std::string::npos);
  EXPECT_NE(test::inputErrorOf([] {
              numberAlgorithms(test::oneStepLesson(kListing + kListing));
            }).find("used twice"),
            std::string::npos);
}

TEST(Apparatus, ThePrintedBookKeepsEachChaptersAnchorsApart) {
  RenderedLesson l;
  l.id = "x";
  l.title = "X";
  l.order = 3;
  l.steps.push_back({"S", "See [Algorithm 3.1](#alg-a) and [Kajiya 1986](#ref-k).\n", {}});
  l.furtherReading = "<ul class=\"references\">\n<li id=\"ref-k\">K.</li>\n</ul>\n";
  const std::string html = printBookHtml({l});
  EXPECT_NE(html.find("href=\"#c3-alg-a\""), std::string::npos);
  EXPECT_NE(html.find("href=\"#c3-ref-k\""), std::string::npos);
  EXPECT_NE(html.find("<li id=\"c3-ref-k\">"), std::string::npos);
  EXPECT_NE(html.find(">Further reading</h2>"), std::string::npos);
}

TEST(Glossary, TermsLinkToTheirFirstUseInBookOrder) {
  Lesson a = test::oneStepLesson("No term here, but `form factor` in code and $form factor$ in maths.\n", 2);
  a.id = "a";
  Lesson b = test::oneStepLesson("Two form factors.\n", 3);
  b.id = "b";
  b.steps[0].title = "Pairs";
  const std::vector<Lesson> lessons{a, b};
  const auto use = firstUse("form factor", lessons);
  ASSERT_TRUE(use.has_value());
  EXPECT_EQ(use->lesson->id, "b");
  EXPECT_EQ(use->section, 1);
  EXPECT_FALSE(firstUse("factorial", lessons).has_value());
  const std::string html = glossaryHtml({{"form factor", "The fraction $F_{ij}$."}}, {a, b});
  EXPECT_EQ(
      html,
      "<p class=\"glossary\" id=\"gl-form-factor\"><b>form factor</b>: The fraction "
      "<x-equation>F_{ij}</x-equation>. First used in <a href=\"b.html#s3-1\">section 3.1, Pairs</a>.</p>\n");
  // In the printed book the link points into the one document.
  RenderedLesson page;
  page.id = "b";
  page.order = 3;
  page.title = "B";
  RenderedLesson terms;
  terms.id = "glossary";
  terms.order = 4;
  terms.title = "Glossary";
  terms.intro = html;
  EXPECT_NE(printBookHtml({page, terms}).find("href=\"#c3-s3-1\""), std::string::npos);
}

// The shipped lessons and their bibliography.

std::string fileText(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

TEST(ShippedApparatus, EveryEntryIsCitedAndEveryCitationResolves) {
  const auto folders = test::repoFolders();
  const Bibliography b = loadBibliography(bibliographyPath(folders.lessons));
  EXPECT_GE(b.entries.size(), 25u);
  std::set<std::string> cited;
  for (const auto& file : lessonFiles(folders.lessons)) {
    const Lesson l = loadLesson(file, folders.scenes);
    EXPECT_TRUE(textProblems(l).empty())
        << l.id << ": " << (textProblems(l).empty() ? "" : textProblems(l)[0]);
    for (const auto& key : citedKeys(l)) {
      EXPECT_NE(b.find(key), nullptr) << l.id << " cites an unknown work " << key;
      cited.insert(key);
    }
  }
  for (const Reference& r : b.entries) EXPECT_TRUE(cited.count(r.key)) << r.key << " is cited nowhere";
}

TEST(ShippedApparatus, EveryGlossaryTermIsUsedInTheBook) {
  const auto folders = test::repoFolders();
  const auto glossary = loadGlossary(glossaryPath(folders.lessons));
  EXPECT_GE(glossary.size(), 20u);
  const std::vector<Lesson> lessons = loadCatalogue(folders);
  for (const GlossaryEntry& e : glossary) EXPECT_TRUE(firstUse(e.term, lessons).has_value()) << e.term;
  const std::string html = glossaryHtml(glossary, lessons);
  EXPECT_NE(html.find("id=\"gl-radiosity\""), std::string::npos);
  EXPECT_EQ(html.find("\n\n"), std::string::npos) << "a blank line would end the HTML block";
}

TEST(ShippedApparatus, TheAlgorithmChaptersListTheirAlgorithmsAndNameCodeThatExists) {
  const std::map<std::string, std::vector<std::string>> expected{
      {"gathering", {"jacobi", "gauss-seidel"}},
      {"shooting", {"shooting"}},
      {"hemicube", {"hemicube"}},
      {"ray-casting", {"local-lines"}},
      {"meshing", {"adaptive"}},
      {"hierarchical", {"hierarchical"}},
      {"stochastic", {"stochastic-jacobi", "random-walk"}},
      {"two-solutions", {"two-pass"}}};
  for (const auto& [id, algorithms] : expected) {
    const Lesson l = test::shippedLesson(id);
    const AlgorithmNumbers numbers = numberAlgorithms(l);
    for (const auto& a : algorithms) EXPECT_TRUE(numbers.count(a)) << id << " has no listing " << a;
  }
  // Every "// file: function()" note names a file under src/ that has the function.
  int notes = 0;
  for (const auto& file : lessonFiles(test::repoFolders().lessons)) {
    const Lesson l = loadLesson(file, test::repoFolders().scenes);
    std::vector<std::pair<std::string, int>> texts{{l.intro, l.introLine}};
    for (const Step& s : l.steps) texts.emplace_back(s.text, s.textLine);
    for (const auto& [text, line] : texts)
      for (const Pseudocode& p : findPseudocode(text, line, l.file))
        for (const PseudocodeLine& pl : p.lines) {
          if (pl.source.empty()) continue;
          ++notes;
          const auto colon = pl.source.find(": ");
          ASSERT_NE(colon, std::string::npos) << l.file << ":" << pl.line << ": 'file: function()' expected";
          const std::string path = rt::test::sourcePath("src/" + pl.source.substr(0, colon));
          ASSERT_TRUE(std::filesystem::is_regular_file(path)) << l.file << ":" << pl.line << ": no " << path;
          std::string function = pl.source.substr(colon + 2);
          function = function.substr(0, function.find('('));
          EXPECT_NE(fileText(path).find(function + "("), std::string::npos)
              << l.file << ":" << pl.line << ": " << path << " has no " << function;
        }
  }
  EXPECT_GE(notes, 20);
}

}  // namespace
}  // namespace rt::lesson
