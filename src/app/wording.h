// How the app words what it counts and how a solve ended: "1 iteration" and "2 iterations", "1 bounce", and
// for the solvers that stop on a budget of rays by design, "noise level reached" rather than the "no
// convergence" that a deterministic solver would deserve. One place, so that the status line, the scene
// summary and the player say the same thing.
#pragma once

#include <QString>
#include <string>
#include <vector>

#include "app/pipeline.h"
#include "core/solvers/solver.h"

namespace rt::app {

// "1 iteration", "3 iterations"; `plural` empty: `singular` + "s".
QString counted(long long n, const QString& singular, const QString& plural = QString());

// Whether `solver` estimates B with random rays or walks (its result carries noise, it stops on a budget).
bool isStochasticSolver(const std::string& solver);

// The unit a solver counts in: "bounce" for the bounce-by-bounce sum, "iteration" otherwise.
QString iterationUnit(const std::string& solver);

// "success", "numerical issue", ...; a stochastic solver that used its whole budget: "noise level reached".
QString statusText(const std::string& solver, SolverStatus status);

// "gauss-seidel: success after 12 iterations, residual 8.1e-07" (the status line and the scene summary).
QString solveSummary(const std::string& solver, SolverStatus status, int iterations, double residual);

// The same for a result: a bounces run counts its bounces (its history holds B after 0, 1, ... bounces).
QString solveSummary(const PipelineResult& result);

// What each record of the result's history stands for, in iterationUnit(result.solverName): a bounces run's
// record k is B after k bounces (record 0 the emission), another solver's the iteration it was taken after.
// The last one is the count solveSummary gives.
std::vector<int> iterationNumbers(const PipelineResult& result);

// A message from the core, which names settings as the command line spells them ("use a coarser mesh, e.g.
// --max-edge 40"), in the app's terms: each option that is a step key becomes its control's label in the
// Parameters panel ("the Max edge control: 40"), and --no-subdivide its Subdivision control at 1. Other text
// is left as it is.
QString inAppTerms(const QString& message);

}  // namespace rt::app
