"""Every command of the command line as a Python function returning a
CommandResult: poundfe.montecarlo(model), poundfe.sweep(model, ...), ...

Each runs through the command line's own dispatcher (the same rules, checks,
messages and numbers as `poundfe NAME FILE --output DIR --set ...`) and
takes a file name, an Input (its file and overrides) or a Model. Without
`output=`, every command here (its row's in_memory column: _core.in_memory)
leaves its results in memory and writes no file: its tables come as the
doubles its CSV files would hold, its other files as their texts, parsed as
the files would be. Given `output=`, a command writes its files, read back
into arrays. (poundfe.modal returns the modal command's results as Modes,
and poundfe.run its Results.)
"""

import json
import os
import shutil
import tempfile

from . import _core
from .model import absolute_overrides
from .results import Table, _pandas, dataframe_of, memory_table, read_csv, read_csv_text, read_npy

# The Python name of each command of item: its name on the command line.
COMMANDS = {
    "montecarlo": "montecarlo", "subset": "subset", "fragility": "fragility", "sweep": "sweep",
    "separation": "separation", "spectrum": "spectrum", "site_hazard": "site-hazard",
    "reliability": "reliability", "dynamic_form": "dynamic-form", "mitigation": "mitigation",
    "stationary_pdf": "stationary-pdf", "bifurcation": "bifurcation", "switching": "switching",
    "ground_motion": "ground-motion", "pushover": "pushover", "ida": "ida", "msa": "msa",
}


def read_directory(directory):
    """{stem: table} of every CSV and NPY table under `directory` (a
    subdirectory's tables as "sub/stem"), and summary.json as a dict (None
    without one)."""
    tables, summary = {}, None
    for root, folders, files in os.walk(directory):
        folders.sort()
        for name in sorted(files):
            path = os.path.join(root, name)
            stem = os.path.splitext(os.path.relpath(path, directory))[0].replace(os.sep, "/")
            if name.endswith(".csv"):
                tables[stem] = read_csv(path)
            elif name.endswith(".npy"):
                tables[stem] = read_npy(path)
            elif name == "summary.json" and root == directory:
                with open(path) as f:
                    summary = json.load(f)
    return tables, summary


class CommandResult:
    """What a command wrote, as arrays.

    command: its name; status: summary.json's ("completed", ...); summary:
    summary.json as a dict; tables: {stem: Table (first column time_s) or
    structured array (one field per column)} of every CSV and NPY table it
    wrote, also as attributes (result.separation); files: the files it
    wrote; output: where they stay (None: removed); report: what the
    command line prints on standard output (its report; nothing is printed).
    to_dataframe(stem) needs pandas."""

    def __init__(self, command, directory, kept):
        self.command = command
        self.tables, self.summary = read_directory(directory)
        self.status = (self.summary or {}).get("status")
        self.files = sorted(os.path.relpath(os.path.join(r, f), directory)
                            for r, _, fs in os.walk(directory) for f in fs)
        self.output = directory if kept else None

    @classmethod
    def in_memory(cls, command, raw):
        """What `_core.command_in_memory` left: its tables (doubles) and
        texts by file name, as read_directory reads the same files; files
        lists the names they would have had."""
        result = cls.__new__(cls)
        result.command = command
        tables = {stem: memory_table(names, array) for stem, names, array in raw["tables"]}
        texts = raw["texts"]
        for name in texts:
            if name.endswith(".csv"):
                tables[name[:-4]] = read_csv_text(texts[name])
        result.tables = dict(sorted(tables.items()))
        result.summary = json.loads(texts["summary.json"]) if "summary.json" in texts else None
        result.status = (result.summary or {}).get("status")
        result.files = sorted([stem + ".csv" for stem, _, _ in raw["tables"]] + list(texts))
        result.output = None
        result.report = raw["report"]
        return result

    def to_dataframe(self, name=None):
        """Table `name` as a pandas DataFrame (name may be left out when
        there is one table). ImportError without pandas."""
        _pandas()
        if name is None:
            if len(self.tables) != 1:
                raise ValueError(f"name a table: {', '.join(self.tables)}")
            name = next(iter(self.tables))
        return dataframe_of(self[name])

    def __getitem__(self, name):
        try:
            return self.tables[name]
        except KeyError:
            raise KeyError(f"'{self.command}' wrote no table '{name}' "
                           f"(tables: {', '.join(self.tables)})") from None

    def __getattr__(self, name):
        tables = self.__dict__.get("tables", {})
        if name in tables:
            return tables[name]
        raise AttributeError(f"no attribute or table '{name}' (tables: {', '.join(tables)})")

    def __repr__(self):
        return f"<poundfe.CommandResult {self.command} {self.status}: {', '.join(self.tables)}>"


