#include "app/exports.h"

#include <filesystem>
#include <fstream>
#include <regex>
#include <sstream>
#include <stdexcept>

#include "core/io/matrix_export.h"
#include "core/solvers/radiosity_system.h"
#include "viz/lesson_figures.h"

namespace rt::app {
namespace {

// "-4.28698e-06" -> "-4.28698 \times 10^{-6}"; a number without an exponent stays as it is.
std::string texNumber(const std::string& token) {
  static const std::regex scientific(R"(^\s*([-+]?[0-9.]+)[eE]([-+]?)0*([0-9]+)\s*$)");
  std::smatch m;
  if (!std::regex_match(token, m, scientific)) {
    const auto first = token.find_first_not_of(' ');
    const auto last = token.find_last_not_of(' ');
    return first == std::string::npos ? std::string() : token.substr(first, last - first + 1);
  }
  const std::string sign = m[2].str() == "-" ? "-" : "";
  return m[1].str() + " \\times 10^{" + sign + m[3].str() + "}";
}

std::string texRow(const std::string& line) {
  std::string body = line;
  std::string end;
  const auto breakAt = body.find("\\\\");
  if (breakAt != std::string::npos) {
    end = " \\\\";
    body = body.substr(0, breakAt);
  }
  std::string out = "  ";
  std::stringstream cells(body);
  std::string cell;
  bool first = true;
  while (std::getline(cells, cell, '&')) {
    out += (first ? "" : " & ") + texNumber(cell);
    first = false;
  }
  return out + end;
}

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

std::string latexDocument(const std::string& bmatrix, long long columns) {
  std::string body;
  std::stringstream lines(bmatrix);
  std::string line;
  while (std::getline(lines, line)) {
    if (line.find("\\begin{bmatrix}") != std::string::npos ||
        line.find("\\end{bmatrix}") != std::string::npos)
      body += line + "\n";
    else if (!line.empty())
      body += texRow(line) + "\n";
  }
  std::ostringstream out;
  out << "% Written by radiosity-textbook. Compile with pdflatex; the matrix alone is the bmatrix below.\n"
      << "\\documentclass{article}\n"
      << "\\usepackage[margin=1cm,landscape]{geometry}\n"
      << "\\usepackage{amsmath}\n"
      // amsmath's matrices stop at 10 columns unless told more.
      << "\\setcounter{MaxMatrixCols}{" << std::max(10LL, columns) << "}\n"
      << "\\begin{document}\n"
      << "\\tiny\n"
      << "\\setlength{\\arraycolsep}{2pt}\n"
      << "\\[\n"
      << body << "\\]\n"
      << "\\end{document}\n";
  return out.str();
}

void exportSceneFigure(const Mesh& mesh, const Camera& camera, const viz::SceneViewData& data,
                       const viz::SceneViewOptions& options, const std::string& path) {
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
                                           const std::string& format) {
  lesson::Step figures = step;
  figures.views.clear();
  for (lesson::View v : step.views)
    if (v != lesson::View::Scene) figures.views.push_back(v);
  if (figures.views.empty()) return {};
  if (figures.figure.empty()) figures.figure = lesson.id + "-figure";
  viz::StepFigureSettings settings;
  settings.width = 1200;
  settings.height = 900;
  settings.format = format;
  viz::renderStepFigures(lesson, figures, result, folder, settings);
  std::vector<std::string> paths;
  for (std::string file : figures.figureFiles())
    paths.push_back(
        (std::filesystem::path(folder) / std::filesystem::path(file).replace_extension(format)).string());
  return paths;
}

}  // namespace rt::app
