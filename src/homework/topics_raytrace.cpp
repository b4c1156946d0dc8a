// Counting a ray tracer's rays by hand: the rays of one full ray tree (every hit spawns its mirror ray, and
// its refracted one through glass, up to a depth), the shadow rays each hit sends to every light, the rays
// per pixel with supersampling, the whole image's and the time they take. The key is computed here from the
// tree's generations; the tests compare it with the core's cost formula and with the Whitted tracer's own
// counts.
#include <cmath>

#include "homework/topics.h"

namespace rt::homework {

std::optional<Exercise> generateRayTree(Draw& draw) {
  static const int kWidths[] = {320, 640, 800, 1024, 1280, 1920};
  const int width = kWidths[draw.integer(0, 5)];
  const int height = width * 3 / 4;
  const int samples = draw.integer(0, 1) == 0 ? 1 : 4 * draw.integer(1, 4);  // 1, 4, 8, 12, 16
  const int lights = draw.integer(1, 4);
  const int shadow = draw.integer(0, 2) == 0 ? 1 : 4 * draw.integer(1, 8);  // hard, or 4..32 soft
  const int depth = draw.integer(1, 5);
  const int branching = draw.integer(1, 2);  // 1: mirrors only, 2: mirrors and glass
  const double rate = draw.value(5, 50, 1);  // millions of rays per second
  if (branching == 1 && shadow == 1 && samples == 1 && lights == 1) return std::nullopt;  // too plain

  // Generation k holds branching^k rays; each one that reaches a surface is a node of the tree.
  double nodes = 0, generation = 1, last = 1;
  for (int k = 0; k <= depth; ++k, generation *= branching) {
    nodes += generation;
    last = generation;
  }
  const double shadowPerTree = nodes * lights * shadow;
  const double perTree = nodes + shadowPerTree;
  const double perPixel = samples * perTree;
  const double pixels = static_cast<double>(width) * height;
  const double total = pixels * perPixel;
  const double seconds = total / (rate * 1e6);

  const auto whole = [](double x) { return num(x, 15); };  // counts in full, never rounded
  Exercise e;
  e.title = "Counting the rays of a ray tracer";
  e.given = {{"width", width},   {"height", height}, {"samples", samples},     {"lights", lights},
             {"shadow", shadow}, {"depth", depth},   {"branching", branching}, {"rate", rate}};
  const std::string surfaces =
      branching == 1 ? "every surface is a mirror (each hit spawns one reflected ray)"
                     : "every surface is glass (each hit spawns one reflected and one refracted ray)";
  e.statement =
      "A recursive ray tracer renders a $" + num(width) + " \\times " + num(height) + "$ image with " +
      num(samples) + (samples == 1 ? " primary ray" : " primary rays") +
      " per pixel. The scene is closed, so every ray reaches a surface, and " + surfaces +
      ". The tracer follows secondary rays to depth $d = " + num(depth) +
      "$ (the primary ray's hit is at depth 0) and sends " + num(shadow) +
      (shadow == 1 ? " shadow ray" : " shadow rays") + " to each of the scene's " + num(lights) +
      (lights == 1 ? " light" : " lights") +
      " from every hit. Find the rays of one ray tree that reach a surface (primary and secondary), "
      "its shadow rays, the rays per pixel, the rays of the whole image and the time they take at " +
      num(rate) + " million rays per second.";
  e.hint =
      "Draw the tree for a small depth: generation $k$ holds $b^k$ rays, where $b$ is the number of "
      "secondary "
      "rays per hit. Every ray of the tree ends at a hit, and every hit sends its shadow rays. Supersampling "
      "multiplies everything by the rays per pixel.";
  e.solution = {
      "Ray tree: generation $k$ has $" + num(branching) + "^k$ rays, so $1" +
          (branching == 1 ? std::string(" + 1 \\cdot ") + num(depth)
                          : std::string(" + 2 + \\dots + 2^{") + num(depth) + "}") +
          " = " + whole(nodes) + "$ rays reach a surface.",
      "Shadow rays: each of the " + whole(nodes) + " hits sends " + num(shadow) + " to each of " +
          num(lights) + ": $" + whole(nodes) + " \\times " + num(lights) + " \\times " + num(shadow) + " = " +
          whole(shadowPerTree) + "$.",
      "Per pixel: $" + num(samples) + " \\times (" + whole(nodes) + " + " + whole(shadowPerTree) +
          ") = " + whole(perPixel) +
          "$ rays, that is $\\text{samples} \\times \\text{nodes} \\times (1 + \\text{lights} \\times "
          "\\text{shadow rays})$.",
      "Whole image: $" + whole(pixels) + " \\times " + whole(perPixel) + " = " + whole(total) + "$ rays.",
      "Time: $" + whole(total) + " / (" + num(rate) + " \\times 10^6) = " + num(seconds, 4) + "$ s.",
  };
  const double plainShadow = nodes * shadow;
  e.questions = {
      {"nodes",
       "rays of one tree that reach a surface",
       nodes,
       0.5,
       true,
       {{"the primary ray left out", nodes - 1},
        {"only the last generation counted", last},
        {"one generation too many (depth counted from 1)", nodes + last * branching}}},
      {"shadow",
       "shadow rays of one tree",
       shadowPerTree,
       0.5,
       true,
       {{"the lights left out (shadow rays per hit only)", plainShadow},
        {"only the primary hit's shadow rays", static_cast<double>(lights * shadow)}}},
      {"perPixel",
       "rays per pixel",
       perPixel,
       0.5,
       true,
       {{"the shadow rays left out", samples * nodes},
        {"the tree's own rays left out (shadow rays only)", samples * shadowPerTree},
        {"the samples per pixel left out", perTree}}},
      {"total",
       "rays of the whole image",
       total,
       0.5,
       true,
       {{"the samples per pixel left out", pixels * perTree},
        {"the shadow rays left out", pixels * samples * nodes}}},
      {"seconds",
       "time in seconds",
       seconds,
       tolerance(seconds, 0.01, 1e-6),
       false,
       {{"the rate taken in rays per second, not millions", total / rate},
        {"the shadow rays left out", pixels * samples * nodes / (rate * 1e6)}}},
  };
  return e;
}

}  // namespace rt::homework
