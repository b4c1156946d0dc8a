// What a scaling step measures: how the dense method's memory and form-factor time grow with the number of
// elements n, how many links hierarchical radiosity with clustering needs instead of the n^2 element
// pairs, how local lines' noise falls with the rays, and the cluster hierarchy's boxes at one depth. The
// viz layer draws them; the numbers are also the step's placeholders.
#pragma once

#include <string>
#include <vector>

#include "core/vec.h"

namespace rt::lesson {

// One mesh of the step's `subdivisions`: the dense matrix's cost against the clustering solver's.
struct ScalingPoint {
  int subdivide = 0;
  long elements = 0;
  double denseBytes = 0;         // n^2 doubles: what storing F takes
  double formFactorSeconds = 0;  // computing F with the step's method
  double directSeconds = 0;      // solving with F by Gaussian elimination
  double sweepSeconds = 0;       // one Jacobi sweep with F
  int jacobiSweeps = 0;          // Jacobi's sweeps to the step's tolerance
  double fill = 0;               // the share of F's entries that are not zero
  long links = 0;                // hierarchical-clustering on the same mesh
  long nodes = 0;
  double clusterBytes = 0;  // tree and links, counted from the containers
  double clusterSeconds = 0;
};

// Local lines on the step's mesh with one number of rays: the standard error it reports, relative to ||B||.
struct SolverNoisePoint {
  double raysPerElement = 0;  // all rays traced, over n
  double standardError = 0;
};

// One scene file of the step's `scenes`, solved by hierarchical-clustering.
struct SceneLinksPoint {
  std::string file;
  long elements = 0;
  long links = 0;
  double seconds = 0;
};

// The files of one scene at several sizes (they share the scene's name), by n, and the log-log slope of
// their links against n.
struct SceneLinksSeries {
  std::string name;  // the scene's own name ("Museum")
  std::string key;   // the name in placeholders: lower case, spaces as '-' ("museum")
  std::vector<SceneLinksPoint> points;
  double slope = 0;
};

struct ClusterBox {
  Vec3 lower, upper;
};

struct ScalingData {
  std::vector<ScalingPoint> points;
  std::vector<SolverNoisePoint> noise;
  // The step's `scenes`, one series per scene name.
  std::vector<SceneLinksSeries> sceneLinks;
  double noiseSlope = 0;       // log-log slope of the standard error against the rays
  double linksSlope = 0;       // log-log slope of the links against n
  double formFactorSlope = 0;  // log-log slope of the form-factor time against n
  double directSlope = 0;      // ... of the direct solve's time
  double sweepSlope = 0;       // ... of one Jacobi sweep's time
  double memoryBytes = 0;      // this machine's physical memory
  double elementsThatFit = 0;  // the n whose dense F fills memoryBytes
  int clusterDepth = 0;
  std::vector<ClusterBox> boxes;  // the cluster tree's nodes at clusterDepth (leaves above it included)
};

}  // namespace rt::lesson
