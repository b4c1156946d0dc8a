// Adds the optional libraries' methods (the CGAL exact reference) to the registries when they are built in,
// as the command line does, so that lessons using them open in the app too.
#pragma once

namespace rt::app {
void registerOptionalMethods();
}
