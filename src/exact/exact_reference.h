// The exact reference (CGAL), behind a header that includes no CGAL: exact visibility from a point, exact point-to-area
// and element-to-element form factors. See docs/architecture.md.
#pragma once

namespace rt::exact {

// Adds the "exact" form-factor method to the core registry.
void registerExactMethod();

}  // namespace rt::exact
