#include "core/solvers/radiosity_system.h"

#include <limits>

#include "core/solvers/gather_products.h"

namespace rt {

RadiositySystem RadiositySystem::fromMesh(const Mesh& mesh, const FormFactorMatrix& F) {
  RadiositySystem s = fromGeometry(mesh);
  s.F = &F;
  return s;
}

RadiositySystem RadiositySystem::fromGeometry(const Mesh& mesh) {
  RadiositySystem s;
  s.mesh = &mesh;
  s.reflectance = mesh.reflectance;
  s.emission = mesh.emission;
  s.areas = mesh.areas();
  return s;
}

double RadiositySystem::relativeResidual(const RgbField& B) const {
  if (!F) return std::numeric_limits<double>::quiet_NaN();
  return relativeResidual(B, solver_detail::productWithF(*F, B));
}

double RadiositySystem::relativeResidual(const RgbField& B, const RgbField& FB) const {
  const RgbField KB = B - (reflectance.array() * FB.array()).matrix();
  const double e = emission.norm();
  const double r = (KB - emission).norm();
  return e > 0 ? r / e : r;
}

}  // namespace rt
