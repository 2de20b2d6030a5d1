#include "strandfem/post/bending_profiles.hpp"

#include <cmath>

#include "strandfem/contact/friction.hpp"

namespace strandfem {

namespace {
// Angle difference folded into [0, 180].
double angular_distance(double a, double b) {
  const double d = std::fmod(std::abs(a - b), 360.0);
  return d > 180.0 ? 360.0 - d : d;
}
}  // namespace

PlaneRegion plane_region(double angle_degrees, double radius, double load_angle_degrees, double half_width_degrees) {
  if (radius <= 1e-9) return PlaneRegion::kNone;
  const double from_load = angular_distance(angle_degrees, load_angle_degrees);  // 0..180
  if (from_load <= half_width_degrees || from_load >= 180.0 - half_width_degrees) return PlaneRegion::kVertical;
  if (std::abs(from_load - 90.0) <= half_width_degrees) return PlaneRegion::kHorizontal;
  return PlaneRegion::kNone;
}

const char* to_string(PlaneRegion region) {
  switch (region) {
    case PlaneRegion::kVertical: return "vertical";
    case PlaneRegion::kHorizontal: return "horizontal";
    default: return "none";
  }
}

const char* to_string(MapStatus status) {
  switch (status) {
    case MapStatus::kSticking: return "sticking";
    case MapStatus::kSliding: return "sliding";
    case MapStatus::kSlipping: return "slipping";
    case MapStatus::kFrictionless: return "frictionless";
    default: return "open";
  }
}

void LoadingHalfTracker::observe(const std::vector<int>& statuses) {
  if (stuck_.size() < statuses.size()) stuck_.resize(statuses.size(), 0);
  for (std::size_t i = 0; i < statuses.size(); ++i)
    if (statuses[i] == static_cast<int>(ContactStatus::kStick)) stuck_[i] = 1;
}

BendingProfiles LoadingHalfTracker::at_peak(int cycle, const StrandSnapshot& peak) const {
  BendingProfiles out;
  out.cycle = cycle;
  // Wire nodes are listed in the same order in every snapshot of a model.
  const bool same_wires = start_.wires.size() == peak.wires.size();
  for (std::size_t i = 0; i < peak.wires.size(); ++i)
    out.wires.push_back({peak.wires[i], same_wires ? peak.wires[i].axial_force - start_.wires[i].axial_force : 0.0});
  const int open = static_cast<int>(ContactStatus::kOpen);
  for (std::size_t i = 0; i < peak.contacts.size(); ++i) {
    const ContactSample& p = peak.contacts[i];
    // A point appended during the half (a new crossing) starts from zero force and slip.
    const ContactSample before = i < start_.contacts.size() ? start_.contacts[i] : ContactSample{};
    if (p.status == open && before.status == open) continue;
    ContactProfileRow row;
    row.point = static_cast<int>(i);
    row.at_peak = p;
    row.normal_force_change = p.normal_force - before.normal_force;
    row.tangential_force_change = p.tangential_force - before.tangential_force;
    row.slip_change = p.slip - before.slip;
    row.tangential_displacement_change = p.tangential_displacement - before.tangential_displacement;
    row.dissipated_energy_change = p.dissipated_energy - before.dissipated_energy;
    if (p.status != open && !p.frictional) {
      row.map_status = MapStatus::kFrictionless;
    } else if (p.status == static_cast<int>(ContactStatus::kStick)) {
      row.map_status = MapStatus::kSticking;
    } else if (p.status == static_cast<int>(ContactStatus::kSlip)) {
      const bool stuck_before = (i < stuck_.size() && stuck_[i]) || before.status == static_cast<int>(ContactStatus::kStick);
      row.map_status = stuck_before ? MapStatus::kSlipping : MapStatus::kSliding;
    }
    out.contacts.push_back(row);
  }
  return out;
}

}  // namespace strandfem
