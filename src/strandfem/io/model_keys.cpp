#include "strandfem/io/model_keys.hpp"

namespace strandfem {
namespace {
// Keys of the strand's own description: listed with the physics, not under "Advanced".
template <class Settings>
std::vector<SettingKey<Settings>> physics(std::vector<SettingKey<Settings>> table) {
  for (auto& key : table) key.section = KeySection::kPhysics;
  return table;
}
}  // namespace

const std::vector<SettingKey<Material>>& material_key_table() {
  static const std::vector<SettingKey<Material>> table = [] {
    auto t = physics<Material>({
        number_key("E", &Material::youngs_modulus, NumberRange::positive(), "MPa", "Young's modulus"),
        number_key("nu", &Material::poisson_ratio, NumberRange::open(-1, 0.5), "", "Poisson's ratio"),
        number_key("density", &Material::density, NumberRange::non_negative(), "t/mm³", "for the mass per length in summary.json"),
    });
    t[0].required = t[1].required = true;
    t[2].default_rule = "—";
    return t;
  }();
  return table;
}

const std::vector<SettingKey<BilinearHardening>>& plasticity_key_table() {
  using B = BilinearHardening;
  static const std::vector<SettingKey<B>> table = [] {
    auto t = physics<B>({
        number_key("yield_stress", &B::yield_stress, NumberRange::positive(), "MPa",
                   "bilinear kinematic hardening (docs/theory.md, \"Plasticity\"): wires of this material get a fibre section (4 × 24 "
                   "fibres, J2 per fibre); needs circular sections"),
        number_key("tangent_modulus", &B::tangent_modulus, NumberRange::non_negative(), "MPa", "hardening slope"),
        choice_key("stress_measure", &B::stress_measure,
                   {{"true_stress", StressMeasure::true_stress}, {"engineering", StressMeasure::engineering}},
                   "the law in true stress against logarithmic strain, or in engineering stress and strain"),
    });
    t[0].required = t[1].required = true;
    t[1].type = "MPa, 0 ≤ Et < E";
    return t;
  }();
  return table;
}

const std::vector<SettingKey<MeshSpec>>& mesh_key_table() {
  static const std::vector<SettingKey<MeshSpec>> table = [] {
    auto t = physics<MeshSpec>({
        number_key("element_length", &MeshSpec::element_length, NumberRange::positive(), "mm",
                   "target element length (or `mesh.elements_per_wire`, not both). At most 250,000 nodes (1,500,000 DOFs), checked "
                   "before anything is allocated; elements at least 1e-6 mm and 1e-6 of the coordinates' magnitude long"),
        integer_key("elements_per_wire", &MeshSpec::elements_per_wire, 1, kMaxElementsPerLine,
                    "elements along each wire, instead of `mesh.element_length`"),
    });
    t[1].default_rule = "—";
    return t;
  }();
  return table;
}

}  // namespace strandfem
