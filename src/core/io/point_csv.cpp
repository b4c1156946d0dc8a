#include "core/io/point_csv.h"

#include <algorithm>
#include <array>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>

#include "core/input_error.h"

namespace rt {
namespace {

std::vector<std::string> splitCells(const std::string& line) {
  std::vector<std::string> cells(1);
  for (char c : line) {
    if (c == ',')
      cells.emplace_back();
    else if (c != '\r')
      cells.back() += c;
  }
  for (std::string& cell : cells) {
    const auto first = cell.find_first_not_of(" \t");
    const auto last = cell.find_last_not_of(" \t");
    cell = first == std::string::npos ? std::string() : cell.substr(first, last - first + 1);
  }
  return cells;
}

bool blank(const std::string& line) {
  return line.find_first_not_of(" \t\r") == std::string::npos;
}

// The columns named in `names`, found in the header; throws naming the first one missing.
std::vector<std::size_t> columnsOf(const std::vector<std::string>& header,
                                   const std::vector<std::string>& names, const SourceLocation& where) {
  std::map<std::string, std::size_t> index;
  for (std::size_t k = 0; k < header.size(); ++k) index.emplace(header[k], k);
  std::vector<std::size_t> columns;
  for (const std::string& name : names) {
    const auto found = index.find(name);
    if (found == index.end())
      throw InputError(where, "the header has no column '" + name + "' (it needs x,y,z,nx,ny,nz)");
    columns.push_back(found->second);
  }
  return columns;
}

double number(const std::vector<std::string>& cells, std::size_t column, const std::string& name,
              const SourceLocation& where) {
  if (column >= cells.size())
    throw InputError(where, "the line has " + std::to_string(cells.size()) + " cells, column '" + name +
                                "' is number " + std::to_string(column + 1));
  const std::string& cell = cells[column];
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(cell.c_str(), &end);
  if (cell.empty() || end != cell.c_str() + cell.size() || errno == ERANGE || !std::isfinite(value))
    throw InputError(where, "column '" + name + "': '" + cell + "' is not a finite number");
  return value;
}

// The breakdown's columns, in order: H's direct, first-bounce and remaining parts, then the standard errors
// of the first two.
std::vector<std::string> breakdownNames() {
  std::vector<std::string> names;
  for (const char* part : {"direct", "bounce", "rest", "direct_error", "bounce_error"})
    for (const char* channel : {"r", "g", "b"}) names.push_back(std::string("H_") + channel + "_" + part);
  return names;
}

}  // namespace

std::vector<SurfacePoint> readSurfacePoints(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError({path}, "cannot open the points file");
  std::string line;
  int lineNumber = 0;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (!blank(line)) break;
  }
  if (blank(line))
    throw InputError({path, lineNumber}, "no header: the file needs the columns x,y,z,nx,ny,nz");
  const std::vector<std::string> names{"x", "y", "z", "nx", "ny", "nz"};
  const auto columns = columnsOf(splitCells(line), names, {path, lineNumber});
  std::vector<SurfacePoint> points;
  while (std::getline(in, line)) {
    ++lineNumber;
    if (blank(line)) continue;
    const SourceLocation where{path, lineNumber};
    const auto cells = splitCells(line);
    std::array<double, 6> v{};
    for (std::size_t k = 0; k < 6; ++k) v[k] = number(cells, columns[k], names[k], where);
    const Vec3 normal(v[3], v[4], v[5]);
    if (!(normal.norm() > 0) || !std::isfinite(normal.norm()))
      throw InputError(
          where, "the normal (nx,ny,nz) is zero: it must give the side of the surface the point receives on");
    points.push_back({Vec3(v[0], v[1], v[2]), normal.normalized()});
  }
  return points;
}

