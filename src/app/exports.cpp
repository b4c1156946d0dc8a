#include "app/exports.h"

#include <stdexcept>

#include "core/io/matrix_export.h"
#include "core/solvers/radiosity_system.h"

namespace rt::app {

void exportSceneFigure(const Mesh& mesh, const Camera& camera, const viz::SceneViewData& data,
                       const viz::SceneViewOptions& options, const std::string& path) {
  viz::writeSceneFigure(mesh, camera, data, options, path);
}

void exportMatrix(const PipelineResult& result, const std::string& which, const std::string& path) {
  if (which == "B") {
    if (result.B.rows() == 0) throw std::runtime_error("there is no radiosity to export");
    const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> B = result.B;
    writeMatrix(B, path);
    return;
  }
  if (!result.F) throw std::runtime_error("this step has no form-factor matrix to export");
  if (which == "K") {
    // K for the first (red) channel, as `radiosity matrix` writes it.
    const FormFactorMatrix K = FormFactorMatrix::Identity(result.F->rows(), result.F->cols()) -
                               result.mesh->reflectance.col(0).asDiagonal() * (*result.F);
    writeMatrix(K, path);
    return;
  }
  writeMatrix(*result.F, path);
}

}  // namespace rt::app
