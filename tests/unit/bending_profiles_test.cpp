// The bending profiles of post/bending_profiles: the regions of paper Fig. 12 and the status map of section 4.1.
#include <gtest/gtest.h>

#include "strandfem/contact/friction.hpp"
#include "strandfem/post/bending_profiles.hpp"

namespace strandfem {
namespace {

TEST(BendingProfiles, PlaneRegionsFollowTheLoadDirection) {
  // Load along y (90 degrees): the paper's top 75-105, bottom 255-285, neutral axis 165-195 and 345-15.
  for (double a : {75.0, 90.0, 105.0, 255.0, 270.0, 285.0, -90.0})
    EXPECT_EQ(plane_region(a, 5.0, 90.0), PlaneRegion::kVertical) << a;
  for (double a : {165.0, 180.0, 195.0, 345.0, 0.0, 15.0, -15.0, 375.0})
    EXPECT_EQ(plane_region(a, 5.0, 90.0), PlaneRegion::kHorizontal) << a;
  for (double a : {74.0, 106.0, 135.0, 200.0, 340.0, 16.0})
    EXPECT_EQ(plane_region(a, 5.0, 90.0), PlaneRegion::kNone) << a;
  // A load along x turns the regions by 90 degrees; the core (on the axis) is in none.
  EXPECT_EQ(plane_region(0.0, 5.0, 0.0), PlaneRegion::kVertical);
  EXPECT_EQ(plane_region(90.0, 5.0, 0.0), PlaneRegion::kHorizontal);
  EXPECT_EQ(plane_region(90.0, 0.0, 90.0), PlaneRegion::kNone);
}

ContactSample sample(ContactStatus status, double normal_force, double slip, bool frictional = true) {
  ContactSample c;
  c.kind = 1;
  c.layer_a = 1;
  c.layer_b = 2;
  c.status = static_cast<int>(status);
  c.normal_force = normal_force;
  c.tangential_force = status == ContactStatus::kOpen ? 0.0 : 0.3 * normal_force;
  c.slip = slip;
  c.tangential_displacement = slip + 0.01;
  c.dissipated_energy = 0.3 * normal_force * slip;  // as if it had slid at mu P, P as now
  c.frictional = frictional;
  return c;
}

TEST(BendingProfiles, StatusMapAndChangesSinceTheStartOfTheLoading) {
  using S = ContactStatus;
  StrandSnapshot start, peak;
  start.wires = {{0, 1, 1, 10.0, 90.0, 5.0, 800.0}, {1, 2, 1, 10.0, 270.0, 5.0, 800.0}};
  peak.wires = {{0, 1, 1, 10.0, 90.0, 5.0, 950.0}, {1, 2, 1, 10.0, 270.0, 5.0, 650.0}};
  // 0: sticks throughout; 1: slides throughout; 2: stuck at the start, slides at the peak; 3: slides at the
  // start, sticks in between, slides at the peak; 4: frictionless; 5: open throughout; 6: closes during the
  // half (a crossing the search added), sliding.
  start.contacts = {sample(S::kStick, 100, 0), sample(S::kSlip, 100, 0.2), sample(S::kStick, 100, 0),
                    sample(S::kSlip, 100, 0.1), sample(S::kStick, 50, 0, false), sample(S::kOpen, 0, 0)};
  peak.contacts = {sample(S::kStick, 120, 0), sample(S::kSlip, 90, 0.5), sample(S::kSlip, 110, 0.05),
                   sample(S::kSlip, 100, 0.3), sample(S::kStick, 60, 0, false), sample(S::kOpen, 0, 0),
                   sample(S::kSlip, 40, 0.02)};
  LoadingHalfTracker tracker;
  tracker.set_start(start);
  const auto as_ints = [](std::initializer_list<S> s) {
    std::vector<int> out;
    for (S x : s) out.push_back(static_cast<int>(x));
    return out;
  };
  tracker.observe(as_ints({S::kStick, S::kSlip, S::kStick, S::kStick, S::kStick, S::kOpen}));
  tracker.observe(as_ints({S::kStick, S::kSlip, S::kSlip, S::kSlip, S::kStick, S::kOpen, S::kSlip}));
  const BendingProfiles p = tracker.at_peak(1, peak);
  EXPECT_EQ(p.cycle, 1);
  ASSERT_EQ(p.wires.size(), 2u);
  EXPECT_DOUBLE_EQ(p.wires[0].axial_force_change, 150.0);
  EXPECT_DOUBLE_EQ(p.wires[1].axial_force_change, -150.0);
  ASSERT_EQ(p.contacts.size(), 6u);  // the open point is left out
  const MapStatus expected[] = {MapStatus::kSticking, MapStatus::kSliding, MapStatus::kSlipping, MapStatus::kSlipping,
                                MapStatus::kFrictionless, MapStatus::kSliding};
  const int points[] = {0, 1, 2, 3, 4, 6};
  for (int i = 0; i < 6; ++i) {
    EXPECT_EQ(p.contacts[i].point, points[i]);
    EXPECT_EQ(p.contacts[i].map_status, expected[i]) << "point " << points[i] << ": " << to_string(p.contacts[i].map_status);
  }
  EXPECT_DOUBLE_EQ(p.contacts[0].normal_force_change, 20.0);
  EXPECT_DOUBLE_EQ(p.contacts[1].tangential_force_change, 0.3 * (90 - 100));
  EXPECT_DOUBLE_EQ(p.contacts[1].slip_change, 0.3);
  EXPECT_DOUBLE_EQ(p.contacts[1].tangential_displacement_change, 0.3);
  EXPECT_DOUBLE_EQ(p.contacts[1].dissipated_energy_change, 0.3 * (90 * 0.5 - 100 * 0.2));
  // The new crossing counts from zero force and slip.
  EXPECT_DOUBLE_EQ(p.contacts[5].normal_force_change, 40.0);
  EXPECT_DOUBLE_EQ(p.contacts[5].slip_change, 0.02);
  EXPECT_DOUBLE_EQ(p.contacts[5].tangential_displacement_change, 0.03);
  EXPECT_DOUBLE_EQ(p.contacts[5].dissipated_energy_change, 0.3 * 40 * 0.02);
  // A new loading half forgets what the last one saw.
  tracker.set_start(peak);
  tracker.observe(as_ints({S::kSlip, S::kSlip, S::kSlip, S::kSlip, S::kStick, S::kOpen, S::kSlip}));
  peak.contacts[0] = sample(S::kSlip, 120, 0.1);
  peak.contacts[3] = sample(S::kSlip, 100, 0.4);
  const BendingProfiles q = tracker.at_peak(2, peak);
  EXPECT_EQ(q.contacts[0].map_status, MapStatus::kSlipping);  // it stuck at this half's start
  EXPECT_EQ(q.contacts[3].map_status, MapStatus::kSliding);
}

}  // namespace
}  // namespace strandfem
