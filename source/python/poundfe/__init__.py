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

OpenSeesPy scripts run with `import poundfe.opensees as ops` (poundfe/opensees.py).
"""

# What `import poundfe` runs loads nothing compiled: the first name used
# (poundfe.read, poundfe.InputError, `from poundfe import run`) imports
# poundfe._api, which loads the compiled core _core and deal.II's ~200 shared
# libraries (~0.5 s of CPU); `import poundfe.opensees` loads the lean
# extension _opensees alone (no deal.II; doc/benchmarks.md, "Start-up").
import importlib
import importlib.util
import sys


def _full():
    return importlib.import_module(__name__ + "._api")


def __getattr__(name):
    """A name of poundfe._api, or a submodule (poundfe.model, poundfe._core,
    poundfe.opensees) imported on its first use."""
    if name.startswith("__") and name != "__all__":  # __path__, __file__ exist; others do not
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}")
    loaded = sys.modules.get(__name__ + "._api")  # partly, while it is being imported
    if loaded is not None and name in vars(loaded):
        return vars(loaded)[name]
    if name == "_core" and loaded is None:  # as _api loads it (RTLD_LAZY: _api.py says why)
        return _full()._core
    submodule = f"{__name__}.{name}"
    if submodule in sys.modules or importlib.util.find_spec(submodule) is not None:
        return importlib.import_module(submodule)
    try:
        return getattr(_full(), name)
    except AttributeError:
        raise AttributeError(f"module {__name__!r} has no attribute {name!r}") from None


def __dir__():
    return sorted(set(globals()) | set(_full().__all__))
