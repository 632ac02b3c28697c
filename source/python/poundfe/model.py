"""A model built in Python: the sections of a parameter file as nested
dicts, written as .prm text and read by the command line's own reader, so
that every check and message is the command line's.

    model = poundfe.Model()
    model.add_building(name="A", type="shear", number_of_storeys=2,
                       storey_heights=3.0, floor_masses=np.array([2e4, 2e4]),
                       storey_stiffnesses=[3e7, 2.5e7])
    model.add_building(name="B", type="shear", ...)
    model.gaps(0.01, law="hertz-damp", stiffness=2.75e9)
    model.ground_motion(type="kanai-tajimi", stochastic={"Target PGA": 0.3})
    model.set("Ground motion/Stochastic", target_pga=0.3)
    model.set("Time integration", time_step=0.001)
    results = poundfe.run(model)

Names: dict keys are written as they are (the parameter names of the user
guide, e.g. {"Target PGA": 0.3}); keyword arguments are looked up among the
entries and subsections the program declares for the section (what
`poundfe print-parameters` prints): a keyword is an entry's name in lower
case with every run of other characters as one underscore (time_step ->
"Time step", target_pga -> "Target PGA", bouc_wen -> "Bouc-Wen"); an unknown
keyword raises InputError with the names closest to it. Values: a dict is a
subsection, a list, tuple or 1-D NumPy array a comma-separated list, a
float (Python's or NumPy's) its shortest exact text, a bool true/false.

A bad value is found by the command line's reader when the model is read
(Model.input, poundfe.run, ...): its InputError names the entry and the line
of the caller's code that set it.
"""

import difflib
import os
import re
import sys

import numpy as np


def _value_text(value):
    """The .prm text of a value (NumPy scalars and 1-D arrays included)."""
    if isinstance(value, np.ndarray):
        if value.ndim > 1:
            raise TypeError(f"a parameter takes a number or a 1-D list, not a {value.ndim}-D array "
                            f"of shape {value.shape}")
        value = value.tolist()
    elif isinstance(value, np.generic):
        value = value.item()
    if isinstance(value, bool):
        return "true" if value else "false"
    if isinstance(value, float):
        return repr(value)
    if isinstance(value, (list, tuple)):
        return ", ".join(_value_text(v) for v in value)
    return str(value)


def normalised(name):
    """An entry's keyword: "Target PGA" -> "target_pga", "Bouc-Wen" -> "bouc_wen"."""
    return re.sub(r"[^0-9a-z]+", "_", name.lower()).strip("_")


def entry_name(keyword):
    """time_step -> "Time step": a keyword's name in a section the program
    does not declare (its first letter upper case, underscores as spaces)."""
    text = keyword.replace("_", " ")
    return text[:1].upper() + text[1:]


_DECLARED = None


def _declared():
    """({section path: [entry and subsection names]}, {entry path: default
    text}) of everything the program declares ("Building 1" stands for
    every building), parsed from what `poundfe print-parameters` prints."""
    global _DECLARED
    if _DECLARED is None:
        from . import _core
        sections, defaults, stack = {"": []}, {}, []
        for line in _core.declarations().splitlines():
            text = line.strip()
            if text.startswith("subsection "):
                name = text[len("subsection "):].strip()
                sections["/".join(stack)].append(name)
                stack.append(name)
                sections.setdefault("/".join(stack), [])
            elif text == "end":
                stack.pop()
            elif text.startswith("set ") and "=" in text:
                name = text[4:text.index("=")].strip()
                sections["/".join(stack)].append(name)
                defaults["/".join(stack + [name])] = text[text.index("=") + 1:].strip()
        _DECLARED = sections, defaults
    return _DECLARED


def declarations():
    """{section path: [entry and subsection names]} of every section the
    program declares ("Building 1" stands for every building)."""
    return _declared()[0]


def given_values(values):
    """The (path, text) pairs of Input.values that differ from their
    declared defaults (and Model/Number of buildings): what a file must
    say to be read as the same input. (An entry that only acts in another
    configuration, e.g. a 3D entry of a planar model, is refused when
    given, even at its default.)"""
    defaults = _declared()[1]
    return [(path, text) for path, text in values
            if path == "Model/Number of buildings" or
            defaults.get(re.sub(r"^Building \d+/", "Building 1/", path)) != text]


