#include "strandfem/io/beam_keys.hpp"

#include "strandfem/mesh/mesh.hpp"

namespace strandfem {

const std::vector<SettingKey<BeamKeys>>& beam_key_table() {
  using B = BeamKeys;
  static const std::vector<SettingKey<B>> table = keys_in_section<B>(KeySection::kPhysics, {
        text_key("name", &B::name, "text", "the line's name, for selectors").must_be_given(),
        text_key("material", &B::material, "name", "one of `materials`").must_be_given(),
        integer_key("elements", &B::elements, 1, kMaxElementsPerLine, "elements along the line (the model-size limit above applies)")
            .must_be_given(),
    });
  return table;
}

const std::vector<SettingKey<SectionKeys>>& section_key_table() {
  using S = SectionKeys;
  const auto positive = [](const char* name, double S::*member, const char* unit, const char* meaning) {
    return number_key(name, member, NumberRange::positive(), unit, meaning).default_is("—");
  };
  static const std::vector<SettingKey<S>> table = keys_in_section<S>(KeySection::kPhysics, {
        optional_number_key("diameter", &S::diameter, NumberRange::positive(), "mm", "a circular section; or the five keys below"),
        positive("area", &S::area, "mm²", "general section"),
        positive("inertia_2", &S::inertia_2, "mm⁴", "second moment about section axis 2"),
        positive("inertia_3", &S::inertia_3, "mm⁴", "second moment about section axis 3"),
        positive("torsion_constant", &S::torsion_constant, "mm⁴", "torsion constant"),
        positive("shear_factor", &S::shear_factor, "", "shear correction factor"),
    });
  return table;
}

const std::vector<SettingKey<BeamLineSpec>>& shape_key_table() {
  using L = BeamLineSpec;
  static const std::vector<SettingKey<L>> table = keys_in_section<L>(KeySection::kPhysics, {
        choice_key("type", &L::shape, {{"straight", L::kStraight}, {"arc", L::kArc}, {"helix", L::kHelix}},
                   "the centerline's kind; the keys below belong to one kind each")
            .must_be_given(),
        vector_key("start", &L::start, "`[x, y, z]` mm", "straight: first point").default_is("—"),
        vector_key("end", &L::end, "`[x, y, z]` mm", "straight: last point").default_is("—"),
        vector_key("normal", &L::normal, "`[x, y, z]`", "straight: the section's axis 2").default_is("—"),
        vector_key("center", &L::center, "`[x, y, z]` mm", "arc: centre").default_is("—"),
        number_key("radius", &L::radius, NumberRange::positive(), "mm", "arc or helix radius").default_is("—"),
        degree_key("start_angle", &L::start_angle, NumberRange::any(),
                   "arc: first angle, in the plane normal to `axis` from x; helix: angular position at z = 0")
            .default_is("0 (helix)"),
        degree_key("end_angle", &L::end_angle, NumberRange::any(), "arc: last angle").default_is("—"),
        vector_key("axis", &L::axis, "`[x, y, z]`", "arc: the plane's normal").default_is("`[0, 0, 1]`"),
        degree_key("lay_angle", &L::lay_angle, NumberRange::open(0, 90), "helix: lay angle").default_is("—"),
        number_key("length", &L::length, NumberRange::positive(), "mm", "helix: axial length").default_is("—"),
        choice_key("lay_direction", &L::lay_direction, {{"right", 1}, {"left", -1}}, "helix"),
    });
  return table;
}

const std::vector<ShapeKind>& shape_kinds() {
  static const std::vector<ShapeKind> kinds = {
      {"straight", {"type", "start", "end", "normal"}, {"start", "end"}},
      {"arc", {"type", "center", "radius", "start_angle", "end_angle", "axis"}, {"center", "radius", "start_angle", "end_angle"}},
      {"helix", {"type", "radius", "lay_angle", "length", "lay_direction", "start_angle"}, {"radius", "lay_angle", "length"}},
  };
  return kinds;
}

const std::vector<SettingKey<HubKeys>>& hub_key_table() {
  using H = HubKeys;
  static const std::vector<SettingKey<H>> table = keys_in_section<H>(KeySection::kPhysics, {
        text_key("name", &H::name, "text", "a rigid plate node").must_be_given(),
        vector_key("position", &H::position, "`[x, y, z]` mm", "where it is").must_be_given(),
        node_key("links", &H::links, "list of selectors",
                 "beam nodes that follow it exactly (`{beam: name}` alone: every node of that beam)")
            .must_be_given(),
    });
  return table;
}

const std::vector<SettingKey<SelectorKeys>>& strand_selector_key_table() {
  using S = SelectorKeys;
  static const std::vector<SettingKey<S>> table = keys_in_section<S>(KeySection::kPhysics, {
        choice_key("core", &S::core, {{"start", std::string("start")}, {"end", std::string("end")}}, "strands: the core's end node")
            .default_is("—"),
        optional_number_key("core_z", &S::core_z, NumberRange::any(), "mm", "strands: the core node nearest z (not with `core`)"),
    });
  return table;
}

const std::vector<SettingKey<SelectorKeys>>& beam_selector_key_table() {
  using S = SelectorKeys;
  static const std::vector<SettingKey<S>> table = keys_in_section<S>(KeySection::kPhysics, {
        text_key("beam", &S::beam, "name", "beam cases: a beam line, with `point` or `node` (alone in hub links: every node)")
            .default_is("—"),
        choice_key("point", &S::point, {{"start", std::string("start")}, {"middle", std::string("middle")}, {"end", std::string("end")}},
                   "beam cases")
            .default_is("—"),
        optional_integer_key("node", &S::node, 0, 2 * kMaxElementsPerLine, "beam cases: node k along the line (not with `point`)"),
        text_key("hub", &S::hub, "name", "beam cases: a hub").default_is("—"),
    });
  return table;
}

}  // namespace strandfem
