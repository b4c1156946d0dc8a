// Local lines from one element (Dutré, Bekaert and Bala 2006, sec. 6.2.2): `count` lines leave element i at
// stratified uniform points, each in a cosine-distributed direction about the normal, with the density
// p(x, theta) = cos(theta) / (pi A_i). A line lands first on element j with probability F_ij, so the count
// N_ij of the lines whose first hit is the front of j is binomial(count, F_ij) and N_ij / count estimates
// F_ij. The "montecarlo" form-factor method builds its rows from these lines and the rays view draws the
// same ones, so a figure shows exactly the lines an estimate counted.
#pragma once

#include <cstdint>
#include <vector>

#include "core/formfactor/line_sampling.h"
#include "core/formfactor/ray_scene.h"
#include "core/mesh.h"

namespace rt {

struct LocalLine {
  Vec3 origin, direction;  // direction: unit
  int hit = -1;            // the element whose front the line hits first; -1: escaped or hit a back side
  int struck = -1;         // the element the line hits first, front or back (-1: escaped)
  double distance = 0;     // to the first element struck (0 when it escaped)
};

// Deterministic for (seed, i). `scene` must be built from `mesh`. Random lines take their origins from a
// jittered grid and their directions from the stream; Sobol lines take both from point k of a scrambled
// 4-dimensional Sobol set (line_sampling.h), so origins and directions are spread evenly together.
std::vector<LocalLine> shootLocalLines(const Mesh& mesh, const RayScene& scene, int i, int count,
                                       std::uint64_t seed, LineSampling sampling = LineSampling::Random);

}  // namespace rt
