#include "strandfem/io/model_keys.hpp"

namespace strandfem {

const std::vector<SettingKey<Material>>& material_key_table() {
  static const std::vector<SettingKey<Material>> table = keys_in_section<Material>(KeySection::kPhysics, {
        number_key("E", &Material::youngs_modulus, NumberRange::positive(), "MPa", "Young's modulus").must_be_given(),
        number_key("nu", &Material::poisson_ratio, NumberRange::open(-1, 0.5), "", "Poisson's ratio").must_be_given(),
        number_key("density", &Material::density, NumberRange::non_negative(), "t/mm³", "for the mass per length in summary.json")
            .default_is("—"),
    });
  return table;
}

const std::vector<SettingKey<BilinearHardening>>& plasticity_key_table() {
  using B = BilinearHardening;
  static const std::vector<SettingKey<B>> table = keys_in_section<B>(KeySection::kPhysics, {
        number_key("yield_stress", &B::yield_stress, NumberRange::positive(), "MPa",
                   "bilinear kinematic hardening (docs/theory.md, \"Plasticity\"): wires of this material get a fibre section (4 × 24 "
                   "fibres, J2 per fibre); needs circular sections")
            .must_be_given(),
        number_key("tangent_modulus", &B::tangent_modulus, NumberRange::non_negative(), "MPa", "hardening slope")
            .must_be_given()
            .typed("MPa, 0 ≤ Et < E"),
        choice_key("stress_measure", &B::stress_measure,
                   {{"true_stress", StressMeasure::true_stress}, {"engineering", StressMeasure::engineering}},
                   "the law in true stress against logarithmic strain, or in engineering stress and strain"),
    });
  return table;
}

const std::vector<SettingKey<MeshSpec>>& mesh_key_table() {
  static const std::vector<SettingKey<MeshSpec>> table = keys_in_section<MeshSpec>(KeySection::kPhysics, {
        number_key("element_length", &MeshSpec::element_length, NumberRange::positive(), "mm",
                   "target element length (or `mesh.elements_per_wire`, not both). At most 250,000 nodes (1,500,000 DOFs), checked "
                   "before anything is allocated; elements at least 1e-6 mm and 1e-6 of the coordinates' magnitude long"),
        integer_key("elements_per_wire", &MeshSpec::elements_per_wire, 1, kMaxElementsPerLine,
                    "elements along each wire, instead of `mesh.element_length`")
            .default_is("—"),
    });
  return table;
}

}  // namespace strandfem
