#include "core/solvers/radiosity_system.h"

namespace rt {

RadiositySystem RadiositySystem::fromMesh(const Mesh& mesh, const FormFactorMatrix& F) {
  RadiositySystem s;
  s.F = &F;
  s.reflectance = mesh.reflectance;
  s.emission = mesh.emission;
  s.areas = mesh.areas();
  return s;
}

double RadiositySystem::relativeResidual(const RgbField& B) const {
  const RgbField KB = B - (reflectance.array() * ((*F) * B).array()).matrix();
  const double e = emission.norm();
  const double r = (KB - emission).norm();
  return e > 0 ? r / e : r;
}

}  // namespace rt
