// Factories of the built-in form-factor methods (registered by name in formfactor_registry.cpp).
#pragma once

#include <memory>

#include "core/formfactor/formfactor_method.h"

namespace rt {

// "analytic" (visibility = false): exact F ignoring occluders (exact in convex enclosures).
// "analytic-visibility" (visibility = true): exact unoccluded F times a ray-cast visible fraction where the
// shaft test finds possible occluders.
std::unique_ptr<FormFactorMethod> makeAnalyticMethod(bool visibility);
std::unique_ptr<FormFactorMethod> makeRaycastMethod();
std::unique_ptr<FormFactorMethod> makeMonteCarloMethod();
std::unique_ptr<FormFactorMethod> makeHemicubeMethod();
std::unique_ptr<FormFactorMethod> makeNusseltMethod();
// "hybrid": exact near, centroid far, ray-cast hidden part with rays in proportion to F (hybrid_method.cpp).
std::unique_ptr<FormFactorMethod> makeHybridMethod();
// "quadrature": every entry to an absolute tolerance, the hidden part clipped per point
// (quadrature_method.cpp).
std::unique_ptr<FormFactorMethod> makeQuadratureMethod();

}  // namespace rt
