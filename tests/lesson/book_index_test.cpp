// The book's index: each section's first use of a term is marked (the chapter's first one links to the
// term's definition in the Glossary), never in code, maths or a link's text, the longer of two overlapping
// terms wins, and the Index chapter links every section using a term; in the printed book those links point
// into the one document.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>

#include "core/input_error.h"
#include "lesson/book_html.h"
#include "lesson/book_index.h"
#include "support/test_paths.h"

namespace rt::lesson {
namespace {

RenderedLesson chapter() {
  RenderedLesson a;
  a.id = "a";
  a.title = "A";
  a.order = 6;
  a.intro = "The form factor of two squares.\n";
  a.steps.push_back({"One", "Two form factors and a delta form factor.\n", {}});
  a.steps.push_back({"Two", "No term here.\n", {}});
  a.steps.push_back(
      {"Three", "`form factor` in code, $form factor$, [form factor](b.html#top), then Form Factors.\n", {}});
  return a;
}

const std::vector<GlossaryEntry> kTerms{{"form factor", "The fraction $F_{ij}$.", false},
                                        {"delta form factor", "Of one pixel.", false},
                                        {"Jacobi", "", true},
                                        {"z-buffer", "", true}};

TEST(BookIndex, MarksEachSectionsFirstUseAndLinksTheChaptersFirstToTheGlossary) {
  std::vector<RenderedLesson> chapters{chapter()};
  chapters[0].steps[1].text = "A z-buffer.\n";
  const auto index = markIndexTerms(chapters, kTerms);
  const RenderedLesson& a = chapters[0];
  EXPECT_EQ(a.intro,
            "The <a class=\"term\" id=\"ix-form-factor-6-0\" href=\"glossary.html#gl-form-factor\" "
            "title=\"The fraction F_ij.\">form factor</a> of two squares.\n")
      << "the definition shows on hover";
  EXPECT_EQ(
      a.steps[0].text,
      "Two <span class=\"term-use\" id=\"ix-form-factor-6-1\">form factors</span> and a <a class=\"term\" "
      "id=\"ix-delta-form-factor-6-1\" href=\"glossary.html#gl-delta-form-factor\" title=\"Of one "
      "pixel.\">delta form factor</a>.\n");
  EXPECT_EQ(a.steps[1].text, "A <span class=\"term-use\" id=\"ix-z-buffer-6-2\">z-buffer</span>.\n")
      << "an index-only term has no definition to link to";
  EXPECT_EQ(a.steps[2].text,
            "`form factor` in code, $form factor$, [form factor](b.html#top), then <span class=\"term-use\" "
            "id=\"ix-form-factor-6-3\">Form Factors</span>.\n");

  ASSERT_EQ(index.size(), 3u) << "Jacobi is never used";
  EXPECT_EQ(index[0].term, "delta form factor");
  EXPECT_EQ(index[1].term, "form factor");
  EXPECT_EQ(index[2].term, "z-buffer");
  EXPECT_FALSE(index[2].defined);
  ASSERT_EQ(index[1].locators.size(), 3u);
  EXPECT_EQ(index[1].locators[0].label, "6");
  EXPECT_EQ(index[1].locators[1].label, "6.1");
  EXPECT_EQ(index[1].locators[2].label, "6.3");

  const std::string html = indexHtml(index);
  EXPECT_NE(
      html.find(
          "<p class=\"index-entry\"><span class=\"index-term\"><a href=\"glossary.html#gl-form-"
          "factor\">form factor</a></span> <a class=\"index-ref\" href=\"a.html#ix-form-factor-6-0\">6</a>, "
          "<a class=\"index-ref\" href=\"a.html#ix-form-factor-6-1\">6.1</a>, "),
      std::string::npos)
      << html;
  EXPECT_NE(html.find("<span class=\"index-term\">z-buffer</span>"), std::string::npos) << html;
  EXPECT_NE(html.find("<h3 class=\"index-letter\">D</h3>"), std::string::npos) << html;
  EXPECT_EQ(html.find("\n\n"), std::string::npos) << "a blank line would end the HTML block";
}

// A page that stands alone, as the app's text pane shows a step: each defined term's first use on the page
// links to its definition listed under it, with the definition as the link's title.
TEST(BookIndex, APageLinksItsFirstUsesToDefinitionsListedUnderIt) {
  std::vector<const GlossaryEntry*> linked;
  const std::string text = linkTermsToDefinitions(
      "Two form factors, a z-buffer and a delta form factor; `form factor` and one more form factor.\n",
      kTerms, linked);
  EXPECT_EQ(text,
            "Two <a class=\"term\" href=\"#gl-form-factor\" title=\"The fraction F_ij.\">form factors</a>, a "
            "z-buffer and a <a class=\"term\" href=\"#gl-delta-form-factor\" title=\"Of one pixel.\">delta "
            "form factor</a>; `form factor` and one more form factor.\n")
      << "the first use only, never an index-only term";
  ASSERT_EQ(linked.size(), 2u);
  EXPECT_EQ(linked[0]->term, "form factor") << "in the order of the text";
  EXPECT_EQ(linked[1]->term, "delta form factor");
  const std::string html = termDefinitionsHtml(linked, 3);
  EXPECT_EQ(html.rfind("<h3 class=\"terms\">Terms</h3>", 0), 0u) << html;
  EXPECT_NE(
      html.find("<p class=\"glossary\" id=\"gl-form-factor\"><b>form factor</b>: The fraction "
                "<x-equation>F_{ij}</x-equation>.</p>\n<p class=\"glossary\" id=\"gl-delta-form-factor\">"),
      std::string::npos)
      << html;
  EXPECT_EQ(html.find("\n\n", html.find("</h3>") + 7), std::string::npos) << "one HTML block";
  EXPECT_EQ(termDefinitionsHtml({}, 3), "");
}

TEST(BookIndex, InThePrintedBookTheLinksPointIntoTheOneDocument) {
  std::vector<RenderedLesson> chapters{chapter()};
  const auto index = markIndexTerms(chapters, kTerms);
  RenderedLesson glossary;
  glossary.id = "glossary";
  glossary.title = "Glossary";
  glossary.order = 7;
  glossary.intro = "<p class=\"glossary\" id=\"gl-form-factor\"><b>form factor</b>: F.</p>\n";
  RenderedLesson terms;
  terms.id = "term-index";
  terms.title = "Index";
  terms.order = 8;
  terms.intro = indexHtml(index);
  chapters.push_back(glossary);
  chapters.push_back(terms);
  const std::string print = printBookHtml(chapters);
  EXPECT_NE(print.find("id=\"c6-ix-form-factor-6-1\""), std::string::npos);
  EXPECT_NE(print.find("class=\"index-ref\" href=\"#c6-ix-form-factor-6-1\""), std::string::npos);
  EXPECT_NE(print.find("href=\"#c7-gl-form-factor\""), std::string::npos) << "a first use to its definition";
  EXPECT_NE(print.find("id=\"c7-gl-form-factor\""), std::string::npos);
  // The site's pages keep their own anchors.
  const std::string page = lessonPageHtml(chapters[0], chapters);
  EXPECT_NE(page.find("id=\"ix-form-factor-6-1\""), std::string::npos);
  EXPECT_NE(page.find("href=\"glossary.html#gl-form-factor\""), std::string::npos);
}

TEST(BookIndex, IndexOnlyTermsHaveNoDefinitionAndAreNotInTheGlossary) {
  const std::string dir = rt::test::scratchDir("book-index-glossary");
  const std::string path = dir + "/glossary.json";
  std::ofstream(path)
      << R"([{"term": "form factor", "definition": "F."}, {"term": "Jacobi", "index-only": true}])";
  const auto entries = loadGlossary(path);
  ASSERT_EQ(entries.size(), 2u);
  EXPECT_TRUE(entries[1].indexOnly);
  EXPECT_EQ(glossaryHtml(entries, {}).find("Jacobi"), std::string::npos);
  std::ofstream(path) << R"([{"term": "Jacobi", "index-only": true, "definition": "A sweep."}])";
  try {
    loadGlossary(path);
    ADD_FAILURE() << "an index-only term with a definition";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("/0"), std::string::npos) << e.what();
  }
  std::ofstream(path) << R"([{"term": "Jacobi"}])";
  EXPECT_THROW(loadGlossary(path), InputError) << "neither a definition nor index-only";
}

}  // namespace
}  // namespace rt::lesson
