// Adds what the optional libraries bring to the registries when they are built in: the CGAL exact
// form-factor method and the constrained-triangulation mesher of discontinuity meshing. The app and the CLI
// both call this one function, so that a lesson computes the same in both.
#pragma once

namespace rt {

// Idempotent and thread-safe.
void registerOptionalMethods();

}  // namespace rt
