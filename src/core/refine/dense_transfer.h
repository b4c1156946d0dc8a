// Dense form factors between mesh elements with the refine transfer kernel (closed-form polygon side,
// ray-sampled visibility), computed incrementally: after a split only the rows and columns of the new
// elements are evaluated. And the gathering solve the refining meshers run after every change.
#pragma once

#include <string>
#include <vector>

#include "core/formfactor/formfactor_matrix.h"
#include "core/mesh.h"
#include "core/progress.h"
#include "core/refine/transfer.h"
#include "core/solvers/radiosity_system.h"

namespace rt {

// Views of a mesh's elements for the transfer kernel; `polygons` owns the vertex lists the pieces point to.
std::vector<SurfacePiece> piecesOfMesh(const Mesh& mesh, std::vector<Polygon>& polygons);

// F for `pieces`, reusing previous(oldIndex[a], oldIndex[b]) whenever both elements existed before (oldIndex
// = -1 for new elements; an empty oldIndex computes everything). pairsComputed receives the number of pairs
// evaluated.
FormFactorMatrix updateFormFactors(const FormFactorMatrix& previous, const std::vector<int>& oldIndex,
                                   const std::vector<SurfacePiece>& pieces,
                                   const VisibilityOracle& visibility, const TransferOptions& options,
                                   Progress& progress, const std::string& stage, std::size_t& pairsComputed);

// Solves the system with the core's Gauss-Seidel (the same iteration `radiosity solve --method gauss-seidel`
// runs) until the relative residual ||K B - E|| / ||E|| is below tolerance or maxSweeps is reached, checking
// for cancellation after every sweep. Returns the number of sweeps.
int gatherSolve(const RadiositySystem& system, RgbField& B, double tolerance, int maxSweeps,
                Progress& progress);

}  // namespace rt
