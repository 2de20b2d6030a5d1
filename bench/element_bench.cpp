// Times one beam element evaluation (residual only, residual and tangent) on a deformed helical element.
// Usage: element_bench [evaluations]. Run on demand; figures go to docs/performance.md.
#include <chrono>
#include <cstdio>
#include <string>

#include "strandfem/beam/beam_element.hpp"
#include "strandfem/core/rotation.hpp"

using namespace strandfem;

int main(int argc, char** argv) {
  const int evaluations = argc > 1 ? std::stoi(argv[1]) : 20000;
  const ElasticSection section(SectionGeometry::circle(3.0, 0.3), Material{200000, 0.3, 7.85e-9});
  // A helical element (radius 4 mm, lay angle 15 deg) with frames tangent to its centreline.
  std::array<NodeState, 3> reference, current;
  const double radius = 4.0, lay = 15.0 * M_PI / 180, pitch_rate = std::tan(lay) / radius;
  for (int i = 0; i < 3; ++i) {
    const double z = 5.0 * i, phi = pitch_rate * z;
    reference[i].position = Vec3(radius * std::cos(phi), radius * std::sin(phi), z);
    Mat3 frame;
    frame.col(0) = Vec3(-std::sin(phi) * std::sin(lay), std::cos(phi) * std::sin(lay), std::cos(lay));
    frame.col(1) = Vec3(std::cos(phi), std::sin(phi), 0);
    frame.col(2) = frame.col(0).cross(frame.col(1));
    reference[i].rotation = Quaternion(frame).normalized();
    current[i].position = reference[i].position + Vec3(0.01 * i, -0.02, 0.03 * i);
    current[i].rotation = (quaternion_from_rotation_vector(Vec3(0.01, 0.02 * i, -0.03)) * reference[i].rotation).normalized();
  }
  BeamElement element({0, 1, 2}, &section, reference);
  BeamElementState state = element.initial_state();
  BeamElement::Output out;
  using clock = std::chrono::steady_clock;
  double checksum = 0;
  for (bool with_tangent : {false, true}) {
    const auto start = clock::now();
    for (int k = 0; k < evaluations; ++k) {
      element.evaluate(current, state, with_tangent, out);
      checksum += out.residual[k % 18] + out.tangent(k % 18, (k / 18) % 18);
    }
    const double seconds = std::chrono::duration<double>(clock::now() - start).count();
    std::printf("%-22s %8.2f us per element\n", with_tangent ? "residual and tangent" : "residual only",
                1e6 * seconds / evaluations);
  }
  std::printf("checksum %.6e\n", checksum);
  return 0;
}