def keyword_table(section):
    """{keyword: name} of the entries and subsections of `section` (a path;
    "Building <i>" as "Building 1"); None for a section not declared."""
    path = re.sub(r"^Building \d+", "Building 1", section)
    names = declarations().get(path)
    if names is None:
        return None
    return {normalised(name): name for name in names}


def _name_of_keyword(section, keyword):
    """The declared name of `keyword` in `section` (InputError with the
    closest keywords when there is none)."""
    table = keyword_table(section)
    if table is None:
        return entry_name(keyword)
    name = table.get(normalised(keyword))
    if name is not None:
        return name
    from . import InputError
    close = difflib.get_close_matches(normalised(keyword), list(table), n=3, cutoff=0.6)
    hint = ("; did you mean " + " or ".join(f"{k} ('{table[k]}')" for k in close)) if close else ""
    error = InputError(f"'{section}' has no entry or subsection '{keyword}'{hint} "
                       f"(its keywords: {', '.join(sorted(table))})")
    error.file, error.line, error.parameter = "", 0, f"{section}/{keyword}"
    error.problem = "unknown keyword"
    raise error


def _caller():
    """'file:line' of the first frame outside this package: the user's call."""
    here = os.path.dirname(os.path.abspath(__file__))
    frame = sys._getframe(1)
    while frame is not None and os.path.dirname(os.path.abspath(frame.f_code.co_filename)) == here:
        frame = frame.f_back
    return f"{frame.f_code.co_filename}:{frame.f_lineno}" if frame is not None else "?"


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


def nested(values):
    """(path, text) pairs as nested dicts (Input.values -> sections)."""
    sections = {}
    for path, text in values:
        *parts, name = path.split("/")
        target = sections
        for part in parts:
            target = target.setdefault(part, {})
        target[name] = text
    return sections


def _merge(into, entries):
    for name, value in entries.items():
        if isinstance(value, dict):
            _merge(into.setdefault(name, {}), value)
        else:
            into[name] = value


def _paths(entries, prefix):
    """Every entry's path under `prefix` (for the callers' lines)."""
    for name, value in entries.items():
        if isinstance(value, dict):
            yield from _paths(value, f"{prefix}/{name}")
        else:
            yield f"{prefix}/{name}"


def _absolute_name(text, name, path):
    """`text` (an entry's value) with `name` as a whole field (between blanks,
    commas or semicolons: a tabulated force's file among its numbers)
    replaced by `path`."""
    return re.sub(r"(?<![^\s,;])" + re.escape(name) + r"(?![^\s,;])", lambda _: path, text)


def absolute_files(sections, files, base):
    """A copy of `sections` (nested dicts) in which each relative file name
    of `files` ((entry, name) pairs: Input.input_files, every file the
    reader found named) is made absolute against `base` (the working
    directory, or the directory of the file a model was read from), so the
    text reads the same files wherever it is written."""
    out = {name: absolute_files(value, (), base) if isinstance(value, dict) else value
           for name, value in sections.items()}
    for entry, name in files:
        if os.path.isabs(name):
            continue
        *parts, key = entry.split("/")
        target = out
        for part in parts:
            target = target.get(part) if isinstance(target, dict) else None
        if isinstance(target, dict) and key in target:
            target[key] = _absolute_name(_value_text(target[key]), name,
                                         os.path.abspath(os.path.join(base, name)))
    return out


def absolute_overrides(pairs, files, base):
    """(path, text) overrides with the relative file names `files` names
    for their entries made absolute against `base`."""
    named = {}
    for entry, name in files:
        if not os.path.isabs(name):
            named.setdefault(entry, []).append(name)
    out = []
    for path, text in pairs:
        for name in named.get(path, []):
            text = _absolute_name(text, name, os.path.abspath(os.path.join(base, name)))
        out.append((path, text))
    return out


