"""A model built in Python: the sections of a parameter file as nested
dicts, written as .prm text and read by the command line's own reader, so
that every check and message is the command line's.

    model = poundfe.Model()
    model.add_building(name="A", type="shear", number_of_storeys=2,
                       storey_heights=3.0, floor_masses=[2e4, 2e4],
                       storey_stiffnesses=[3e7, 2.5e7])
    model.add_building(name="B", type="shear", ...)
    model.gaps(0.01, law="hertz-damp", stiffness=2.75e9)
    model.ground_motion(type="kanai-tajimi", stochastic={"Target PGA": 0.3})
    model.set("Time integration", time_step=0.001)
    results = poundfe.run(model)

Names: dict keys are written as they are (the parameter names of the user
guide, e.g. {"Target PGA": 0.3}); keyword arguments are turned into them
with underscores as spaces and the first letter upper-case (time_step ->
"Time step", column_E -> "Column E"). A dict value is a subsection, a list a
comma-separated list, a float its shortest exact text.
"""

import os
import tempfile


def entry_name(keyword):
    """time_step -> "Time step" (a keyword argument's parameter name)."""
    text = keyword.replace("_", " ")
    return text[:1].upper() + text[1:]


def _value_text(value):
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, (list, tuple)):
        return ", ".join(_value_text(v) for v in value)
    return str(value)


# Entries that name a file: made absolute (against the working directory)
# when a Model is read from a temporary file.
_FILE_ENTRIES = ("File", "Mesh file", "Catalogue file")


def parameter_text(sections, indent=""):
    """Nested dicts as the text of a .prm file."""
    lines = []
    for name, value in sections.items():
        if isinstance(value, dict):
            lines.append(f"{indent}subsection {name}")
            lines.append(parameter_text(value, indent + "  "))
            lines.append(f"{indent}end")
        else:
            lines.append(f"{indent}set {name} = {_value_text(value)}")
    return "\n".join(line for line in lines if line)


def _merge(into, entries):
    for name, value in entries.items():
        if isinstance(value, dict):
            _merge(into.setdefault(name, {}), value)
        else:
            into[name] = value


def _absolute_files(sections, base):
    out = {}
    for name, value in sections.items():
        if isinstance(value, dict):
            out[name] = _absolute_files(value, base)
        elif name in _FILE_ENTRIES and isinstance(value, str) and value and not os.path.isabs(value):
            out[name] = os.path.join(base, value)
        else:
            out[name] = value
    return out


class Model:
    """A parameter file under construction (see the module's text)."""

    def __init__(self):
        self.sections = {"Model": {}}
        self.buildings = []

    def set(self, section, entries=None, **keywords):
        """Set entries of `section` ("Time integration", or a path such as
        "Ground motion/Stochastic"): a dict (names as written) and/or
        keyword arguments (time_step=0.001). Returns the model."""
        values = dict(entries or {})
        values.update({entry_name(k): v for k, v in keywords.items()})
        target = self.sections
        for part in section.split("/"):
            target = target.setdefault(part, {})
        _merge(target, values)
        return self

    def add_building(self, entries=None, **keywords):
        """A building (its `Building <i>` section); returns its number i.
        Subsections as dicts: hinges={"Locations": "column bases"}."""
        values = dict(entries or {})
        values.update({entry_name(k): v for k, v in keywords.items()})
        self.buildings.append(values)
        return len(self.buildings)

    def gaps(self, separations, **contact):
        """Model/Separations (m: one for all neighbours or one per pair) and
        the Contact section (law="hertz-damp", stiffness=..., ...)."""
        self.set("Model", {"Separations": separations})
        return self.set("Contact", **contact)

    def ground_motion(self, entries=None, **keywords):
        """The Ground motion section, e.g. type="record", record={"File": ...}."""
        return self.set("Ground motion", entries, **keywords)

    def text(self):
        """The .prm text."""
        sections = {"Model": {"Number of buildings": len(self.buildings),
                              **self.sections["Model"]}}
        for i, building in enumerate(self.buildings, 1):
            sections[f"Building {i}"] = building
        sections.update({k: v for k, v in self.sections.items() if k != "Model"})
        return parameter_text(sections) + "\n"

    def write(self, path):
        """Write the .prm file (`poundfe run path` runs the same model)."""
        with open(path, "w") as f:
            f.write(self.text())

    def input(self, overrides=None, name="model.prm"):
        """Read through the command line's reader: an Input. The text goes
        to a temporary file `name` (the messages name it); file names in it
        are taken against the working directory."""
        from . import read
        absolute = Model()
        absolute.sections = _absolute_files(self.sections, os.getcwd())
        absolute.buildings = [_absolute_files(b, os.getcwd()) for b in self.buildings]
        with tempfile.TemporaryDirectory(prefix="poundfe-model-") as directory:
            path = os.path.join(directory, name)
            absolute.write(path)
            return read(path, overrides)

    def __repr__(self):
        return f"<poundfe.Model {len(self.buildings)} buildings>"
