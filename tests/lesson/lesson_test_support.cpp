#include "lesson_test_support.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "core/formfactor/analytic.h"
#include "core/formfactor/formfactor_method.h"
#include "core/input_error.h"
#include "lesson/lesson_parser.h"
#include "lesson/step_runner.h"
#include "support/test_paths.h"
#ifdef RT_HAVE_EXACT
#include "exact/exact_reference.h"
#endif

namespace rt::lesson::test {
namespace {

class ClosedFormMethod : public FormFactorMethod {
 public:
  std::string name() const override { return "analytic"; }
  std::string description() const override { return "closed form, unoccluded (test stand-in)"; }
  FormFactorMatrix computeMatrix(const Mesh& mesh, const FormFactorOptions&, Progress&,
                                 FormFactorStats& stats) const override {
    const auto n = static_cast<Eigen::Index>(mesh.size());
    FormFactorMatrix F = FormFactorMatrix::Zero(n, n);
    for (Eigen::Index i = 0; i < n; ++i)
      for (Eigen::Index j = 0; j < n; ++j)
        if (i != j)
          F(i, j) = polygonToPolygonFormFactor(mesh.polygon(static_cast<int>(i)),
                                               mesh.polygon(static_cast<int>(j)));
    stats.elements = mesh.size();
    return F;
  }
};

}  // namespace

LessonFolders repoFolders() {
  return foldersUnder(rt::test::sourcePath(""));
}

Lesson shippedLesson(const std::string& id) {
  const auto folders = repoFolders();
  return loadLesson(lessonPath(folders, id), folders.scenes);
}

const Step& stepWithFigure(const Lesson& lesson, const std::string& figure) {
  for (const auto& step : lesson.steps)
    if (step.figure == figure) return step;
  throw std::runtime_error("lesson " + lesson.id + " has no figure " + figure);
}

bool hasMethod(const std::string& name) {
  const auto names = formFactorMethodNames();
  return std::find(names.begin(), names.end(), name) != names.end();
}

void ensureAnalyticMethod() {
#ifdef RT_HAVE_EXACT
  if (!hasMethod("exact")) rt::exact::registerExactMethod();
#endif
  if (!hasMethod("analytic"))
    registerFormFactorMethod("analytic", [] { return std::make_unique<ClosedFormMethod>(); });
}

Lesson oneStepLesson(const std::string& text, int order) {
  Lesson l;
  l.file = "lessons/x.md";
  l.order = order;
  Step step;
  step.text = text;
  step.textLine = 10;
  l.steps.push_back(step);
  return l;
}

std::string inputErrorOf(const std::function<void()>& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

double RanStep::operator[](const std::string& name) const {
  const auto v = result.value(name);
  EXPECT_TRUE(v.has_value()) << name;
  return v.value_or(std::nan(""));
}

RanStep runShippedStep(const std::string& lesson, const std::string& figure,
                       const std::function<void(StepParameters&)>& change) {
  RanStep r{shippedLesson(lesson), {}, {}};
  r.step = stepWithFigure(r.lesson, figure);
  if (change) change(r.step.parameters);
  StepRunner runner(repoFolders().scenes);
  r.result = runner.run(r.lesson, r.step);
  EXPECT_NO_THROW(resolvedText(r.lesson, r.step, r.result));
  return r;
}

}  // namespace rt::lesson::test
