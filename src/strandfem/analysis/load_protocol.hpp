// Load protocols: steps of nodal loads and imposed motions (ramps, holds, cycles), expanded into ramps.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace strandfem {

// Components of a node's 6 DOFs: displacements ux, uy, uz (mm), rotations rx, ry, rz (rad, about fixed
// global axes), forces (N) and moments (N mm) conjugate to them.
enum Component { kUx = 0, kUy, kUz, kRx, kRy, kRz };

// A nodal action: a force/moment (dead load in global axes) or an imposed motion of one DOF. Values are
// totals at the end of the step; within a step they vary linearly from the previous step's totals.
struct NodalAction {
  enum Kind { kForce, kMotion } kind = kForce;
  int node = -1;
  int component = 0;
  double value = 0;
};

// A step of the case. Without cycles it is a ramp: the listed actions go linearly from their totals before
// the step to their values here, in `increments`; actions not listed keep their totals (a step with no
// actions holds everything). With cycles = n > 0 the listed actions go to their values and back to their
// totals before the step, n times: 2n ramps of `increments` each (a transverse load 0 -> Vmax -> 0 -> ...).
struct LoadStep {
  std::string name;
  int increments = 1;
  std::vector<NodalAction> actions;
  int cycles = 0;
};

// Where a ramp of the expanded protocol comes from: its case step (0-based) and, for cyclic steps, the cycle
// (1-based) and whether it is the half that returns to the values before the step.
struct RampOrigin {
  int step = 0;
  int cycle = 0;  // 0: the step is not cyclic
  bool returning = false;
};

// A linear ramp of the analysis: the listed actions reach their values at its end.
struct LoadRamp {
  std::string name;
  int increments = 1;
  std::vector<NodalAction> actions;
  RampOrigin origin;
};

// The ramps a sequence of steps expands into, in order (one per plain step, 2n per cyclic step).
std::vector<LoadRamp> expand_load_steps(const std::vector<LoadStep>& steps);

// Supports: DOFs of a node held at zero motion for the whole analysis.
struct Support {
  int node = -1;
  std::array<bool, 6> fixed{};
};

}  // namespace strandfem
