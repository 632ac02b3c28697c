"""The names of the package poundfe (read, run, Model, Results, the
commands, the errors): poundfe/__init__.py hands them out from here, and
imports this module (with the compiled core _core and deal.II) at the first
name used, so that `import poundfe.opensees` loads none of it."""

import contextlib
import os
import sys
import threading

import numpy as np

# _core brings deal.II's ~200 shared libraries. Python loads an extension with
# RTLD_NOW, which binds every function each of them calls before the import
# returns (a third more of the loader's work than binding each on its first call,
# as the poundfe executable does: doc/benchmarks.md, "Start-up").
_dlopen_flags = sys.getdlopenflags()
sys.setdlopenflags((_dlopen_flags & ~os.RTLD_NOW) | os.RTLD_LAZY)
try:
    from . import _core
finally:
    sys.setdlopenflags(_dlopen_flags)
    del _dlopen_flags
from ._core import Input, InputError, NumericalError, OutputError, StepState
from .model import Model, _value_text, keyword_table, parameter_text, write_input
from .results import DemandTable, Modes, Results, Table
from .commands import COMMANDS, CommandResult, _command_function, run_command

__all__ = ["read", "run", "modal", "moment_curvature", "command", "Model", "Input", "Results", "Modes", "Table",
           "DemandTable",
           "CommandResult", "StepState", "InputError", "NumericalError", "OutputError",
           "parameter_text", "keyword_table", *COMMANDS]

# poundfe.montecarlo(model, output=None, realizations=None, overrides=None), ...:
# each command of the command line returning a CommandResult (commands.py).
for _python_name, _name in COMMANDS.items():
    globals()[_python_name] = _command_function(_python_name, _name)
del _python_name, _name


Input.write = write_input  # Input.write(path): its every entry as a .prm file

# One run or command at a time in a process: poundfe's engine keeps
# process-wide state (the interruption flag, the output directory's
# manifest, MPI), so a second thread waits for the first, and a callback
# that starts a run inside its own run is refused (it would wait forever).
_engine_lock = threading.Lock()
_engine_owner = None


@contextlib.contextmanager
def _engine():
    global _engine_owner
    if _engine_owner == threading.get_ident():
        raise RuntimeError("poundfe: a run's callback cannot start another run or command "
                           "(start it after the run returns)")
    with _engine_lock:
        _engine_owner = threading.get_ident()
        try:
            yield
        finally:
            _engine_owner = None


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
    pairs = []
    for item in items:
        if not isinstance(item, (tuple, list)) or len(item) != 2:
            raise TypeError(f"overrides: a dict {{'Section/Entry': value}} or (path, value) pairs, "
                            f"not {item!r}")
        path, value = item
        if not isinstance(path, str):
            raise TypeError(f"overrides: a path is a str 'Section/Entry', not {path!r}")
        pairs.append((path, _value_text(value)))
    return pairs


def _input_of(model):
    if isinstance(model, Input):
        return model
    if isinstance(model, Model):
        return model.input()
    return read(model)


def modal(model, output=None, overrides=None):
    """The undamped modes of the whole model and of each building: `poundfe
    modal` through the command line's dispatcher (an Input, a Model or a
    file name; overrides as --set). Without output= nothing is written (the
    shapes are not drawn); with it, its files (summary.json,
    mode_shapes*.csv, modes.pvd) stay there. Returns Modes, with the
    command's summary, report, files and output."""
    return Modes.of_command(run_command("modal", model, output=output, overrides=overrides))


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
    plots, VTU as the input asks), read back into the results; None: no
    file at all, the same observers fill the arrays in memory (no plots or
    VTU).
    callback(state): called at step 0 and every `every` steps with a
    StepState (time, displacement, floor_displacement, drift_ratio, ...);
    an exception it raises stops the run and propagates.

    Returns Results. A numerical failure raises NumericalError with the
    results up to the failure in its `results` attribute. Ctrl-C (or an
    exception of the callback) raises KeyboardInterrupt (or that exception)
    with the results so far, status "interrupted", in its `result`
    attribute, as a command's KeyboardInterrupt holds its result."""
    parameters = _input_of(model)
    directory = None if output is None else os.fspath(output)
    if directory == "":
        raise ValueError("output: a directory, or None for results in memory")
    if callback is not None and not callable(callback):
        raise TypeError(f"callback: a function of the step's state, not {callback!r}")
    if isinstance(every, bool) or not isinstance(every, (int, np.integer)) or every < 1:
        raise ValueError(f"every: a whole number of steps >= 1, not {every!r}")
    try:
        with _engine():
            raw = _core.run_time_history(parameters, directory or "", callback=callback,
                                         every=int(every))
    except InputError as error:  # found when the model is built: named at the caller's line
        if not isinstance(model, Model):
            raise
        raise model._pointed(error) from None
    results = Results(raw, directory)
    if raw["exception"] is not None:  # Ctrl-C, or the callback's: after the files are finished
        error = raw["exception"]
        error.result = results
        raise error
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
    the command refuses raises ValueError with the command line's message.
    Ctrl-C (or SIGTERM) raises KeyboardInterrupt, as every command of
    poundfe does from Python, where the command line exits 128 + the
    signal; its `result` is the CommandResult of what the command wrote
    into output= so far (None without output=)."""
    from .commands import CommandResult, interrupted_or
    with _engine():
        status = _core.command(name, [os.fspath(a) for a in arguments],
                               "" if output is None else os.fspath(output), realizations or 0,
                               _override_pairs(overrides))
    if status >= 128:
        kept = output is not None and os.path.isdir(output)
        interrupted_or(CommandResult(name, os.fspath(output), True) if kept else None, status, name)
    return status
