#include "app/exports.h"

#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

#include "app/render_lock.h"
#include "core/io/matrix_export.h"
#include "core/solvers/radiosity_system.h"
#include "viz/lesson_figures.h"

namespace rt::app {
namespace {

std::string readFile(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

void writeTexMatrix(MatrixView matrix, const std::string& path) {
  writeMatrix(matrix, path);  // the core's writer: its size limit and its digits
  const std::string document = latexDocument(readFile(path), static_cast<long long>(matrix.cols()));
  std::ofstream out(path, std::ios::trunc);
  out << document;
  if (!out) throw std::runtime_error(path + ": could not be written");
}

}  // namespace

// The core writes the matrix as LaTeX (numbers as a \times 10^{b}, MaxMatrixCols where needed); the app
// wraps it into a document that compiles on its own.
std::string latexDocument(const std::string& bmatrix, long long columns) {
  const auto begin = bmatrix.find("\\begin{bmatrix}");
  const std::string lead = begin == std::string::npos ? std::string() : bmatrix.substr(0, begin);
  const std::string body = begin == std::string::npos ? bmatrix : bmatrix.substr(begin);
  std::ostringstream out;
  out << "% Written by radiosity-textbook. Compile with pdflatex; the matrix alone is the bmatrix below.\n"
      << "\\documentclass{article}\n"
      << "\\usepackage[margin=1cm,landscape]{geometry}\n"
      << "\\usepackage{amsmath}\n"
      // amsmath's matrices stop at 10 columns unless told more.
      << "\\setcounter{MaxMatrixCols}{" << std::max(10LL, columns) << "}\n"
      << "\\begin{document}\n"
      << lead << "\\tiny\n"
      << "\\setlength{\\arraycolsep}{2pt}\n"
      << "\\[\n"
      << body << "\\]\n"
      << "\\end{document}\n";
  return out.str();
}

void exportSceneFigure(const Mesh& mesh, const Camera& camera, const viz::SceneViewData& data,
                       const viz::SceneViewOptions& options, const std::string& path) {
  const std::lock_guard lock(renderMutex());
  viz::writeSceneFigure(mesh, camera, data, options, path);
}

void exportMatrix(const PipelineResult& result, const std::string& which, const std::string& path) {
  const bool tex = std::filesystem::path(path).extension() == ".tex";
  auto write = [&](const auto& matrix) {
    if (tex)
      writeTexMatrix(matrix, path);
    else
      writeMatrix(matrix, path);
  };
  if (which == "B") {
    if (result.B.rows() == 0) throw std::runtime_error("there is no radiosity to export");
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> B = result.B;
    write(B);
    return;
  }
  if (!result.F) throw std::runtime_error("this step has no form-factor matrix to export");
  if (which == "K") {
    // K for the first (red) channel, as `radiosity matrix` writes it.
    const FormFactorMatrix K = FormFactorMatrix::Identity(result.F->rows(), result.F->cols()) -
                               result.mesh->reflectance.col(0).asDiagonal() * (*result.F);
    write(K);
    return;
  }
  write(*result.F);
}

std::vector<std::string> exportStepFigures(const lesson::Lesson& lesson, const lesson::Step& step,
                                           const lesson::StepResult& result, const std::string& folder,
                                           const std::string& format, const std::string& name) {
  lesson::Step figures = step;
  figures.views.clear();
  for (lesson::View v : step.views)
    if (v != lesson::View::Scene) figures.views.push_back(v);
  if (figures.views.empty()) return {};
  if (!name.empty())
    figures.figure = name;
  else if (figures.figure.empty())
    figures.figure = lesson.id + "-figure";
  viz::StepFigureSettings settings;
  settings.width = 1200;
  settings.height = 900;
  settings.format = format;
  const std::lock_guard lock(renderMutex());
  viz::renderStepFigures(lesson, figures, result, folder, settings);
  std::vector<std::string> paths;
  for (std::string file : figures.figureFiles())
    paths.push_back(
        (std::filesystem::path(folder) / std::filesystem::path(file).replace_extension(format)).string());
  return paths;
}

}  // namespace rt::app
