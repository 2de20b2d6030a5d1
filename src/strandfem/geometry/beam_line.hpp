// Free beam lines (straight, circular arc, helix) for textbook beam problems run through the same program.
#pragma once
#include <string>

#include "strandfem/core/types.hpp"
#include "strandfem/mesh/mesh.hpp"

namespace strandfem {

struct BeamLineSpec {
  enum Shape { kStraight, kArc, kHelix } shape = kStraight;
  std::string name;
  int elements = 1;
  // straight: from start to end; section axis 2 along `normal` (made orthogonal to the line) if given.
  Vec3 start = Vec3::Zero(), end = Vec3::UnitX(), normal = Vec3::Zero();
  // arc: center, radius, angles (rad) in the plane normal to `axis` (x toward angle 0); section axis 2
  // points to the center. helix: about the z axis from z = 0 to `length`.
  Vec3 center = Vec3::Zero(), axis = Vec3::UnitZ();
  double radius = 1, start_angle = 0, end_angle = 0;
  double lay_angle = 0, length = 0;
  int lay_direction = 1;
};

// Meshes the line into `spec.elements` quadratic elements with the given section; returns the wire id.
int add_beam_line(Mesh& mesh, const BeamLineSpec& spec, int section);

}  // namespace strandfem
