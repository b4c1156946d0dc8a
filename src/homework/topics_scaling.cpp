// What a dense form-factor matrix costs: a room's patches are each split into s x s elements, and the
// student finds the n elements, the bytes of F in doubles (8 n^2), the largest n whose F fits in a given
// memory, the time of all n^2 form factors at a given rate of pairs, the time of one Jacobi sweep (n^2
// multiply-adds per colour channel) and the factor by which refining every element m x m multiplies F's
// memory (m^4). The key is written from those formulas; the tests compare the bytes with the size of the
// core's FormFactorMatrix (its scalar's size) and the fitting n with the memory it stands for.
#include <cmath>

#include "homework/topics.h"

namespace rt::homework {

std::optional<Exercise> generateDenseCost(Draw& draw) {
  const int patches = draw.integer(20, 400);
  const int split = draw.integer(2, 12);
  const double memoryGB = draw.value(4, 64, 4);      // the machine's memory, 10^9 bytes
  const double pairRate = draw.value(0.5, 20, 0.5);  // millions of form factors per second
  const double flopRate = draw.value(0.5, 8, 0.5);   // 10^9 multiply-adds per second
  const int refine = draw.integer(2, 4);             // every element split refine x refine
  const double n = static_cast<double>(patches) * split * split;
  const double bytes = 8.0 * n * n;
  const double gigabytes = bytes / 1e9;
  const double fits = std::floor(std::sqrt(memoryGB * 1e9 / 8.0));
  const double formFactorSeconds = n * n / (pairRate * 1e6);
  const double sweepSeconds = 3.0 * n * n / (flopRate * 1e9);
  const double growth = std::pow(static_cast<double>(refine), 4);
  if (n < 200) return std::nullopt;  // too small to be a question about scale

  Exercise e;
  e.title = "What a dense form-factor matrix costs";
  e.given = {{"patches", patches},   {"split", split},       {"memory", memoryGB},
             {"pairRate", pairRate}, {"flopRate", flopRate}, {"refine", refine}};
  e.statement =
      "A room of " + num(patches) + " patches is meshed by splitting every patch into $" + num(split) +
      " \\times " + num(split) +
      "$ elements, and its form-factor matrix $F$ is stored densely in 8-byte doubles. Find the number of "
      "elements $n$, the memory $F$ takes in GB ($10^9$ bytes), and the largest $n$ whose $F$ fits in the " +
      num(memoryGB) + " GB of the machine. The form factors are computed at " + num(pairRate) +
      " million pairs per second: how many seconds do all $n^2$ of them take? A Jacobi sweep does one "
      "multiply-add per entry of $F$ for each of the three colour channels, at " +
      num(flopRate) +
      " billion multiply-adds per second: how many seconds does one sweep take? Finally, every element is "
      "split again into $" +
      num(refine) + " \\times " + num(refine) + "$: by what factor does the memory of $F$ grow?";
  e.hint =
      "$F$ has one entry per ordered pair of elements, $n^2$ in all. Solve $8 n^2 = M$ for the $n$ that "
      "fits. "
      "Splitting an element into $m \\times m$ multiplies $n$ by $m^2$.";
  e.solution = {
      "Elements: $n = " + num(patches) + " \\times " + num(split) + "^2 = " + num(n, 15) + "$.",
      "Memory: $8 n^2 = 8 \\times " + num(n, 15) + "^2 = " + num(bytes, 4) + "$ bytes, " + num(gigabytes, 4) +
          " GB.",
      "Largest $n$ that fits: $n = \\sqrt{" + num(memoryGB) + " \\times 10^9 / 8} = " + num(fits, 15) +
          "$ elements (rounded down).",
      "Form factors: $n^2 / (" + num(pairRate) + " \\times 10^6) = " + num(formFactorSeconds, 4) + "$ s.",
      "One sweep: $3 n^2 / (" + num(flopRate) + " \\times 10^9) = " + num(sweepSeconds, 4) + "$ s.",
      "Refining: $n$ grows by $" + num(refine) + "^2$, so $n^2$ and the memory by $" + num(refine) +
          "^4 = " + num(growth) + "$.",
  };
  e.questions = {
      {"n",
       "number of elements $n$",
       n,
       0.5,
       true,
       {{"only one split direction counted", static_cast<double>(patches * split)}}},
      {"GB",
       "memory of $F$ in GB",
       gigabytes,
       tolerance(gigabytes, 0.01, 1e-6),
       false,
       {{"4-byte floats instead of doubles", gigabytes / 2},
        {"bits counted as bytes (64 per entry)", 8 * gigabytes},
        {"n entries instead of n^2", 8.0 * n / 1e9},
        {"GiB (2^30 bytes) instead of GB", bytes / (1024.0 * 1024.0 * 1024.0)}}},
      {"fits",
       "largest $n$ whose $F$ fits in the memory",
       fits,
       tolerance(fits, 0.005, 1),
       false,
       {{"the 8 bytes per entry left out", std::floor(std::sqrt(memoryGB * 1e9))},
        {"the square root left out (n entries, not n^2)", memoryGB * 1e9 / 8.0}}},
      {"formFactorSeconds",
       "seconds for all $n^2$ form factors",
       formFactorSeconds,
       tolerance(formFactorSeconds, 0.01, 1e-6),
       false,
       {{"the rate taken in pairs per second, not millions", n * n / pairRate},
        {"n pairs instead of n^2", n / (pairRate * 1e6)}}},
      {"sweepSeconds",
       "seconds for one Jacobi sweep",
       sweepSeconds,
       tolerance(sweepSeconds, 0.01, 1e-9),
       false,
       {{"one colour channel only", n * n / (flopRate * 1e9)},
        {"n multiply-adds instead of n^2", 3.0 * n / (flopRate * 1e9)}}},
      {"growth",
       "factor by which the memory of $F$ grows",
       growth,
       0.5,
       true,
       {{"n's growth m^2 instead of n^2's", static_cast<double>(refine * refine)},
        {"m instead of m^4", static_cast<double>(refine)}}},
  };
  return e;
}

}  // namespace rt::homework
