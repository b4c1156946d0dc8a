// Pieces shared by the scene loaders (JSON, OBJ): reading files, checking materials, and turning one polygon
// read from a file into patches. Every format goes through the same checks so that they reject and repair
// input identically. Internal to src/core/io; the public entry points are in scene_loader.h.
#pragma once

#include <string>

#include "core/scene.h"

namespace rt::io_detail {

// Relative tolerances, as fractions of the polygon's longest edge (docs/scene-format.md, "Validation").
inline constexpr double kPlanarityTolerance = 1e-6;   // vertex distance from the best-fit plane
inline constexpr double kCoincidentTolerance = 1e-9;  // two vertices closer than this are the same vertex
inline constexpr double kZeroAreaTolerance =
    1e-10;  // area / longest_edge^2 below this is a degenerate polygon

// Whole file as text. Throws InputError "cannot open ..." naming the file.
std::string readTextFile(const std::string& path);

// Compact rendering of a number for messages ("3.2", "1e-06") with `digits` significant digits.
std::string formatNumber(double value, int digits = 6);
std::string formatRgb(const Rgb& value);

// Reflectance finite and in [0,1), emission finite and >= 0, name not empty. Throws InputError at `where`.
void checkMaterial(const Material& material, const SourceLocation& where);

// The location of vertex `index` of a polygon at `where`: for JSON, the path gets "/index" appended.
SourceLocation vertexLocation(const SourceLocation& where, std::size_t index);

// Checks one polygon and appends it to scene.patches as one patch, or as a fan of triangles with a warning in
// scene.warnings when it is not planar. Rejects non-finite coordinates, fewer than 3 distinct vertices, zero
// area, non-convex and self-overlapping outlines with InputError at `where`. Repeated consecutive vertices
// are dropped (with a warning). scene.unit is only used in messages.
void addPolygon(Scene& scene, const Polygon& polygon, int surface, const SourceLocation& where);

}  // namespace rt::io_detail