def _file_and_overrides(model, overrides, scratch, read):
    """The parameter file the dispatcher reads and the (path, text)
    overrides: a file name as it is, an Input's file and overrides (then
    `overrides`), a Model written into `scratch` (`read`: its Input, whose
    relative file names, in the text and in the overrides, are made
    absolute against the working directory, as the reader took them)."""
    from . import Input, Model, _override_pairs
    pairs = _override_pairs(overrides)
    if isinstance(model, Input):
        return model.file, list(model.overrides) + pairs
    if isinstance(model, Model):
        path = os.path.join(scratch, "model.prm")
        with open(path, "w") as f:
            f.write(model.absolute_text(read))
        return path, absolute_overrides(pairs, read.input_files, os.getcwd())
    return os.fspath(model), pairs


def _is_model(model):
    """A Model, which the dispatcher reads from a file written for it."""
    from . import Model
    return isinstance(model, Model)


def run_command(name, model, output=None, realizations=None, overrides=None):
    """`poundfe NAME FILE [--output DIR] [--realizations N] [--set ...]`
    through the command line's dispatcher, its files read back: a
    CommandResult. Bad input raises InputError (nothing written), a
    refused command line ValueError, a numerical failure NumericalError
    (with output=, the files so far and summary.json stay there). Without
    output=, a command that can leaves its results in memory: no result
    file (a Model's parameter file alone, in a temporary directory)."""
    from . import InputError, _engine
    # a Model's bad values named at the caller's line, before any file
    read = model.input(overrides) if _is_model(model) else None
    kept = output is not None
    in_memory = not kept and _core.in_memory(name)
    # a temporary directory only for what must be a file: a Model's
    # parameter file, the output of a command that cannot keep it in memory
    scratch = tempfile.mkdtemp(prefix="poundfe-") if _is_model(model) or not (kept or in_memory) \
        else None
    try:
        file, pairs = _file_and_overrides(model, overrides, scratch, read)
        if in_memory:
            with _engine():
                raw = _core.command_in_memory(name, [file], realizations or 0, pairs)
            return interrupted_or(CommandResult.in_memory(name, raw), raw["exit_status"])
        directory = os.fspath(output) if kept else os.path.join(scratch, "output")
        with _engine():
            status, report = _core.command_reported(name, [file], directory, realizations or 0,
                                                    pairs)
        result = CommandResult(name, directory, kept)
        result.report = report
        return interrupted_or(result, status)
    except InputError as error:
        if not _is_model(model):
            raise
        raise model._pointed(error, os.path.join(scratch, "")) from None
    finally:
        if scratch:
            shutil.rmtree(scratch, ignore_errors=True)


def interrupted_or(result, status, command=None):
    """`result`, or KeyboardInterrupt carrying it when Ctrl-C (or SIGTERM)
    stopped the command: the command line's exit status 128 + signal, its
    results so far kept (in memory, or in output= for a later run to
    resume from). `command`: its name when there is no result (None)."""
    if status >= 128:
        name = command if result is None else result.command
        kept = "none" if result is None else "in this exception's `result`"
        error = KeyboardInterrupt(f"poundfe: {name} interrupted; its results so far: {kept}")
        error.result = result
        raise error
    return result


def _command_function(python_name, name):
    def command(model, output=None, realizations=None, overrides=None):
        return run_command(name, model, output=output, realizations=realizations,
                           overrides=overrides)
    command.__name__ = python_name
    command.__doc__ = (f"`poundfe {name} FILE` from Python: model is a file name, an Input or a "
                       f"Model; output a directory to keep the files in (None: none kept); "
                       f"realizations as --realizations; overrides as --set. Returns a "
                       f"CommandResult (summary, tables as arrays, to_dataframe).")
    return command
