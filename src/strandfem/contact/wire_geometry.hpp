// Where points lie on the wires at a state: element centerlines and poses, a wire's element ranges, projections
// onto a wire, and the nearest pair of points of a crossing.
#pragma once
#include <vector>

#include "strandfem/contact/contact_kinematics.hpp"
#include "strandfem/contact/contact_point.hpp"
#include "strandfem/mesh/mesh.hpp"

namespace strandfem::wire_geometry {

// An element's centreline nodes, and with its node rotations its pose, at `state`.
ElementCenterline<double> centerline(const Mesh& mesh, const std::vector<NodeState>& state, int element);
ElementPose<double> pose(const Mesh& mesh, const std::vector<NodeState>& state, int element);
Vec3 to_vec(const V3<double>& v);

// The element's index within its wire.
int local_index(const Mesh& mesh, int element);

// Half-open parameter ranges (-1, 1] partition a wire among its elements (the first element also takes -1),
// so a foot point on a shared node belongs to exactly one element.
bool in_range(double parameter, int local);

// Length of an element's centreline (4-point Gauss rule).
double arc_length(const ElementCenterline<double>& x);

// The orthogonal projection of x onto a wire: the candidate element (index within the wire) whose half-open
// range holds the foot point, nearest first. element = -1 when x projects past the wire's ends.
struct FootPoint {
  int element = -1;
  double eta = 0, distance = 1e300;
};
FootPoint project_onto_wire(const Mesh& mesh, const std::vector<NodeState>& state, int wire,
                            const std::vector<int>& candidates, const V3<double>& x, int guess_element, double guess_eta);

// Where a crossing lies now: the nearest pair of points of the two wires around the element pair it was last
// committed on. Away from element ends that is the closest-point solution of that pair. Near an end the nearest of
// every candidate over the neighbouring elements is taken: closest points inside an element pair, a wire's shared
// node projected inside the other wire's element, node against node. Where a wire's two elements meet at an angle
// the nearest point often is the node (the closest point of each element lies past its end, on S32 under bending
// -1.002 on one and 1.010 on the other). The minimum of distances is continuous as the wires move and does not
// depend on the path of earlier evaluations: stepping from element to element did, and the same state gave 160 N
// or 784 N at a crossing depending on the element it started from (docs/theory.md, "Locating a crossing as the
// nearest pair of points").
struct CrossingLocation {
  int element_a = -1, element_b = -1;  // indices within each wire; -1: no nearby pair of points
  double xi = 0, eta = 0;
  PinnedParameter pinned = PinnedParameter::kNone;
  double distance = 1e300;
};

CrossingLocation locate_crossing(const Mesh& mesh, const std::vector<NodeState>& state, const ContactPoint& p);

}  // namespace strandfem::wire_geometry