void writePointEstimates(const std::string& path, const std::vector<SurfacePoint>& points,
                         const std::vector<PointEstimate>& estimates,
                         const std::vector<std::string>& surfaces, bool breakdown, bool withErrorEstimate) {
  std::ofstream out(path);
  if (!out) throw InputError({path}, "cannot write the output file");
  out << "x,y,z,nx,ny,nz,surface,H_r,H_g,H_b,B_r,B_g,B_b,H_r_error,H_g_error,H_b_error,B_r_error,B_g_error,"
         "B_b_error,H_r_mesh_error,H_g_mesh_error,H_b_mesh_error,B_r_mesh_error,B_g_mesh_error,B_b_mesh_"
         "error";
  if (breakdown)
    for (const std::string& name : breakdownNames()) out << ',' << name;
  if (withErrorEstimate) out << ",H_r_estimate,H_g_estimate,H_b_estimate";
  out << '\n';
  char buffer[1024];
  for (std::size_t p = 0; p < points.size(); ++p) {
    const SurfacePoint& q = points[p];
    const PointEstimate& e = estimates[p];
    std::snprintf(
        buffer, sizeof buffer,
        "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,%s,%.10g,%.10g,%.10g,%.10g,%.10g,%.10g,%.4g,%.4g,%.4g,%.4g,"
        "%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g,%.4g",
        q.position.x(), q.position.y(), q.position.z(), q.normal.x(), q.normal.y(), q.normal.z(),
        surfaces[p].c_str(), e.H(0), e.H(1), e.H(2), e.B(0), e.B(1), e.B(2), e.HError(0), e.HError(1),
        e.HError(2), e.BError(0), e.BError(1), e.BError(2), e.HMeshError(0), e.HMeshError(1), e.HMeshError(2),
        e.BMeshError(0), e.BMeshError(1), e.BMeshError(2));
    out << buffer;
    if (breakdown) {
      const Rgb rest = e.H - e.HDirect - e.HBounce;
      for (const Rgb& part : {e.HDirect, e.HBounce, rest})
        for (int c = 0; c < 3; ++c) {
          std::snprintf(buffer, sizeof buffer, ",%.10g", part(c));
          out << buffer;
        }
      for (const Rgb& part : {e.HDirectError, e.HBounceError})
        for (int c = 0; c < 3; ++c) {
          std::snprintf(buffer, sizeof buffer, ",%.4g", part(c));
          out << buffer;
        }
    }
    if (withErrorEstimate) {
      const Rgb estimate = errorEstimate(e);
      std::snprintf(buffer, sizeof buffer, ",%.4g,%.4g,%.4g", estimate(0), estimate(1), estimate(2));
      out << buffer;
    }
    out << '\n';
  }
  if (!out) throw InputError({path}, "error while writing the output file");
}

std::vector<PointEstimate> readPointEstimates(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError({path}, "cannot open the file");
  std::string line;
  if (!std::getline(in, line)) throw InputError({path, 1}, "empty file");
  const std::vector<std::string> names{"H_r",       "H_g",       "H_b",       "B_r",
                                       "B_g",       "B_b",       "H_r_error", "H_g_error",
                                       "H_b_error", "B_r_error", "B_g_error", "B_b_error"};
  const auto header = splitCells(line);
  const auto columns = columnsOf(header, names, {path, 1});
  // The mesh-error columns are the two-pass method's alone; files written before them lack them.
  const std::vector<std::string> meshNames{"H_r_mesh_error", "H_g_mesh_error", "H_b_mesh_error",
                                           "B_r_mesh_error", "B_g_mesh_error", "B_b_mesh_error"};
  const bool hasMeshErrors = std::all_of(meshNames.begin(), meshNames.end(), [&](const std::string& n) {
    return std::find(header.begin(), header.end(), n) != header.end();
  });
  const auto meshColumns =
      hasMeshErrors ? columnsOf(header, meshNames, {path, 1}) : std::vector<std::size_t>();
  const std::vector<std::string> partNames = breakdownNames();
  const bool hasParts = std::all_of(partNames.begin(), partNames.end(), [&](const std::string& n) {
    return std::find(header.begin(), header.end(), n) != header.end();
  });
  const auto partColumns = hasParts ? columnsOf(header, partNames, {path, 1}) : std::vector<std::size_t>();
  std::vector<PointEstimate> out;
  for (int lineNumber = 2; std::getline(in, line); ++lineNumber) {
    if (blank(line)) continue;
    const SourceLocation where{path, lineNumber};
    const auto cells = splitCells(line);
    PointEstimate e;
    for (int c = 0; c < 3; ++c) {
      e.H(c) = number(cells, columns[static_cast<std::size_t>(c)], names[static_cast<std::size_t>(c)], where);
      e.B(c) = number(cells, columns[static_cast<std::size_t>(c + 3)], names[static_cast<std::size_t>(c + 3)],
                      where);
      e.HError(c) = number(cells, columns[static_cast<std::size_t>(c + 6)],
                           names[static_cast<std::size_t>(c + 6)], where);
      e.BError(c) = number(cells, columns[static_cast<std::size_t>(c + 9)],
                           names[static_cast<std::size_t>(c + 9)], where);
      if (hasParts) {
        auto part = [&](int k) {
          const auto column = static_cast<std::size_t>(3 * k + c);
          return number(cells, partColumns[column], partNames[column], where);
        };
        e.HDirect(c) = part(0);
        e.HBounce(c) = part(1);
        e.HDirectError(c) = part(3);
        e.HBounceError(c) = part(4);
      }
      if (!hasMeshErrors) continue;
      e.HMeshError(c) = number(cells, meshColumns[static_cast<std::size_t>(c)],
                               meshNames[static_cast<std::size_t>(c)], where);
      e.BMeshError(c) = number(cells, meshColumns[static_cast<std::size_t>(c + 3)],
                               meshNames[static_cast<std::size_t>(c + 3)], where);
    }
    out.push_back(e);
  }
  return out;
}

}  // namespace rt
