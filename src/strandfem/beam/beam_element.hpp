// Geometrically exact (Simo-Reissner) 3-node beam element with objective interpolation of rotations.
#pragma once
#include <array>

#include "strandfem/beam/section.hpp"
#include "strandfem/core/types.hpp"

namespace strandfem {

class ArchiveWriter;
class ArchiveReader;

// Current position and orientation of a node; the rotation maps the reference axes (e1 = beam tangent)
// to the current section axes.
struct NodeState {
  Vec3 position = Vec3::Zero();
  Quaternion rotation = Quaternion::Identity();
};

using ElementVector = Eigen::Matrix<double, 18, 1>;
using ElementMatrix = Eigen::Matrix<double, 18, 18>;

// One of the two reduced (Gauss) integration points of an element: its fixed geometry.
struct BeamIntegrationPoint {
  std::array<double, 3> shape{};             // N_i at the point
  std::array<double, 3> shape_derivative{};  // dN_i/ds (s: reference arc length)
  double weight_length = 0;                  // Gauss weight * ds/dxi
  Vec6 reference_strain = Vec6::Zero();      // [Gamma0, K0] of the stress-free configuration
};

// What an integration point's solution state is: its section history (committed at the last converged
// increment, trial at the current iterate) and its last evaluated strain and resultants.
struct SectionPointState {
  Vec6 strain = Vec6::Zero();      // last evaluated strain (from the reference)
  Vec6 resultants = Vec6::Zero();  // last evaluated [N, Q2, Q3, T, M2, M3]
  SectionHistory committed, trial;
};

// The solution state of one element (owned by the analysis's ModelState, not by the element).
struct BeamElementState {
  std::array<SectionPointState, 2> points;
  void commit();  // trial history becomes committed (increment converged)
  void revert();  // trial history reset to committed (increment rejected)
  // Checkpoints: the committed history of both integration points.
  void save_history(ArchiveWriter& out) const;
  void restore_history(ArchiveReader& in);
};

// Element with nodes (end, middle, end) at xi = (-1, 0, 1). Rotations are interpolated as rotation
// vectors relative to the middle node (Crisfield & Jelenic 1999): strains are invariant under rigid
// motions and independent of the load path. Degrees of freedom per node: displacement increment and
// spatial spin increment (Lambda <- exp(dtheta^) Lambda); residual and tangent refer to these.
class BeamElement {
 public:
  BeamElement(const std::array<int, 3>& nodes, const Section* section, const std::array<NodeState, 3>& reference);

  struct Output {
    ElementVector residual = ElementVector::Zero();  // internal forces minus nothing (no loads here)
    ElementMatrix tangent = ElementMatrix::Zero();   // d residual / d (du, dtheta)
    double energy = 0;                               // elastic strain energy (elastic sections)
  };
  // Evaluates the element at the current nodal states from the committed history in `state`; writes its
  // trial history and point results there.
  void evaluate(const std::array<NodeState, 3>& current, BeamElementState& state, bool with_tangent, Output& out) const;
  // The state before any load: the section's initial history at both points.
  BeamElementState initial_state() const;

  const std::array<int, 3>& nodes() const { return nodes_; }
  const Section& section() const { return *section_; }
  const std::array<BeamIntegrationPoint, 2>& points() const { return points_; }
  double reference_length() const { return points_[0].weight_length + points_[1].weight_length; }

 private:
  std::array<int, 3> nodes_;
  const Section* section_;
  std::array<BeamIntegrationPoint, 2> points_;
};

}  // namespace strandfem
