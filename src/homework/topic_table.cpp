#include "homework/topic_table.h"

#include <cmath>
#include <set>
#include <stdexcept>

#include "homework/topics.h"

namespace rt::homework {

double Draw::value(double lo, double hi, double step) {
  const double x = lo + (hi - lo) * random_.uniform();
  return std::clamp(std::round(x / step) * step, lo, hi);
}

int Draw::integer(int lo, int hi) {
  return lo + static_cast<int>(random_.uniform() * (hi - lo + 1));
}

const std::vector<Topic>& topicTable() {
  static const std::vector<Topic> table{
      {"rectangles", "Form factor between two rectangles",
       "F_ij and F_ji of two rectangles: parallel, perpendicular or at an angle",
       "form-factor,exact-reference,runtime-error-lab", generateRectangles},
      {"nusselt", "The Nusselt analog", "point-to-rectangle F by projecting onto the hemisphere and the disk",
       "nusselt-analog,hemicube", generateNusselt},
      {"closure", "Reciprocity and closure", "missing F_ij of a closed box from given ones",
       "form-factor,radiosity-matrix", generateClosure},
      {"hemicube", "Hemicube delta form factors",
       "delta form factors of given pixels and the F of a footprint", "hemicube", generateHemicube},
      {"raycast", "A ray-cast or local-line estimate and its standard error",
       "F_ij from a given table of random numbers (point pairs or local lines), with the standard error",
       "exact-reference,ray-casting,runtime-error-lab", generateRaycast},
      {"assemble-k", "Assembling K", "K = I - diag(rho) F for an enclosure of 3 to 5 patches",
       "numerical-stability,radiosity-matrix", generateAssembleK},
      {"jacobi-gauss-seidel", "Jacobi and Gauss-Seidel by hand",
       "two Jacobi and two Gauss-Seidel sweeps, and the exact solution", "gathering",
       generateJacobiGaussSeidel},
      {"southwell", "Southwell shooting", "three shots, the shooter and the unshot power after each",
       "shooting", generateSouthwell},
      {"stochastic-jacobi", "One iteration of stochastic Jacobi",
       "lines drawn from a table of random numbers by power and by F, the estimate, its standard error and "
       "the deterministic sweep",
       "stochastic,when-n-squared-is-too-big", generateStochasticJacobi},
      {"bounces", "The k-th bounce", "the power carried by bounce k and its share of the total",
       "cornell-box,local-vs-global,rendering-equation,shooting", generateBounces},
      {"spectral-radius", "Spectral radius and iteration count",
       "the spectral radius of rho F and the sweeps needed for a tolerance", "gathering,numerical-stability",
       generateSpectralRadius},
      {"tone-mapping", "Tone mapping to 8-bit",
       "exposure, linear or Reinhard tone map and sRGB gamma to 0..255", "patches-to-pixels",
       generateToneMapping},
      {"subdivision", "The adaptive subdivision criterion",
       "whether the gradient criterion splits an element", "meshing", generateSubdivision},
      {"irradiance", "Solid angle and irradiance",
       "a small tilted patch lit by a point source: its solid angle, the intensity, the irradiance and the "
       "power received",
       "measuring-light", generateIrradiance},
      {"ray-tree", "Counting the rays of a ray tracer",
       "the rays of a full ray tree, its shadow rays, the rays per pixel and the image's rays and time",
       "ray-tracing", generateRayTree},
      {"phong", "A Phong reflection",
       "a distant lamp and a viewer in the plane of incidence: the angle from the mirror direction, the "
       "normalised Phong BRDF's specular part and whole value, and the radiance seen",
       "reflection", generatePhong},
      {"reflection-equation", "One bounce of the reflection equation",
       "a round lamp of radiance L over a Lambertian point: the cosine-weighted solid angle, the irradiance, "
       "the "
       "reflected radiance and the radiosity",
       "rendering-equation,cornell-box", generateReflectionEquation},
      {"hierarchical-oracle", "A refinement decision of hierarchical radiosity",
       "the oracle's form-factor estimates of two nodes, which node splits and how many of its children link",
       "hierarchical,when-n-squared-is-too-big", generateHierarchicalOracle},
      {"random-walk", "Random walks: path length and the two estimators",
       "the expected arrivals of a walk for a given rho, and one walk's collision and absorption scores",
       "stochastic,two-solutions", generateRandomWalk},
      {"two-pass", "The two-pass method at a point",
       "the direct part from a small lamp plus the indirect part gathered from the first pass, the radiosity "
       "and the radiance",
       "two-solutions,local-vs-global", generateTwoPass},
      {"linear-element", "Evaluating a linear element",
       "a rectangle's bilinear shape functions and radiosity at a point, its average and one corner's weight",
       "finite-elements", generateLinearElement},
      {"discontinuity", "The critical lines of a shadow",
       "where the rays from a strip light's edges past a table's edges meet the floor (the umbra and "
       "penumbrae), the width of the light a penumbra point sees, the lines' order and the element they cut",
       "meshing", generateDiscontinuity},
      {"dense-cost", "What a dense form-factor matrix costs",
       "the elements of a mesh, the memory of its F in doubles, the largest n that fits, the time of all "
       "form "
       "factors and of one Jacobi sweep, and the growth of the memory when every element is split again",
       "when-n-squared-is-too-big", generateDenseCost},
  };
  return table;
}

const Topic* findTopic(const std::string& id) {
  for (const Topic& t : topicTable())
    if (id == t.id) return &t;
  return nullptr;
}

std::vector<std::string> topicIds() {
  std::vector<std::string> ids;
  for (const Topic& t : topicTable()) ids.emplace_back(t.id);
  return ids;
}

bool topicFitsLesson(const Topic& topic, const std::string& lessonId) {
  const std::string list = std::string(",") + topic.lessons + ",";
  return list.find("," + lessonId + ",") != std::string::npos;
}

Exercise generateExercise(const Topic& topic, std::uint64_t seed, int student) {
  // The topic's id, not its row, picks the stream: adding a topic does not change anyone's numbers.
  std::uint64_t hash = 1469598103934665603ull;
  for (const char* c = topic.id; *c; ++c) hash = (hash ^ static_cast<unsigned char>(*c)) * 1099511628211ull;
  Draw draw(seed, static_cast<std::uint64_t>(student), hash);
  for (int attempt = 0; attempt < 1000; ++attempt)
    if (std::optional<Exercise> e = topic.generate(draw)) {
      e->topic = topic.id;
      e->student = student;
      e->seed = seed;
      for (Question& q : e->questions) {
        if (q.integer) q.tolerance = 0.5;
        pruneMistakes(q);
      }
      return *e;
    }
  throw std::runtime_error(std::string("topic ") + topic.id + ": no well-posed variant in 1000 draws");
}

std::vector<std::string> exerciseProblems(const Exercise& e) {
  std::vector<std::string> problems;
  if (e.questions.empty()) problems.push_back("no questions");
  std::set<std::string> ids;
  for (const Question& q : e.questions) {
    if (!ids.insert(q.id).second) problems.push_back("duplicate question id " + q.id);
    if (!std::isfinite(q.answer)) problems.push_back(q.id + ": answer is not finite");
    if (!(q.tolerance > 0) || !std::isfinite(q.tolerance)) problems.push_back(q.id + ": tolerance <= 0");
    if (q.integer && std::abs(q.answer - std::round(q.answer)) > 1e-9)
      problems.push_back(q.id + ": integer answer is not whole");
  }
  for (const RowCheck& r : e.rowChecks)
    for (const auto& [id, count] : r.terms)
      if (!ids.count(id)) problems.push_back(r.row + " names unknown question " + id);
  if (e.solution.empty()) problems.push_back("no worked solution");
  return problems;
}

std::string topicTableMarkdown() {
  std::string out = "| topic | title | practises | lessons |\n|---|---|---|---|\n";
  for (const Topic& t : topicTable()) {
    std::string lessons = t.lessons;
    for (std::size_t k = lessons.find(','); k != std::string::npos; k = lessons.find(',', k + 2))
      lessons.replace(k, 1, ", ");
    out += std::string("| `") + t.id + "` | " + t.title + " | " + t.practises + " | " + lessons + " |\n";
  }
  return out;
}

}  // namespace rt::homework
