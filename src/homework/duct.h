// A long duct whose cross-section is a convex polygon of 3 to 5 sides: the enclosure of the matrix and solver
// exercises. Its form factors (per unit length, the duct being long) follow exactly from Hottel's crossed
// strings, F_ij = (|P_i P_j| + |P_i+1 P_j+1| - |P_i P_j+1| - |P_i+1 P_j|) / (2 L_i), so a student can check
// them with a ruler, and rows sum to 1 (closed) with A_i F_ij = A_j F_ji.
#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

#include "homework/exercise.h"
#include "homework/topic_table.h"

namespace rt::homework {

struct Duct {
  std::vector<Vec2> corners;  // counter-clockwise; side i runs from corner i to corner i+1
  Eigen::VectorXd length;     // side lengths (the "areas" per unit length of duct)
  Eigen::MatrixXd F;          // rounded to 4 decimals, as handed out
  Eigen::VectorXd rho;        // reflectance per side
  Eigen::VectorXd E;          // emission per side
};

// n sides with corners on a jittered circle (rounded to 0.1), reflectances in [rhoLo, rhoHi] and one or two
// emitting sides; nullopt when the shape is degenerate (a side shorter than 0.3, not convex).
std::optional<Duct> drawDuct(Draw& draw, int n, double rhoLo = 0.3, double rhoHi = 0.9);

// The statement's description of the duct and its data (F, rho, E, side lengths) as data files.
std::string ductStatement(const Duct& duct);
void addDuctData(Exercise& exercise, const Duct& duct);
// Cross-section figure with the sides numbered.
Figure ductFigure(const Duct& duct);
// The duct extruded to 10 units as a scene (its F is close to, not equal to, the 2D value).
void addDuctScene(Exercise& exercise, const Duct& duct);

// K = I - diag(rho) F.
Eigen::MatrixXd ductK(const Duct& duct);

}  // namespace rt::homework
