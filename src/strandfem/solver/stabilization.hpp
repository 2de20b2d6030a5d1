// Viscous stabilization: weak damping, proportional to the wires' elastic stiffness, of the motion since the last
// converged state.
#pragma once
#include <array>
#include <vector>

#include "strandfem/beam/beam_element.hpp"

namespace strandfem {

// The static counterpart of Abaqus' automatic stabilization, with a stiffness-proportional (Rayleigh β) damping
// matrix in place of a mass-proportional one: on each beam element a force factor · K₀ q, where K₀ is the element's
// elastic tangent in the reference configuration and q its nodes' motion since the last converged state (the
// displacements and the rotation vectors of Λ Λ_convergedᵀ). A soft mode that leaves the static tangent indefinite
// (a wire hinging plastically: its elastic bending stiffness is large, its plastic one small or negative) is held
// by factor · K₀, while a rigid motion, which K₀ does not resist, costs nothing: mass- or diagonal-proportional
// damping resisted the strand's own stretching (docs/theory.md, "Viscous stabilization").
class ViscousStabilization {
 public:
  // K₀ of every element, evaluated on copies of the elements at the mesh's reference configuration (before any
  // load, so the sections are elastic).
  void initialize(const std::vector<BeamElement>& elements, const std::vector<NodeState>& reference);
  bool initialized() const { return !reference_stiffness_.empty(); }

  // Adds factor · K₀ q to element `element`'s residual and, with tangent, its derivative with respect to the
  // nodes' (displacement, spin) corrections.
  void add(int element, const std::array<NodeState, 3>& now, const std::array<NodeState, 3>& converged, double factor,
           ElementVector& residual, ElementMatrix* tangent) const;
  // Energy dissipated over an increment ending at `state`: Σ_e factor qᵀ K₀ q (a constant rate over the increment).
  double dissipated_energy(const std::vector<BeamElement>& elements, const std::vector<NodeState>& state,
                           const std::vector<NodeState>& converged, double factor) const;

 private:
  std::vector<ElementMatrix> reference_stiffness_;
};

// What the assembler needs to add the stabilization to the elements.
struct ElementDamping {
  const ViscousStabilization* stabilization = nullptr;
  const std::vector<NodeState>* converged = nullptr;
  double factor = 0;
};

// Inverse of the left Jacobian of SO(3): d log(exp(δθ) exp(φ)) / dδθ at δθ = 0.
Mat3 inverse_left_jacobian(const Vec3& phi);

}  // namespace strandfem
