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

// Largest coordinate magnitude accepted: beyond it products of coordinates (areas, normals) lose all
// precision or overflow, and a scene that large is a unit mistake.
inline constexpr double kMaxCoordinate = 1e15;
// Largest vertex count of one polygon in a file (the outline checks are quadratic in it).
inline constexpr std::size_t kMaxPolygonVertices = 1000;

// Whole file as text. Throws InputError "cannot open ..." naming the file.
std::string readTextFile(const std::string& path);

// Compact rendering of a number for messages ("3.2", "1e-06") with `digits` significant digits.
std::string formatNumber(double value, int digits = 6);
std::string formatRgb(const Rgb& value);

// Reflectance finite and in [0,1), emission finite and >= 0, name not empty. Throws InputError at `where`.
void checkMaterial(const Material& material, const SourceLocation& where);

// The location of vertex `index` of a polygon at `where`: for JSON, the path gets "/index" appended.
SourceLocation vertexLocation(const SourceLocation& where, std::size_t index);

// Checks one polygon and appends it to scene.patches as one patch, or as triangles with a warning in
// scene.warnings when it is not planar (a fan) or not convex (ear clipping). Rejects non-finite coordinates,
// fewer than 3 distinct vertices, more than kMaxPolygonVertices, zero area and outlines that cross or touch
// themselves with InputError at `where`. Repeated consecutive vertices are dropped (with a warning).
// scene.unit is only used in messages.
void addPolygon(Scene& scene, const Polygon& polygon, int surface, const SourceLocation& where);

// Appends a warning to scene.warnings for each light (emitting surface) none of whose patches has any other
// patch in front of it that faces back, i.e. whose emission reaches nothing (a light listed clockwise faces
// away from the room), and one more when no light reaches anything: the solve then succeeds with every
// reflector black, which must not pass in silence.
void addLightWarnings(Scene& scene);

}  // namespace rt::io_detail
