// Reading a matrix back: NumPy .npy files of doubles, as `writeMatrix` writes them (and as numpy.save writes
// a float64 array), and Matrix Market files (coordinate or array, real, general), so that a reference matrix
// computed once (the exact method on a fine mesh takes minutes) can be compared against every fast method
// without recomputing it. Both readers refuse, before allocating, a matrix that cannot fit in memory
// (core/memory_budget.h) and never read past the data they are given.
#pragma once

#include <string>

#include <Eigen/Core>

namespace rt {

// A 2D array of little- or big-endian float64, C or Fortran order. Throws InputError naming the file for
// anything else: a missing file, another dtype or rank, a damaged header, too few bytes.
Eigen::MatrixXd readNpyMatrix(const std::string& path);
// The same from the file's bytes; `name` only appears in messages.
Eigen::MatrixXd parseNpyMatrix(const std::string& bytes, const std::string& name);

// "%%MatrixMarket matrix coordinate real general" (entries "i j value", 1-based, absent = 0) or "... array
// real general" (column by column). Throws InputError naming the file and line: another object, field or
// symmetry, an index out of range, a missing or malformed value, more or fewer entries than announced.
Eigen::MatrixXd readMatrixMarket(const std::string& path);
Eigen::MatrixXd parseMatrixMarket(const std::string& text, const std::string& name);

// By extension: .npy or .mtx.
Eigen::MatrixXd readMatrix(const std::string& path);

}  // namespace rt
