"""A strand case built from Python objects: materials, layers, the strand and its steps. Each object takes the case
file's own keys (docs/case-files.md) as keyword arguments and becomes the nested data the reader checks, so a
built case is checked with the same messages as a file."""


def _keys(fields, extra):
    """The case-file keys of an object: its named fields that are set, then any further keys as given."""
    data = {key: value for key, value in fields.items() if value is not None}
    data.update(extra)
    return data


class Material:
    """A wire material. `name` is its key under `materials`; `plasticity` a dict of the plasticity keys
    (yield_stress, tangent_modulus, stress_measure)."""

    def __init__(self, name, E, nu, density=None, plasticity=None, **keys):
        self.name = name
        self._data = _keys({"E": E, "nu": nu, "density": density, "plasticity": plasticity}, keys)

    def to_dict(self):
        """Its case-file keys as nested data."""
        return dict(self._data)

    def __repr__(self):
        return f"Material({self.name!r}, {self._data})"


class Layer:
    """One layer of wires: the core is a layer of 1 wire without a lay angle; lay_angle in degrees from the axis."""

    def __init__(self, wires, diameter, material, lay_angle=None, lay_direction=None, **keys):
        if not isinstance(material, Material):
            raise TypeError(f"Layer: material must be a strandfem.Material, not {type(material).__name__}")
        self.material = material
        self._data = _keys({"wires": wires, "diameter": diameter, "material": material.name, "lay_angle": lay_angle,
                            "lay_direction": lay_direction}, keys)

    def to_dict(self):
        """Its case-file keys as nested data."""
        return dict(self._data)


class Strand:
    """The strand: its length (mm), its layers from the core out, and its ends (`fixed` or `free`)."""

    def __init__(self, length, layers, ends=None, **keys):
        self.layers = list(layers)
        self._data = _keys({"length": length, "ends": ends}, keys)

    def materials(self):
        """The layers' materials by name, in the order the layers name them; two different materials under one
        name are an error."""
        named = {}
        for layer in self.layers:
            known = named.setdefault(layer.material.name, layer.material)
            if known is not layer.material and known.to_dict() != layer.material.to_dict():
                raise ValueError(f"Strand: two different materials are named {layer.material.name!r}")
        return named

    def to_dict(self):
        """Its case-file keys as nested data, the layers included."""
        return {**self._data, "layers": [layer.to_dict() for layer in self.layers]}


class Step:
    """A load step: its name, its increments and its actions as keyword arguments with the case file's keys
    (axial_strain, axial_force, torque, twist, transverse_force={...}, cycles, forces=[...], motions=[...])."""

    def __init__(self, name, increments, **actions):
        self._data = {"name": name, "increments": increments, **actions}

    def to_dict(self):
        """Its case-file keys as nested data."""
        return dict(self._data)


_BEFORE_STEPS = ("mesh", "supports", "contact", "solver")


def case_data(strand, steps, title=None, **sections):
    """The nested data of a case in the case file's order: the title, the strand's materials collected from its
    layers, the strand, further top-level sections (mesh, supports, contact, solver, output) as dicts with the case
    file's keys, and the steps."""
    data = {"title": title} if title is not None else {}
    data["materials"] = {name: material.to_dict() for name, material in strand.materials().items()}
    data["strand"] = strand.to_dict()
    given = {key: value for key, value in sections.items() if value is not None}
    data.update({key: given.pop(key) for key in _BEFORE_STEPS if key in given})
    data["steps"] = [step.to_dict() for step in steps]
    data.update(given)
    return data
