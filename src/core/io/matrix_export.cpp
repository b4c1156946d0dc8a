#include "core/io/matrix_export.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <limits>
#include <sstream>

#include "core/input_error.h"

namespace rt {

namespace {

std::string lowerExtension(const std::string& path) {
  const std::size_t slash = path.find_last_of("/\\");
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string::npos || (slash != std::string::npos && dot < slash)) return {};
  std::string ext = path.substr(dot);
  std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
  return ext;
}

// 17 significant digits is the shortest count that makes every double round-trip through text exactly.
std::string formatDouble(double v) {
  std::ostringstream s;
  s.imbue(std::locale::classic());
  s << std::setprecision(std::numeric_limits<double>::max_digits10) << v;
  return s.str();
}

std::ofstream openOrThrow(const std::string& path, std::ios::openmode mode) {
  std::ofstream out(path, mode);
  if (!out) throw InputError({path, 0, {}}, "cannot open the file for writing");
  return out;
}

void finishOrThrow(std::ofstream& out, const std::string& path) {
  out.flush();
  if (!out) throw InputError({path, 0, {}}, "writing the file failed (disk full or file not writable?)");
}

void writeCsv(MatrixView m, const std::string& path) {
  std::ofstream out = openOrThrow(path, std::ios::out | std::ios::trunc);
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (j > 0) out << ',';
      out << formatDouble(m(i, j));
    }
    out << '\n';
  }
  finishOrThrow(out, path);
}

// Matrix Market: 1-based coordinates, explicit zeros omitted (the format's "coordinate" means sparse).
void writeMatrixMarket(MatrixView m, const std::string& path) {
  std::ofstream out = openOrThrow(path, std::ios::out | std::ios::trunc);
  long nonZeros = 0;
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (m(i, j) != 0.0) ++nonZeros;
  out << "%%MatrixMarket matrix coordinate real general\n";
  out << "% written by radiosity (Radiosity Textbook)\n";
  out << m.rows() << ' ' << m.cols() << ' ' << nonZeros << '\n';
  for (Eigen::Index i = 0; i < m.rows(); ++i)
    for (Eigen::Index j = 0; j < m.cols(); ++j)
      if (m(i, j) != 0.0) out << (i + 1) << ' ' << (j + 1) << ' ' << formatDouble(m(i, j)) << '\n';
  finishOrThrow(out, path);
}

bool hostIsLittleEndian() {
  const std::uint16_t probe = 1;
  unsigned char first = 0;
  std::memcpy(&first, &probe, 1);
  return first == 1;
}

// NumPy format version 1.0: magic, version, 2-byte little-endian header length, a Python dict literal padded
// with spaces and ended by '\n' so that magic + length + header is a multiple of 64 bytes, then the raw data.
void writeNpy(MatrixView m, const std::string& path) {
  std::ofstream out = openOrThrow(path, std::ios::out | std::ios::trunc | std::ios::binary);
  std::string header = "{'descr': '<f8', 'fortran_order': False, 'shape': (" + std::to_string(m.rows()) +
                       ", " + std::to_string(m.cols()) + "), }";
  const std::size_t preamble = 6 + 2 + 2;  // magic, version, header length
  const std::size_t total = ((preamble + header.size() + 1 + 63) / 64) * 64;
  header.append(total - preamble - header.size() - 1, ' ');
  header.push_back('\n');
  if (header.size() > 65535) throw InputError({path, 0, {}}, "matrix shape too long for an .npy v1.0 header");
  const char magic[] = {'\x93', 'N', 'U', 'M', 'P', 'Y', 1, 0};
  out.write(magic, sizeof magic);
  const std::uint16_t length = static_cast<std::uint16_t>(header.size());
  const char lengthBytes[2] = {static_cast<char>(length & 0xff), static_cast<char>(length >> 8)};
  out.write(lengthBytes, 2);
  out.write(header.data(), static_cast<std::streamsize>(header.size()));
  const bool little = hostIsLittleEndian();
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      const double v = m(i, j);
      char bytes[8];
      std::memcpy(bytes, &v, 8);
      if (!little) std::reverse(bytes, bytes + 8);
      out.write(bytes, 8);
    }
  }
  finishOrThrow(out, path);
}

// A number as LaTeX math: six significant digits, and powers of ten written out (-4.28698 \times 10^{-6}),
// since "e-06" would be typeset as letters.
std::string latexNumber(double v) {
  std::ostringstream s;
  s.imbue(std::locale::classic());
  if (v == 0 || !std::isfinite(v)) {
    s << (v == 0 ? 0.0 : v);
    return s.str();
  }
  int exponent = static_cast<int>(std::floor(std::log10(std::abs(v))));
  if (exponent >= -3 && exponent < 6) {
    s << std::setprecision(6) << v;
  } else {
    double mantissa = std::round(v / std::pow(10.0, exponent) * 1e5) / 1e5;
    if (std::abs(mantissa) >= 10) mantissa /= 10, ++exponent;  // 9.999999 rounds to 10
    s << std::setprecision(6) << mantissa << " \\times 10^{" << exponent << "}";
  }
  return s.str();
}

void writeLatex(MatrixView m, const std::string& path) {
  if (m.rows() > kMaxLatexSize || m.cols() > kMaxLatexSize) {
    throw InputError({path, 0, {}},
                     "LaTeX output is limited to " + std::to_string(kMaxLatexSize) + " x " +
                         std::to_string(kMaxLatexSize) + " matrices, this one is " +
                         std::to_string(m.rows()) + " x " + std::to_string(m.cols()) +
                         "; use .csv, .mtx or .npy instead (or a coarser mesh, e.g. --no-subdivide)");
  }
  std::ofstream out = openOrThrow(path, std::ios::out | std::ios::trunc);
  // Six significant digits: a printed matrix is for reading, the other formats are for computing. amsmath's
  // bmatrix stops at 10 columns unless MaxMatrixCols says more.
  out << "% needs \\usepackage{amsmath}\n";
  if (m.cols() > 10) out << "\\setcounter{MaxMatrixCols}{" << m.cols() << "}\n";
  out << "\\begin{bmatrix}\n";
  for (Eigen::Index i = 0; i < m.rows(); ++i) {
    out << "  ";
    for (Eigen::Index j = 0; j < m.cols(); ++j) {
      if (j > 0) out << " & ";
      out << latexNumber(m(i, j));
    }
    out << (i + 1 < m.rows() ? " \\\\\n" : "\n");
  }
  out << "\\end{bmatrix}\n";
  finishOrThrow(out, path);
}

}  // namespace

MatrixFormat matrixFormatFromPath(const std::string& path) {
  const std::string ext = lowerExtension(path);
  if (ext == ".csv") return MatrixFormat::Csv;
  if (ext == ".mtx") return MatrixFormat::MatrixMarket;
  if (ext == ".npy") return MatrixFormat::Npy;
  if (ext == ".tex") return MatrixFormat::Latex;
  throw InputError({path, 0, {}},
                   "unknown matrix file extension '" + ext + "' (expected .csv, .mtx, .npy or .tex)");
}

void writeMatrix(MatrixView matrix, const std::string& path, MatrixFormat format) {
  switch (format) {
    case MatrixFormat::Csv:
      return writeCsv(matrix, path);
    case MatrixFormat::MatrixMarket:
      return writeMatrixMarket(matrix, path);
    case MatrixFormat::Npy:
      return writeNpy(matrix, path);
    case MatrixFormat::Latex:
      return writeLatex(matrix, path);
  }
  throw InputError({path, 0, {}}, "unknown matrix format");
}

}  // namespace rt
