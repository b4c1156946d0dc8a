// Lesson maths: found as the Markdown parser finds it (never in code), numbered per chapter, referred to by
// label, and every mistake reported at its line. The shipped lessons carry the book's key equations.
#include <gtest/gtest.h>

#include <set>

#include "core/input_error.h"
#include "lesson/markdown_html.h"
#include "lesson/maths.h"
#include "lesson_test_support.h"

namespace rt::lesson {
namespace {

TEST(LessonMaths, FindsInlineAndDisplayedFormulasWithTheirLines) {
  const std::string text =
      "A value $\\rho_i$ here.\n\n$$\nB_i = E_i + \\rho_i \\sum_j F_{ij} B_j\n$$ {#eq:radiosity}\n\n"
      "Code `$x$` is not maths.\n\n```\n$$ y $$\n```\n";
  const auto formulas = findFormulas(text, 10);
  ASSERT_EQ(formulas.size(), 2u);
  EXPECT_FALSE(formulas[0].display);
  EXPECT_EQ(formulas[0].tex, "\\rho_i");
  EXPECT_EQ(formulas[0].line, 10);
  EXPECT_TRUE(formulas[1].display);
  EXPECT_EQ(formulas[1].line, 13);  // the TeX starts on the line after the opening $$
  EXPECT_EQ(formulas[1].label, "radiosity");
  EXPECT_NE(formulas[1].tex.find("F_{ij}"), std::string::npos);
}

TEST(LessonMaths, DisplayedEquationsAreNumberedByChapterAndReferencesBecomeLinks) {
  const Lesson l = test::oneStepLesson("$$ a = b $$\n\n$$ c = d $$ {#eq:second}\n\nBy @eq:second, done.\n");
  const EquationNumbers numbers = numberEquations(l);
  EXPECT_EQ(numbers.byLabel.at("second"), "4.2");
  const std::string prepared = prepareMaths(l.steps[0].text, 10, l.file, numbers);
  EXPECT_NE(prepared.find("a = b  \\tag{4.1}$$"), std::string::npos) << prepared;
  EXPECT_NE(prepared.find("\\tag{4.2}"), std::string::npos);
  EXPECT_NE(prepared.find("id=\"eq-second\""), std::string::npos);
  EXPECT_NE(prepared.find("By [(4.2)](#eq-second), done."), std::string::npos) << prepared;
  EXPECT_EQ(prepared.find("{#eq:"), std::string::npos);
  const std::string html = markdownToHtml(prepared);
  EXPECT_NE(html.find("<x-equation type=\"display\">"), std::string::npos) << html;
  EXPECT_NE(html.find("href=\"#eq-second\""), std::string::npos) << html;
}

TEST(LessonMaths, AnUnknownReferenceIsAnErrorAtItsLine) {
  const Lesson l = test::oneStepLesson("Text.\n\nSee @eq:missing.\n");
  try {
    prepareMaths(l.steps[0].text, 10, l.file, numberEquations(l));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 12);
    EXPECT_NE(std::string(e.what()).find("lessons/x.md:12: error:"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("eq:missing"), std::string::npos);
  }
}

TEST(LessonMaths, ALabelUsedTwiceIsAnError) {
  const Lesson l = test::oneStepLesson("$$ a $$ {#eq:same}\n\n$$ b $$ {#eq:same}\n");
  EXPECT_THROW(numberEquations(l), InputError);
}

TEST(LessonMaths, ADisplayCutByMarkdownIsAnErrorAtItsLine) {
  // A line of '=' under text makes a heading: the $$ would silently stay text.
  const Lesson l = test::oneStepLesson("$$\na\n=\nb\n$$\n");
  try {
    prepareMaths(l.steps[0].text, 10, l.file, numberEquations(l));
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 10);
  }
}

TEST(LessonMaths, PlaceholdersInMathsAreCheckedWithSampleNumbers) {
  const Lesson l = test::oneStepLesson("So $F = {{F.a.b:5}}$ and $p = {{x:%}}$.\n");
  const auto formulas = lessonFormulas(l);
  ASSERT_EQ(formulas.size(), 2u);
  EXPECT_EQ(formulas[0].tex, "F = 0.125");
  EXPECT_EQ(formulas[1].tex, "p = 12.5%");  // a TeX comment: the check reports it
}

TEST(LessonMaths, TheShippedLessonsCarryTheKeyEquations) {
  const std::set<std::string> key = {"rendering",        "radiosity-integral",
                                     "radiosity",        "system",
                                     "form-factor",      "lambert",
                                     "nusselt",          "delta-top",
                                     "delta-side",       "jacobi",
                                     "gauss-seidel",     "southwell",
                                     "neumann",          "raycast",
                                     "raycast-variance", "local-lines",
                                     "tone-map",         "gamma"};
  std::set<std::string> found;
  int formulas = 0;
  for (const Lesson& l : loadCatalogue(test::repoFolders())) {
    const EquationNumbers numbers = numberEquations(l);
    for (const auto& [label, number] : numbers.byLabel) {
      found.insert(label);
      EXPECT_EQ(number.rfind(std::to_string(l.order) + ".", 0), 0u) << l.id << " " << label;
    }
    // Every reference resolves and no $$ is left outside maths.
    EXPECT_NO_THROW(prepareMaths(l.intro, l.introLine, l.file, numbers)) << l.id;
    for (const Step& s : l.steps) EXPECT_NO_THROW(prepareMaths(s.text, s.textLine, l.file, numbers)) << l.id;
    const auto all = lessonFormulas(l);
    EXPECT_FALSE(all.empty()) << l.id << " has no maths";
    formulas += static_cast<int>(all.size());
  }
  for (const auto& label : key) EXPECT_TRUE(found.count(label)) << "no equation labelled eq:" << label;
  EXPECT_GT(formulas, 150);
}

}  // namespace
}  // namespace rt::lesson
