// Rows of F computed at the shooter, for shooting without a stored n x n matrix (progressive refinement as
// Cohen et al. 1988 ran it): when element i shoots, a hemicube at its centroid, or rays from it, give what it
// sees, and the row is thrown away after the shot. Memory O(n) instead of O(n^2); an element that shoots
// again computes its row again.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "core/formfactor/formfactor_method.h"
#include "core/mesh.h"
#include "core/solvers/shooting_solvers.h"

namespace rt {

// Form-factor methods that can give one row at a time: "hemicube" and "raycast".
std::vector<std::string> rowProviderMethods();

// Row i of the named method's matrix, computed on demand. "hemicube" gives exactly the hemicube method's row
// (rows are independent there). "raycast" integrates F_ij from i's side for every j with the raycast
// method's estimator (stratified points on i, Lambert's formula to j, ray-cast visibility where the shaft may
// be blocked); the matrix method derives half of its entries by reciprocity instead, so the two agree to the
// estimator's noise. The mesh must outlive the provider. Throws std::invalid_argument for other methods.
// Thread-compatible: one provider per thread.
FormFactorRowProvider makeRowProvider(const std::string& method, const Mesh& mesh,
                                      const FormFactorOptions& options);

}  // namespace rt
