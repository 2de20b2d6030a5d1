// Wire forces and contact results of a cyclic bending protocol at each cycle's peak load, with their changes
// since the start of that loading half (V = 0), and the contact status map of the loading (paper section 4,
// Figs. 11, 13 and 14).
#pragma once
#include <string>
#include <vector>

#include "strandfem/post/strand_snapshot.hpp"

namespace strandfem {

// The regions of paper Fig. 12: within half_width of the plane of the transverse load ("vertical": top and
// bottom, 75-105 and 255-285 degrees for a load along y) or of the plane across it ("horizontal", the neutral
// axis: 165-195 and 345-15 degrees).
enum class PlaneRegion { kNone, kVertical, kHorizontal };
// Points on the strand axis (radius 0, the core) are in no region.
PlaneRegion plane_region(double angle_degrees, double radius, double load_angle_degrees, double half_width_degrees = 15.0);
const char* to_string(PlaneRegion region);

// Status of a contact point over a loading half, as section 4.1 maps it: sticking or sliding at the peak,
// and "slipping" for a point that slides at the peak but was sticking at some converged state of the half
// (its start included): a status change from sticking to sliding during the loading. Closed points without
// friction are "frictionless".
enum class MapStatus { kOpen, kSticking, kSliding, kSlipping, kFrictionless };
const char* to_string(MapStatus status);

struct WireProfileRow {
  WireForceSample at_peak;
  double axial_force_change = 0;  // F(peak) - F(V = 0), N
};

struct ContactProfileRow {
  int point = -1;
  ContactSample at_peak;
  double normal_force_change = 0, tangential_force_change = 0, slip_change = 0;  // peak - start
  double tangential_displacement_change = 0;
  double dissipated_energy_change = 0;  // friction's work at the point over the loading half, N mm
  MapStatus map_status = MapStatus::kOpen;
};

struct BendingProfiles {
  int cycle = 0;
  std::vector<WireProfileRow> wires;
  std::vector<ContactProfileRow> contacts;  // points closed at the peak or at the start
};

// Follows one loading half at a time: the state it starts from, whether each contact point stuck on the way.
class LoadingHalfTracker {
 public:
  // The converged state at V = 0 from which the next loading half starts.
  void set_start(StrandSnapshot start) { start_ = std::move(start); stuck_.clear(); }
  // Contact statuses of a converged increment within the loading half (and at its start).
  void observe(const std::vector<int>& statuses);
  // The profiles at the peak of `cycle`, against the start.
  BendingProfiles at_peak(int cycle, const StrandSnapshot& peak) const;

  const StrandSnapshot& start() const { return start_; }
  const std::vector<char>& stuck() const { return stuck_; }
  void restore(StrandSnapshot start, std::vector<char> stuck) { start_ = std::move(start); stuck_ = std::move(stuck); }

 private:
  StrandSnapshot start_;
  std::vector<char> stuck_;  // per contact point: sticking at some converged state of the half
};

}  // namespace strandfem
