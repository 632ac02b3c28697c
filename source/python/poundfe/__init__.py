"""poundfe from Python: read or build a model of adjacent buildings that
pound, run a time history or any command of the command line, and get the
results as NumPy arrays.

    import poundfe
    model = poundfe.read("input/two-buildings.prm", overrides={"Model/Separations": 0.02})
    results = poundfe.run(model)
    results.drift.time, results.drift["A3_storey1_drift_ratio"]
    results.peaks["A3"]["drift_ratio"], results.impacts["peak_force_N"]

Everything goes through the command line's own reader and engine: the same
checks, messages and numbers (a run's arrays are the doubles of its CSV
files). Bad input raises poundfe.InputError (a ValueError), a numerical
failure poundfe.NumericalError (a RuntimeError).
"""

import os
import shutil
import tempfile

from . import _core
from ._core import Input, InputError, NumericalError, OutputError, StepState
from .model import Model, _value_text, parameter_text
from .results import Modes, Results, Table

__all__ = ["read", "run", "modal", "moment_curvature", "command", "Model", "Input", "Results", "Modes", "Table",
           "StepState", "InputError", "NumericalError", "OutputError", "parameter_text"]


def read(file, overrides=None):
    """Read and check a .prm or .json parameter file.

    overrides: {"Section/Entry": value} (or (path, value) pairs), applied
    before the checks as `poundfe sweep` does; "Section/Entry:k" sets the
    k-th field of a list entry. Raises InputError naming file, line and
    parameter."""
    return _core.read(os.fspath(file), _override_pairs(overrides))


def _override_pairs(overrides):
    """(path, text) pairs of a dict or of (path, value) pairs (None: none)."""
    items = overrides.items() if isinstance(overrides, dict) else (overrides or [])
    return [(str(path), _value_text(value)) for path, value in items]


def _input_of(model):
    if isinstance(model, Input):
        return model
    if isinstance(model, Model):
        return model.input()
    return read(model)


def modal(model):
    """The undamped modes of the whole model and of each building (what
    `poundfe modal` writes): an Input, a Model or a file name."""
    return Modes(_core.modal(_input_of(model)))


def moment_curvature(model, overrides=None):
    """The moment-curvature curve of a section (what `poundfe
    moment-curvature` computes), from a parameter file (with overrides as
    in read()) or an Input with Sections and Moment curvature sections.

    Returns a dict: NumPy arrays curvature (1/m), moment (N m),
    axial_strain, concrete_strain_min, steel_strain_max, steel_strain_min,
    tangent (N m^2), moment_z, moment_y; first_yield, peak, ultimate
    ({"curvature", "moment"}), ductility, stop_reason, fibres and events
    [(what, curvature, moment)]."""
    if not isinstance(model, Input):
        model = read(model, overrides)
    return _core.moment_curvature(model)


def run(model, output=None, callback=None, every=1):
    """Run the time history of `model` (an Input, a Model or a file name).

    output: a directory for the command line's files (CSV, summary.json,
    plots, VTU as the input asks); None: a temporary one, removed after the
    results are read (NumPy tables, no plots or VTU).
    callback(state): called at step 0 and every `every` steps with a
    StepState (time, displacement, floor_displacement, drift_ratio, ...);
    an exception it raises stops the run and propagates.

    Returns Results. A numerical failure raises NumericalError with the
    results up to the failure in its `results` attribute."""
    model = _input_of(model)
    temporary = output is None
    directory = tempfile.mkdtemp(prefix="poundfe-") if temporary else os.fspath(output)
    try:
        raw = _core.run_time_history(model, directory, npy=temporary, vtu_and_plots=not temporary,
                                     callback=callback, every=every)
        results = Results(directory, raw)
    finally:
        if temporary:
            shutil.rmtree(directory, ignore_errors=True)
    if raw["status"] == "failed":
        error = (OutputError if raw["output_failed"] else NumericalError)(raw["message"])
        error.results = results
        raise error
    return results


def command(name, *arguments, output=None, realizations=None, overrides=None):
    """Run a command of the command line exactly as `poundfe NAME ARGUMENTS
    [--output DIR] [--realizations N] [--set PATH=VALUE]...` does (the same
    dispatcher, rules and messages), e.g.
    poundfe.command("sweep", "input/two-buildings.prm", output="results/sweep",
                    overrides={"Model/Separations": 0.02}).
    overrides: {"Section/Entry": value} (or (path, value) pairs), as read()'s.
    Returns the exit status (0; 2 after a numerical failure, the files so far
    kept); bad input raises InputError and writes nothing, a command line
    the command refuses raises ValueError with the command line's message."""
    return _core.command(name, [os.fspath(a) for a in arguments],
                         "" if output is None else os.fspath(output), realizations or 0,
                         _override_pairs(overrides))
