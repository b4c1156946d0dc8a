// Random walks by hand (Dutre, Bekaert and Bala 2006, sec. 6.3): in a closed room whose surfaces all reflect
// rho, a walk leaves the light carrying the power w, always arrives somewhere (the room is closed) and
// survives each arrival with probability rho. So it makes 1 + rho + rho^2 + ... = 1 / (1 - rho) arrivals on
// average. The collision estimator scores the reflected power rho w / A_i at every arrival on patch i; the
// absorption estimator scores only where the walk ends, weighted by 1 / (1 - rho): rho w / ((1 - rho) A_i).
// The walk of the exercise comes from a printed table: the patch each arrival lands on and the number that
// decides survival (u < rho survives). Written from the estimators' definitions, as the core's random-walk
// solver scores them; the tests compare the path length with the core's direct solution of a closed room.
#include <cmath>

#include "homework/topics.h"

namespace rt::homework {

std::optional<Exercise> generateRandomWalk(Draw& draw) {
  const double rho = draw.value(0.3, 0.8, 0.05);
  const double w = draw.value(1, 20, 0.5);       // W carried by the walk
  const double area = draw.value(0.5, 4, 0.25);  // m^2, the patch scored
  const int k = draw.integer(2, 4);              // the asked survival probability: at least k arrivals
  // The walk: arrivals land on the floor (1) or elsewhere (0); it goes on while u < rho.
  std::vector<double> u;
  std::vector<int> onFloor;
  for (int step = 0; step < 12; ++step) {
    u.push_back(std::round(100 * draw.uniform()) / 100);
    onFloor.push_back(draw.uniform() < 0.5 ? 1 : 0);
    if (std::abs(u.back() - rho) < 0.02) return std::nullopt;  // too close to call
    if (u.back() >= rho) break;
  }
  if (u.back() < rho) return std::nullopt;  // the walk must end within the table
  const int n = static_cast<int>(u.size());
  int floorHits = 0;
  for (int f : onFloor) floorHits += f;
  if (n < 2 || floorHits == 0) return std::nullopt;
  const bool endsOnFloor = onFloor.back() == 1;
  const double collision = floorHits * rho * w / area;
  const double absorption = endsOnFloor ? rho * w / ((1 - rho) * area) : 0.0;
  const double hits = 1 / (1 - rho), survive = std::pow(rho, k - 1);

  Exercise e;
  e.title = "Random walks: path length and the two estimators";
  e.given = {{"rho", rho},
             {"power", w},
             {"area", area},
             {"k", static_cast<double>(k)},
             {"arrivals", static_cast<double>(n)}};
  std::string table = "| arrival | lands on | $u$ |\n|---|---|---|\n";
  for (int t = 0; t < n; ++t)
    table += "| " + std::to_string(t + 1) + " | " + (onFloor[t] ? "floor" : "elsewhere") + " | " + num(u[t]) +
             " |\n";
  e.statement =
      "Every surface of a closed room reflects $\\rho = " + num(rho) +
      "$. A random walk leaves the light carrying the power $w = " + num(w) +
      "$ W; at each arrival it survives (is reflected on) when the table's number $u$ is below $\\rho$, and "
      "ends there otherwise. Find the expected number of arrivals of a walk, the probability that a walk "
      "makes at least $k = " +
      std::to_string(k) +
      "$ arrivals, and, for the walk in the table, its number of arrivals and the scores it gives the floor "
      "(area $A = " +
      num(area) + "$ m²) under the collision and the absorption estimators.\n\n" + table;
  e.hint =
      "The first arrival always happens (the room is closed); each further one needs one more survival. The "
      "collision estimator scores $\\rho w / A$ at every arrival on the floor; the absorption estimator "
      "scores "
      "only the last arrival, $\\rho w / ((1 - \\rho) A)$, if it is on the floor.";
  e.solution = {
      "Arrivals: $1 + \\rho + \\rho^2 + \\dots = 1/(1-\\rho) = " + num(hits, 6) + "$ on average (" +
          num(rho / (1 - rho), 6) + " of them after a reflection).",
      "At least $k$ arrivals needs $k - 1$ survivals: $\\rho^{k-1} = " + num(survive, 6) + "$.",
      "The walk in the table: it survives while $u < \\rho$, so it makes " + std::to_string(n) +
          " arrivals, " + std::to_string(floorHits) + " of them on the floor, and ends " +
          (endsOnFloor ? "on the floor" : "elsewhere") + ".",
      "Collision estimator: " + std::to_string(floorHits) + " $\\times\\ \\rho w / A = " + num(collision, 6) +
          "$ W/m².",
      "Absorption estimator: " +
          (endsOnFloor ? "$\\rho w / ((1-\\rho) A) = " + num(absorption, 6) + "$ W/m²"
                       : std::string("0 (the walk ends elsewhere)")) +
          ". Both are unbiased: averaged over many walks they give the same radiosity, the absorption one "
          "with more noise.",
  };
  e.questions = {
      {"hits",
       "expected arrivals per walk",
       hits,
       tolerance(hits, 0.002, 1e-6),
       false,
       {{"the reflections counted, not the arrivals (rho / (1 - rho))", rho / (1 - rho)},
        {"1 / rho", 1 / rho}}},
      {"survive",
       "probability of at least $k$ arrivals",
       survive,
       tolerance(survive, 0.002, 1e-6),
       false,
       {{"rho^k: one survival too many", std::pow(rho, k)}, {"(1 - rho)^(k-1)", std::pow(1 - rho, k - 1)}}},
      {"n",
       "arrivals of the walk in the table",
       static_cast<double>(n),
       0.5,
       true,
       {{"the survivals counted", n - 1.0}}},
      {"collision",
       "collision score on the floor in W/m²",
       collision,
       tolerance(collision, 0.002, 1e-6),
       false,
       {{"rho left out (w / A per arrival)", floorHits * w / area},
        {"only the last arrival scored", endsOnFloor ? rho * w / area : std::nan("")}}},
      {"absorption",
       "absorption score on the floor in W/m²",
       absorption,
       tolerance(absorption, 0.002, 1e-6),
       false,
       {{"no 1 / (1 - rho) weight", endsOnFloor ? rho * w / area : std::nan("")},
        {"every arrival scored (the collision estimator's score)", collision}}},
  };
  return e;
}

}  // namespace rt::homework
