// A step's figures other than its live 3D view (hemicube, Nusselt disk, rays, matrix, charts...), drawn by
// the viz layer as the book draws them, into PNG files read back as images. Drawn in the computation's job,
// on the figure thread (app/figure_thread.h), so that the window's thread only shows them: the reader's
// control changes and the step computed ahead never stop the window while their figures are drawn.
#pragma once

#include <QImage>
#include <QSize>
#include <QString>
#include <QStringList>
#include <vector>

#include "app/pipeline.h"
#include "lesson/lesson.h"
#include "lesson/step_result.h"

namespace rt::app {

struct StepFigures {
  std::vector<QImage> images;
  QStringList files, captions;  // one per image: where it was written, its caption
  QString error;                // drawing failed (the figures tab stays empty; the window says why)
};

// The step with only the views drawn as figures (not the 3D scene view, nor the walkthrough, which is flown
// in the 3D view): its views are empty when it has no figure.
lesson::Step figureStep(const lesson::Step& step);

// Draws `step`'s figures (figureStep) from `result` into `folder` (created; one folder per call, since the
// files of the figures on screen must stay), `size` pixels each. Safe on any thread (it holds
// renderMutex()).
StepFigures drawStepFigures(const lesson::Lesson& lesson, const lesson::Step& step,
                            const lesson::StepResult& result, const QString& folder, QSize size);

// A computed lesson step's figures into result.figures, drawn with the step's `parameters` (the reader's, as
// the step ran); nothing for a step without figures. Throws Cancelled when the computation was cancelled
// before they were drawn.
void addStepFigures(PipelineResult& result, const lesson::Lesson& lesson, const lesson::Step& step,
                    const lesson::StepParameters& parameters, const QString& folder, QSize size,
                    Progress& progress);

}  // namespace rt::app
