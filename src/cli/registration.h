// Adds the optional libraries' methods (the CGAL exact reference) to the registries when they are built in.
#pragma once

namespace rt::cli {
void registerOptionalMethods();
}
