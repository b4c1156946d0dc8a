// The lesson format: what parses, and that every mistake is reported at the right line.
#include "lesson/lesson_parser.h"

#include <gtest/gtest.h>

#include "core/input_error.h"
#include "lesson/step_runner.h"

namespace rt::lesson {
namespace {

const char* kGood = R"(---
title: Two squares
order: 3
chapter: Form factors
summary: How much one square sees of another.
---

An introduction.

## Look at the scene

```step
scene: parallel_squares.json
stage: scene
views: scene
figure: squares
```

Two squares face each other.

## The form factor

```step
scene: parallel_squares.json
stage: formfactors
method: analytic
subdivide: 2
reflectance.floor: 0.5 0.4 0.3
views: scene, formfactor
highlight: floor, 0
figure: squares-ff
controls: method, subdivide
camera.position: 0 1 5
```

F is {{F.floor.ceiling}} and
the row sums to {{rowsum[0]:.2f}}.
)";

int errorLine(const std::string& text) {
  try {
    parseLesson(text, "x", "x.md");
  } catch (const InputError& e) {
    return e.where().line;
  }
  return -1;
}

std::string errorMessage(const std::string& text) {
  try {
    parseLesson(text, "x", "x.md");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

// Replaces the first occurrence of `from` in the good lesson.
std::string goodWith(const std::string& from, const std::string& to) {
  std::string text = kGood;
  const auto pos = text.find(from);
  EXPECT_NE(pos, std::string::npos) << from;
  return text.replace(pos, from.size(), to);
}

TEST(LessonParser, ReadsHeaderStepsParametersAndText) {
  const Lesson lesson = parseLesson(kGood, "two-squares", "two-squares.md");
  EXPECT_EQ(lesson.id, "two-squares");
  EXPECT_EQ(lesson.title, "Two squares");
  EXPECT_EQ(lesson.order, 3);
  EXPECT_EQ(lesson.chapter, "Form factors");
  EXPECT_EQ(lesson.intro, "An introduction.\n");
  EXPECT_EQ(lesson.introLine, 8);
  ASSERT_EQ(lesson.steps.size(), 2u);
  const Step& a = lesson.steps[0];
  EXPECT_EQ(a.title, "Look at the scene");
  EXPECT_EQ(a.line, 10);
  EXPECT_EQ(a.stage, Stage::Scene);
  EXPECT_EQ(a.text, "Two squares face each other.\n");
  EXPECT_EQ(a.textLine, 19);
  EXPECT_EQ(a.figureFiles(), std::vector<std::string>{"squares.png"});
  const Step& b = lesson.steps[1];
  EXPECT_EQ(b.stage, Stage::FormFactors);
  EXPECT_EQ(b.parameters.method, "analytic");
  EXPECT_EQ(*b.parameters.subdivide, 2);
  EXPECT_DOUBLE_EQ(b.parameters.reflectance.at("floor")[2], 0.3);
  EXPECT_EQ(b.views, (std::vector<View>{View::Scene, View::FormFactor}));
  EXPECT_EQ(b.figureFiles(), (std::vector<std::string>{"squares-ff-scene.png", "squares-ff-formfactor.png"}));
  EXPECT_EQ(b.highlights, (std::vector<std::string>{"floor", "0"}));
  EXPECT_EQ(b.controls, (std::vector<std::string>{"method", "subdivide"}));
  EXPECT_DOUBLE_EQ((*b.camera.position)[2], 5.0);
  EXPECT_EQ(b.textLine, 36);
  EXPECT_EQ(b.fields.at("subdivide").line, 27);
}

TEST(LessonParser, ErrorsNameTheLine) {
  EXPECT_EQ(errorLine(goodWith("stage: formfactors", "stage: sorcery")), 25);
  EXPECT_NE(errorMessage(goodWith("stage: formfactors", "stage: sorcery")).find("x.md:25"),
            std::string::npos);
  EXPECT_EQ(errorLine(goodWith("views: scene, formfactor", "views: scene, teapot")), 29);
  EXPECT_EQ(errorLine(goodWith("subdivide: 2", "subdivide: two")), 27);
  EXPECT_EQ(errorLine(goodWith("subdivide: 2", "subdivide: 0")), 27);
  EXPECT_EQ(errorLine(goodWith("reflectance.floor: 0.5 0.4 0.3", "reflectance.floor: 1.5")), 28);
  EXPECT_EQ(errorLine(goodWith("reflectance.floor: 0.5 0.4 0.3", "reflectance.floor: 0.5 0.4")), 28);
  EXPECT_EQ(errorLine(goodWith("method: analytic", "method: guesswork")), 26);
  EXPECT_EQ(errorLine(goodWith("method: analytic", "colour: red")), 26);
  EXPECT_EQ(errorLine(goodWith("figure: squares-ff", "figure: Squares FF")), 31);
  EXPECT_EQ(errorLine(goodWith("order: 3", "order: third")), 3);
  EXPECT_EQ(errorLine(goodWith("chapter: Form factors", "author: me")), 4);
  EXPECT_EQ(errorLine(goodWith("controls: method, subdivide", "controls: method, figure")), 32);
  EXPECT_EQ(errorLine(goodWith("{{rowsum[0]:.2f}}", "{{rowsum[0]:fancy}}")), 37);
  EXPECT_EQ(errorLine(goodWith("{{rowsum[0]:.2f}}", "{{rowsum[0]")), 37);
  EXPECT_EQ(errorLine(goodWith("views: scene, formfactor", "views: scene, convergence")), 29);  // wrong stage
}

// A step's caption is its first figure's, with placeholders filled from the step's result; it needs a figure.
TEST(LessonParser, ACaptionBelongsToTheFirstFigureAndTakesPlaceholders) {
  const Lesson l = parseLesson(
      goodWith("figure: squares-ff\n", "figure: squares-ff\ncaption: F is {{F:.3f}}\n"), "x", "x.md");
  EXPECT_EQ(l.steps[1].caption, "F is {{F:.3f}}");
  EXPECT_EQ(l.steps[1].captionLine, 32);
  // The first view listed: the app's figures tab, which leaves the 3D scene view out, does not move the
  // caption onto the next figure.
  EXPECT_EQ(l.steps[1].captionView, View::Scene);
  StepResult r;
  r.values["F"] = 0.19982;
  EXPECT_EQ(resolvedCaption(l, l.steps[1], r), "F is 0.200");
  EXPECT_EQ(resolvedCaption(l, l.steps[0], r), "") << "no caption: the view's own title stays";
  r.values.clear();
  try {
    resolvedCaption(l, l.steps[1], r);
    ADD_FAILURE() << "an unknown placeholder in a caption is an error";
  } catch (const InputError& e) {
    EXPECT_EQ(e.where().line, 32);
  }
  EXPECT_EQ(errorLine(goodWith("figure: squares-ff\n", "figure: squares-ff\ncaption:\n")), 32);
  EXPECT_EQ(
      errorLine(goodWith("stage: scene\nviews: scene\nfigure: squares\n", "stage: scene\ncaption: Two\n")),
      15);
}

TEST(LessonParser, DuplicateFigureFilesAreRejected) {
  // Both steps would write squares.png.
  std::string text = goodWith("views: scene, formfactor", "views: formfactor");
  text = text.replace(text.find("figure: squares-ff"), 18, "figure: squares");
  EXPECT_EQ(errorLine(text), 31);
  EXPECT_NE(errorMessage(text).find("line 16"), std::string::npos);
}

TEST(LessonParser, StructuralMistakes) {
  EXPECT_EQ(errorLine("title: x\n"), 1);                                          // no header
  EXPECT_EQ(errorLine("---\ntitle: x\norder: 1\n---\n\n## Step\n\nText.\n"), 6);  // no block
  EXPECT_EQ(errorLine("---\ntitle: x\n\n"), 3);                                   // header not closed
  EXPECT_EQ(errorLine("---\norder: 1\n---\n"), 3);                                // no title
  EXPECT_EQ(errorLine("---\ntitle: x\norder: 1\n---\nno steps\n"), 5);
  EXPECT_EQ(errorLine("---\ntitle: x\norder: 1\n---\n## A\n```step\nstage: text\n"), 6);  // block not closed
  EXPECT_EQ(errorLine("---\ntitle: x\norder: 1\n---\n## A\n```step\nstage: solve\n```\n"), 7);  // no scene
  EXPECT_EQ(errorLine("---\ntitle: x\norder: 1\n---\n## A\n```step\nstage: text\nstage: text\n```\n"), 8);
  EXPECT_EQ(errorLine("---\ntitle: x\norder: 1\n---\n## A\nText first.\n```step\nstage: text\n```\n"), 7);
  EXPECT_EQ(errorLine("---\ntitle: x\norder: 1\n---\n## A\n```step\nstage: text\nviews: scene\n```\n"), 8);
  EXPECT_EQ(errorLine("---\ntitle: x\norder: 1\n---\n## A\n```step\nscene: a.json\nstage: compare\nsolvers: "
                      "jacobi\n```\n"),
            8);
  // Code fences in the text may contain '## ' lines without starting a step.
  const Lesson ok =
      parseLesson("---\ntitle: x\norder: 1\n---\n## A\n```step\nstage: text\n```\n```\n## not a step\n```\n",
                  "x", "x.md");
  EXPECT_EQ(ok.steps.size(), 1u);
}

}  // namespace
}  // namespace rt::lesson
