// The hemicube (Cohen & Greenberg 1985): a half cube of pixels around an element's centre. Every other
// element is z-buffered onto its five faces; the form factor to element j is the sum of the delta form
// factors of the pixels where j is nearest. Exposed piece by piece for the lessons: the face buffers of one
// element and the delta form factors of a resolution.
#pragma once

#include <array>
#include <vector>

#include "core/mesh.h"

namespace rt {

// Face order: top (along the normal), then the four sides +u, +v, -u, -v of the element's tangent frame.
enum class HemicubeFace { Top = 0, PlusU = 1, PlusV = 2, MinusU = 3, MinusV = 4 };

// A face as three axes in the element's local frame (x = u, y = v, z = normal): pixels run along `across`
// (columns) and `up` (rows); `forward` points from the eye through the face. Views that draw the buffers use
// it.
struct HemicubeFaceAxes {
  Vec3 across, up, forward;
  double upMin;  // the top face spans up in [-1, 1]; the sides span [0, 1] (horizon to the top edge)
};
HemicubeFaceAxes hemicubeFaceAxes(HemicubeFace face);

// Pixel values besides element ids: nothing in that direction, or the back of a polygon. Polygons are
// one-sided but opaque: a back face blocks what lies behind it and takes no share itself, as in every other
// method (rays that hit a back face count for nothing; the exact method's occluders are all polygons).
constexpr int kHemicubeSeesNothing = -1;
constexpr int kHemicubeSeesBackFace = -2;

struct HemicubeFaceBuffer {
  int width = 0, height = 0;  // top: res x res; sides: res x ceil(res/2) (rows from the horizon upwards)
  std::vector<int> element;   // width * height, row-major; an element id, kHemicubeSeesNothing or ...BackFace
  std::vector<float> depth;   // distance along the face's axis, +inf where nothing is seen
};

struct HemicubeFaces {
  int resolution = 0;
  int element = -1;
  Vec3 origin, u, v,
      normal;  // eye (the element's centroid) and frame: top face along normal, sides along +-u, +-v
  std::array<HemicubeFaceBuffer, 5> faces;
};

// Side faces have ceil(resolution / 2) rows, each 1 / rows high.
int hemicubeSideRows(int resolution);

// Delta form factors of one face at a resolution (row-major, same layout as the buffers). Each is the exact
// form factor from the eye to the pixel's square (Lambert's formula), so all five faces together sum to 1 to
// rounding at every resolution. Cached per resolution; thread-safe. Throws std::invalid_argument for
// resolution < 2.
const std::vector<double>& deltaFormFactors(int resolution, HemicubeFace face);
// The largest delta form factor over the five faces (the scale of a delta-form-factor heat map).
double maxDeltaFormFactor(int resolution);

// Renders the hemicube of `element`: pixel-centre coverage, near-plane clipping, z-buffer. Elements that turn
// their back to the eye are drawn as kHemicubeSeesBackFace (they occlude: the floor under a block without a
// bottom sees the block's inside, not the room through it); elements edge-on to the eye and the parts below
// the element's horizon are not drawn.
HemicubeFaces renderHemicube(const Mesh& mesh, int element, int resolution);

// The mesh's elements as a hemicube reads them, every element for every eye: their corners' indices, normal,
// bounding sphere and corner count in one flat record each instead of behind a vector apiece. Made once per
// mesh and read by any number of threads; it refers to `mesh`, which must outlive it.
struct HemicubeMesh {
  struct Record {
    Vec3 normal;
    Vec3 centre;        // of a sphere around the corners
    double radius = 0;  // that sphere's
    std::array<int, 8> vertices;
    int count = 0;
  };
  explicit HemicubeMesh(const Mesh& mesh);
  const Mesh& mesh;
  std::vector<Record> elements;
};

// Reusable storage for rendering many hemicubes in a row (one per thread): no allocation after the first.
struct HemicubeWorkspace {
  HemicubeFaces faces;
  std::array<std::vector<double>, 5> inverseDepth;
  std::vector<Vec3> localVertices;  // every mesh vertex in the eye's frame (u, v, normal), once per hemicube
  bool computeDepth = true;  // false: leave faces[].depth empty (the matrix builder only needs the ids)
};
void renderHemicube(const HemicubeMesh& mesh, int element, int resolution, HemicubeWorkspace& workspace);

// Row i of the form-factor matrix from a rendered hemicube: sums the delta form factors per visible element.
void accumulateHemicubeRow(const HemicubeFaces& faces, double* row);

// Row `element` of the hemicube method's matrix (n entries, overwritten): the hemicube rendered in
// `workspace` without depths, its delta form factors summed per visible element.
void hemicubeRow(const HemicubeMesh& mesh, int element, int resolution, HemicubeWorkspace& workspace,
                 double* row);

}  // namespace rt
