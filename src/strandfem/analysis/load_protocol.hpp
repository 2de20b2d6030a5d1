// Load steps: target values of nodal loads and imposed motions, reached in increments.
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

struct LoadStep {
  std::string name;
  int increments = 1;
  std::vector<NodalAction> actions;  // actions not listed keep the previous step's totals
};

// Supports: DOFs of a node held at zero motion for the whole analysis.
struct Support {
  int node = -1;
  std::array<bool, 6> fixed{};
};

}  // namespace strandfem