class Model:
    """A parameter file under construction (see the module's text)."""

    def __init__(self):
        self.sections = {"Model": {}}
        self.buildings = []
        self.origins = {}  # entry path -> the caller's 'file:line' that set it

    @classmethod
    def from_file(cls, file, overrides=None):
        """The model of a .prm or .json file (read and checked by the
        command line's reader, with overrides): every entry that differs
        from its default, file names made absolute."""
        from . import read
        return cls.from_input(read(file, overrides))

    @classmethod
    def from_input(cls, input):
        """The model of an Input (its entries that differ from their
        defaults, file names made absolute)."""
        sections = absolute_files(nested(given_values(input.values)), input.input_files,
                                  input.directory or os.getcwd())
        model = cls()
        n = int(sections.get("Model", {}).pop("Number of buildings", 0))
        model.buildings = [sections.pop(f"Building {i}", {}) for i in range(1, n + 1)]
        model.sections = {"Model": sections.pop("Model", {}), **sections}
        return model

    def _keywords(self, section, entries, keywords):
        values = dict(entries or {})
        values.update({_name_of_keyword(section, k): v for k, v in keywords.items()})
        origin = _caller()
        for path in _paths(values, section):
            self.origins[path] = origin
        return values

    def set(self, section, entries=None, **keywords):
        """Set entries of `section` ("Time integration", or a path such as
        "Ground motion/Stochastic"): a dict (names as written) and/or
        keyword arguments (time_step=0.001). Returns the model."""
        values = self._keywords(section, entries, keywords)
        target = self.sections
        for part in section.split("/"):
            target = target.setdefault(part, {})
        _merge(target, values)
        return self

    def add_building(self, entries=None, **keywords):
        """A building (its `Building <i>` section); returns its number i.
        Subsections as dicts: hinges={"Locations": "column bases"}."""
        values = self._keywords(f"Building {len(self.buildings) + 1}", entries, keywords)
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

    def _all_sections(self):
        """Every section as a parameter file holds them (buildings numbered)."""
        sections = {"Model": {"Number of buildings": len(self.buildings),
                              **self.sections["Model"]}}
        for i, building in enumerate(self.buildings, 1):
            sections[f"Building {i}"] = building
        sections.update({k: v for k, v in self.sections.items() if k != "Model"})
        return sections

    def text(self):
        """The .prm text (file names as given: relative ones are taken
        against the directory of the file it is written to)."""
        return parameter_text(self._all_sections()) + "\n"

    def absolute_text(self, input):
        """The .prm text with the relative names of the files `input` (this
        model read: Model.input) names made absolute against the working
        directory, to be written elsewhere and read the same."""
        return parameter_text(absolute_files(self._all_sections(), input.input_files,
                                             os.getcwd())) + "\n"

    def write(self, path):
        """Write the .prm file (`poundfe run path` runs the same model)."""
        with open(path, "w") as f:
            f.write(self.text())

    def input(self, overrides=None, name="model.prm"):
        """Read through the command line's reader: an Input. The reader
        parses the model's text itself (no file is written), named `name`;
        a bad entry raises the reader's InputError naming `name`, the line
        of the text, the entry and the line of the caller's code that set
        it. Relative file names are taken against the working directory.
        (A command given the Model still reads it from a temporary file, its
        file names made absolute: a sweep reads its file again for each
        value.)"""
        from . import InputError, _core, _override_pairs
        try:
            return _core.read_text(name, self.text(), _override_pairs(overrides))
        except InputError as error:
            raise self._pointed(error) from None

    def _pointed(self, error, temporary=None):
        """The reader's error with the caller's line that set the entry (and
        without `temporary`, the directory a command read the model's file
        from)."""
        from . import InputError
        message = str(error).replace(temporary, "") if temporary else str(error)
        parameter = getattr(error, "parameter", "") or ""
        origin = self.origins.get(parameter)
        if origin is None:  # a whole list entry "Section/Entry:k", or a section
            origin = next((o for p, o in self.origins.items()
                           if parameter and (p.startswith(parameter.split(":")[0]))), None)
        if origin is not None:
            message += f" (set at {origin})"
        pointed = InputError(message)
        pointed.file = getattr(error, "file", "") or ""
        if temporary:
            pointed.file = pointed.file.replace(temporary, "")
        pointed.line = getattr(error, "line", 0)
        pointed.parameter = parameter
        pointed.problem = getattr(error, "problem", "")
        pointed.origin = origin
        return pointed

    def __repr__(self):
        return f"<poundfe.Model {len(self.buildings)} buildings>"


def write_input(input, path):
    """Input.write(path): a read Input (with its overrides) as a .prm file
    of every entry that differs from its default (file names absolute),
    which reads back to the same entries."""
    sections = absolute_files(nested(given_values(input.values)), input.input_files,
                              input.directory or os.getcwd())
    with open(path, "w") as f:
        f.write(parameter_text(sections) + "\n")
