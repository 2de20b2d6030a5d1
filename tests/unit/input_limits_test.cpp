// Requirement (issue 10): the checks at the roots of the input: UTF-8 validation, saturating element counts,
// overlap of per-wire start angles.
#include <gtest/gtest.h>

#include <numbers>

#include "strandfem/geometry/strand.hpp"
#include "strandfem/io/yaml_document.hpp"
#include "strandfem/mesh/mesh.hpp"

namespace strandfem {
namespace {

TEST(InputLimits, Utf8ValidationFindsTheFirstBadByte) {
  EXPECT_EQ(first_invalid_utf8("title: caf\xc3\xa9 \xe2\x82\xac \xf0\x9f\x98\x80\n\ttab\r\n", true), std::string::npos);
  EXPECT_EQ(first_invalid_utf8("ab\xff", false), 2u);
  EXPECT_EQ(first_invalid_utf8("a\xc3", false), 1u);              // truncated sequence
  EXPECT_EQ(first_invalid_utf8("\xc0\xaf", false), 0u);           // overlong
  EXPECT_EQ(first_invalid_utf8("\xed\xb2\x80", false), 0u);       // surrogate U+DC80
  EXPECT_EQ(first_invalid_utf8("\xf4\x90\x80\x80", false), 0u);   // beyond U+10FFFF
  EXPECT_EQ(first_invalid_utf8(std::string("a\0b", 3), true), 1u);  // control character
  EXPECT_EQ(first_invalid_utf8(std::string("a\0b", 3), false), std::string::npos);
  EXPECT_EQ(first_invalid_utf8("\xc2\x85", true), std::string::npos);  // NEL is printable in YAML
  EXPECT_EQ(first_invalid_utf8("\xc2\x86", true), 0u);
}

TEST(InputLimits, ElementCountsSaturateInsteadOfOverflowing) {
  MeshSpec spec;
  spec.element_length = 1e-300;
  EXPECT_EQ(element_count_for(40.0, spec), kMaxModelNodes);
  spec.element_length = 1e-9;
  EXPECT_EQ(element_count_for(40.0, spec), kMaxModelNodes);
  spec.element_length = 1e300;
  EXPECT_EQ(element_count_for(40.0, spec), 1);
  spec.element_length = 10;
  EXPECT_EQ(element_count_for(1e11, spec), kMaxModelNodes);
  EXPECT_EQ(element_count_for(40.0, spec), 4);
}

TEST(InputLimits, OverlapUsesTheActualStartAngles) {
  StrandSpec s;
  s.length = 200;
  s.layers.resize(2);
  s.layers[0].wire_diameter = 3.94;
  LayerSpec& l = s.layers[1];
  l.wires = 6;
  l.wire_diameter = 3.73;
  l.lay_angle = 11.8 * std::numbers::pi / 180;
  const double even = lateral_clearance(s, 1);
  const double deg = std::numbers::pi / 180;
  l.wire_start_angles = {0, 60 * deg, 120 * deg, 180 * deg, 240 * deg, 300 * deg};
  EXPECT_NEAR(lateral_clearance(s, 1), even, 1e-9);
  l.wire_start_angles = {0, 0, 0, 0, 0, 0};
  EXPECT_NEAR(lateral_clearance(s, 1), -3.73, 1e-9);  // stacked wires: a whole diameter
  EXPECT_TRUE(std::isnan(touching_layer_radius(s, 1)));
  l.wire_start_angles = {300 * deg, 0, 50 * deg, 120 * deg, 180 * deg, 240 * deg};  // order free; 0 and 50 closest
  EXPECT_LT(lateral_clearance(s, 1), even - 0.4);
  // Nearly straight wires: the search stays finite (the lay angle 1e-300 once sent it to z^2 = inf).
  l.wire_start_angles.clear();
  l.lay_angle = 1e-300;
  EXPECT_TRUE(std::isfinite(lateral_clearance(s, 1)));
  EXPECT_NEAR(lateral_clearance(s, 1), layer_radius(s, 1) - 3.73, 1e-9);  // chord 2 R sin(30 deg) = R
}

}  // namespace
}  // namespace strandfem
