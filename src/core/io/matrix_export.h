// Writing matrices and vectors for homework and other tools: CSV (17 significant digits, so values
// round-trip), Matrix Market (coordinate real general; zeros omitted), NumPy .npy (little-endian float64, C
// order), LaTeX bmatrix (small matrices only: a clear InputError otherwise).
#pragma once

#include <Eigen/Core>
#include <string>

namespace rt {

enum class MatrixFormat { Csv, MatrixMarket, Npy, Latex };

// By extension: .csv, .mtx, .npy, .tex. Throws InputError naming the path for anything else.
MatrixFormat matrixFormatFromPath(const std::string& path);

using MatrixView = Eigen::Ref<const Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>>;

// Throws InputError (with the path) when the file cannot be written or the format cannot hold the matrix.
void writeMatrix(MatrixView matrix, const std::string& path, MatrixFormat format);
inline void writeMatrix(MatrixView matrix, const std::string& path) {
  writeMatrix(matrix, path, matrixFormatFromPath(path));
}
// Largest n for which LaTeX output is accepted.
constexpr int kMaxLatexSize = 20;

}  // namespace rt
