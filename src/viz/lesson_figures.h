// The figures of a lesson step: one file per view, drawn from the step's result. The CLI (`radiosity lesson
// render`) and the app draw them through this one function, so the book and the app show the same pictures.
#pragma once

#include <string>
#include <vector>

#include "lesson/book.h"
#include "lesson/lesson.h"
#include "lesson/step_result.h"

namespace rt::viz {

struct StepFigureSettings {
  int width = 900;
  int height = 700;
  // The files' extension: "png", or "svg" / "pdf" for vectors (the 2D views are drawn as paths and text; a
  // 3D view in a PDF is a raster, and has no SVG form). The names are Step::figureFiles() with it.
  std::string format = "png";
};

// Writes the step's figures into `dir` (file names from Step::figureFiles(), extension from settings.format)
// and returns them with captions
// (paths relative to dir's parent, for the book). Throws std::runtime_error when drawing fails.
std::vector<lesson::RenderedFigure> renderStepFigures(const lesson::Lesson& lesson, const lesson::Step& step,
                                                      const lesson::StepResult& result,
                                                      const std::string& dir,
                                                      const StepFigureSettings& settings);

}  // namespace rt::viz
