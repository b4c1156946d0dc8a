#include "lesson/step_result.h"

#include <regex>

namespace rt::lesson {

std::optional<Rgb> surfaceMean(const Mesh& mesh, const Scene& scene, const RgbField& field,
                               const std::string& surface) {
  int index = -1;
  for (std::size_t s = 0; s < scene.surfaces.size(); ++s)
    if (scene.surfaces[s].name == surface) index = static_cast<int>(s);
  if (index < 0 || field.rows() != static_cast<Eigen::Index>(mesh.size())) return std::nullopt;
  Rgb sum = Rgb::Zero();
  double area = 0;
  for (std::size_t e = 0; e < mesh.size(); ++e) {
    const Element& el = mesh.elements[e];
    if (scene.patches[el.patch].surface != index) continue;
    sum += field.row(static_cast<Eigen::Index>(e)).transpose().array() * el.area;
    area += el.area;
  }
  if (area <= 0) return std::nullopt;
  return Rgb(sum / area);
}

std::optional<double> StepResult::value(const std::string& name) const {
  if (auto it = values.find(name); it != values.end()) return it->second;
  static const std::regex fEntry(R"(F\[(\d+)\]\[(\d+)\])");
  static const std::regex bEntry(R"(B\[(\d+)\](?:\.([rgb]))?)");
  static const std::regex rowSum(R"(rowsum\[(\d+)\])");
  std::smatch m;
  const auto n = static_cast<long>(mesh.size());
  if (F && std::regex_match(name, m, fEntry)) {
    const long i = std::stol(m[1]), j = std::stol(m[2]);
    if (i < F->rows() && j < F->cols()) return (*F)(i, j);
  }
  if (F && std::regex_match(name, m, rowSum)) {
    const long i = std::stol(m[1]);
    if (i < F->rows()) return F->row(i).sum();
  }
  if (B.rows() == n && std::regex_match(name, m, bEntry)) {
    const long i = std::stol(m[1]);
    if (i >= n) return std::nullopt;
    if (m[2].matched) return B(i, std::string("rgb").find(m[2].str()[0]));
    return B.row(i).mean();
  }
  return std::nullopt;
}

std::vector<std::string> StepResult::valueNames() const {
  std::vector<std::string> names;
  if (F) {
    names.push_back("F[i][j]");
    names.push_back("rowsum[i]");
  }
  if (B.rows() > 0) names.push_back("B[i]");
  for (const auto& [name, v] : values) names.push_back(name);
  return names;
}

}  // namespace rt::lesson
