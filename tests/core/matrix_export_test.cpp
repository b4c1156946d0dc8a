#include "core/io/matrix_export.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "core/input_error.h"
#include "support/test_paths.h"

namespace rt {
namespace {

using RowMatrix = Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor>;

std::string readAll(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Values chosen so that fewer than 17 digits would lose bits: 0.1+0.2, 1/3, pi-ish, tiny and huge, negative
// zero.
RowMatrix awkwardMatrix() {
  RowMatrix m(3, 4);
  m << 0.1 + 0.2, 1.0 / 3.0, 3.141592653589793, -2.5e-300,  //
      1e300, 0.0, -0.0, 0.19982489569838738,                //
      0.20004377607540316, 123456789.12345678, -1.0 / 7.0, 5e-324;
  return m;
}

TEST(MatrixExport, FormatFromExtension) {
  EXPECT_EQ(matrixFormatFromPath("a/K.csv"), MatrixFormat::Csv);
  EXPECT_EQ(matrixFormatFromPath("K.MTX"), MatrixFormat::MatrixMarket);
  EXPECT_EQ(matrixFormatFromPath("K.npy"), MatrixFormat::Npy);
  EXPECT_EQ(matrixFormatFromPath("K.tex"), MatrixFormat::Latex);
  EXPECT_THROW(matrixFormatFromPath("K.xlsx"), InputError);
  EXPECT_THROW(matrixFormatFromPath("dir.csv/K"), InputError);
  try {
    matrixFormatFromPath("out/K.txt");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("out/K.txt"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find(".csv"), std::string::npos);
  }
}

TEST(MatrixExport, CsvRoundTripsBitExact) {
  const RowMatrix m = awkwardMatrix();
  const std::string path = test::scratchDir("matrix_export_csv") + "/m.csv";
  writeMatrix(m, path);
  std::istringstream in(readAll(path));
  std::string line;
  int row = 0;
  while (std::getline(in, line)) {
    std::istringstream cells(line);
    std::string cell;
    int col = 0;
    while (std::getline(cells, cell, ',')) {
      // strtod, not stod: stod rejects subnormals such as 5e-324 with out_of_range.
      const double v = std::strtod(cell.c_str(), nullptr);
      std::uint64_t a = 0, b = 0;
      const double expected = m(row, col);
      std::memcpy(&a, &v, 8);
      std::memcpy(&b, &expected, 8);
      EXPECT_EQ(a, b) << "row " << row << " col " << col << " text '" << cell << "'";
      ++col;
    }
    EXPECT_EQ(col, m.cols());
    ++row;
  }
  EXPECT_EQ(row, m.rows());
}

TEST(MatrixExport, NpyHeaderAndData) {
  const RowMatrix m = awkwardMatrix();
  const std::string path = test::scratchDir("matrix_export_npy") + "/m.npy";
  writeMatrix(m, path);
  const std::string bytes = readAll(path);
  ASSERT_GE(bytes.size(), 10u);
  EXPECT_EQ(bytes.substr(0, 6), std::string("\x93NUMPY"));
  EXPECT_EQ(bytes[6], 1);  // version 1.0
  EXPECT_EQ(bytes[7], 0);
  const std::size_t headerLength = static_cast<unsigned char>(bytes[8]) |
                                   (static_cast<std::size_t>(static_cast<unsigned char>(bytes[9])) << 8);
  EXPECT_EQ((10 + headerLength) % 64, 0u) << "data must start on a 64-byte boundary";
  const std::string header = bytes.substr(10, headerLength);
  EXPECT_EQ(header.back(), '\n');
  EXPECT_NE(header.find("'descr': '<f8'"), std::string::npos) << header;
  EXPECT_NE(header.find("'fortran_order': False"), std::string::npos) << header;
  EXPECT_NE(header.find("'shape': (3, 4)"), std::string::npos) << header;
  ASSERT_EQ(bytes.size(), 10 + headerLength + 8 * 12);
  // C order: row after row. The test machine is little-endian like the file.
  for (int k = 0; k < 12; ++k) {
    double v = 0;
    std::memcpy(&v, bytes.data() + 10 + headerLength + 8 * k, 8);
    const double expected = m(k / 4, k % 4);
    EXPECT_EQ(std::memcmp(&v, &expected, 8), 0) << k;
  }
}

TEST(MatrixExport, MatrixMarketReadable) {
  RowMatrix m = RowMatrix::Zero(3, 3);
  m(0, 0) = 1.0;
  m(1, 2) = -0.19982489569838738;
  m(2, 1) = 1.0 / 3.0;
  const std::string path = test::scratchDir("matrix_export_mtx") + "/m.mtx";
  writeMatrix(m, path);
  std::istringstream in(readAll(path));
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "%%MatrixMarket matrix coordinate real general");
  while (std::getline(in, line) && !line.empty() && line[0] == '%') {
  }
  std::istringstream sizes(line);
  long rows = 0, cols = 0, entries = 0;
  sizes >> rows >> cols >> entries;
  EXPECT_EQ(rows, 3);
  EXPECT_EQ(cols, 3);
  ASSERT_EQ(entries, 3);
  RowMatrix back = RowMatrix::Zero(3, 3);
  for (long k = 0; k < entries; ++k) {
    long i = 0, j = 0;
    double v = 0;
    in >> i >> j >> v;
    ASSERT_TRUE(in) << "entry " << k;
    ASSERT_GE(i, 1);
    ASSERT_GE(j, 1);
    back(i - 1, j - 1) = v;
  }
  EXPECT_EQ(back, m);
}

TEST(MatrixExport, LatexSmallMatrix) {
  RowMatrix m(2, 2);
  m << 1, -0.5, 0.25, 1;
  const std::string path = test::scratchDir("matrix_export_tex") + "/m.tex";
  writeMatrix(m, path);
  EXPECT_EQ(readAll(path),
            "% needs \\usepackage{amsmath}\n\\begin{bmatrix}\n  1 & -0.5 \\\\\n  0.25 & 1\n\\end{bmatrix}\n");
}

// Any size the export allows compiles: more than 10 columns set MaxMatrixCols, and small numbers are written
// as powers of ten (LaTeX would typeset "e-06" as letters). With pdflatex installed the file is compiled.
TEST(MatrixExport, LatexOfTwentyColumnsAndTinyNumbersCompiles) {
  RowMatrix m = RowMatrix::Identity(20, 20);
  m(0, 1) = -4.28698e-06;
  m(1, 0) = 9.9999999e-7;
  const std::string dir = test::scratchDir("matrix_export_tex_20");
  writeMatrix(m, dir + "/m.tex");
  const std::string tex = readAll(dir + "/m.tex");
  EXPECT_NE(tex.find("\\setcounter{MaxMatrixCols}{20}"), std::string::npos) << tex;
  EXPECT_NE(tex.find("-4.28698 \\times 10^{-6}"), std::string::npos) << tex;
  EXPECT_NE(tex.find("1 \\times 10^{-6}"), std::string::npos) << tex;
  EXPECT_EQ(tex.find("e-"), std::string::npos) << tex;
  if (test::runCommand("command -v pdflatex > /dev/null") != 0)
    return;  // the preamble above is what it needs
  std::ofstream doc(dir + "/doc.tex");
  doc << "\\documentclass{article}\\usepackage{amsmath}\\usepackage[margin=5mm,landscape]{geometry}"
         "\\begin{document}\\tiny\\[\\input{m.tex}\\]\\end{document}\n";
  doc.close();
  std::string log;
  EXPECT_EQ(
      test::runCommand("cd " + dir + " && pdflatex -interaction=nonstopmode -halt-on-error doc.tex", &log), 0)
      << log;
}

TEST(MatrixExport, LatexRefusesLargeMatrixWithClearMessage) {
  const RowMatrix ok = RowMatrix::Identity(kMaxLatexSize, kMaxLatexSize);
  const std::string dir = test::scratchDir("matrix_export_tex_large");
  EXPECT_NO_THROW(writeMatrix(ok, dir + "/ok.tex"));
  const RowMatrix big = RowMatrix::Identity(kMaxLatexSize + 1, kMaxLatexSize + 1);
  try {
    writeMatrix(big, dir + "/big.tex");
    FAIL() << "expected InputError";
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("big.tex"), std::string::npos) << what;
    EXPECT_NE(what.find("21 x 21"), std::string::npos) << what;
    EXPECT_NE(what.find("20"), std::string::npos) << what;
  }
}

TEST(MatrixExport, UnwritablePathIsInputError) {
  const RowMatrix m = RowMatrix::Identity(2, 2);
  EXPECT_THROW(writeMatrix(m, "/nonexistent-folder-for-test/m.csv"), InputError);
}

TEST(MatrixExport, ColumnMajorVectorsExportAsColumns) {
  // RgbField is column-major; the view copies it into row-major order.
  Eigen::Matrix<double, Eigen::Dynamic, 3> field(2, 3);
  field << 1, 2, 3, 4, 5, 6;
  const std::string path = test::scratchDir("matrix_export_field") + "/b.csv";
  writeMatrix(field, path);
  EXPECT_EQ(readAll(path), "1,2,3\n4,5,6\n");
}

}  // namespace
}  // namespace rt
