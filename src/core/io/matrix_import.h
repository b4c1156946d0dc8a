// Reading a matrix back: NumPy .npy files of doubles, as `writeMatrix` writes them (and as numpy.save writes
// a float64 array), so that a reference matrix computed once (the exact method on a fine mesh takes minutes)
// can be compared against every fast method without recomputing it.
#pragma once

#include <string>

#include <Eigen/Core>

namespace rt {

// A 2D array of little- or big-endian float64, C or Fortran order. Throws InputError naming the file for
// anything else: a missing file, another dtype or rank, a damaged header, too few bytes.
Eigen::MatrixXd readNpyMatrix(const std::string& path);

}  // namespace rt
