// Strand cases that several verification tests run.
#pragma once
#include <string>

namespace strandfem::verification {

// The inner 19 wires of S32 (1 + 6 + 12), 200 mm, 10 kN in 3 increments, then 1 kN at midspan and back in 5
// each way, mu = 0.2; `contact_keys` is appended inside the contact mapping (", key: value, ...").
inline std::string nineteen_wire_bent_once(const std::string& contact_keys = "") {
  return R"(
materials:
  core: {E: 200000, nu: 0.3, density: 7.85e-9}
  steel: {E: 180000, nu: 0.3, density: 7.85e-9}
strand:
  length: 200
  ends: fixed
  layers:
    - {wires: 1,  diameter: 3.72, material: core}
    - {wires: 6,  diameter: 3.54, material: steel, lay_angle: 14.22}
    - {wires: 12, diameter: 3.54, material: steel, lay_angle: 13.69}
mesh: {element_length: 10}
contact: {friction: 0.2)" + contact_keys + R"(}
steps:
  - {name: tension, increments: 3, axial_force: 10000}
  - {name: bend, increments: 5, cycles: 1, transverse_force: {value: 1000, z: 100, direction: [0, 1, 0]}}
output: {vtu: false}
)";
}

}  // namespace strandfem::verification
