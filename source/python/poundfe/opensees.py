"""OpenSees's commands with OpenSeesPy's calling conventions, on poundfe:

    import poundfe.opensees as ops

    ops.wipe()
    ops.model('basic', '-ndm', 2, '-ndf', 3)
    ops.node(1, 0.0, 0.0)
    ...
    ops.analyze(10)          # 0, or a negative int when a step failed
    ops.nodeDisp(3, 1)       # a float; ops.nodeDisp(3): a list of floats

so that an OpenSeesPy script runs by changing its import line. Each command
is a thin function over ONE entry of the lean extension _opensees
(opensees_call: the interpreter's library alone, no deal.II),
which hands the arguments, as the words a Tcl script would give, to the same
command procedures as `poundfe opensees SCRIPT.tcl` on one domain per Python
process (`wipe` clears it). The functions are made from the core's own list
of commands, so nothing is listed twice; a command poundfe lacks is here too
and raises OpenSeesError naming it.

Arguments: int, float, str, NumPy scalars; a list, tuple or NumPy array is
one list argument (`'-values', values` of a Path series; `'-values',
*values` works too). Results: float, int, list of floats or ints, or None,
as OpenSeesPy returns them (`eigen` a list, `analyze` an int).

OpenSeesPy has no script bodies: `pattern('Plain', ...)` makes the pattern
that later `load` and `eleLoad` calls fill, and `section('Fiber', tag)` the
section that later `patch`, `layer` and `fiber` calls fill.

poundfe's additions, Tcl's `poundfe::` commands, are the functions of
`poundfe.opensees.poundfe`, their results as dicts: `ops.poundfe.energy()`
(the energy balance of the transient analyses since `ops.poundfe.energy('on')`),
`ops.poundfe.impacts()` (a list of dicts, one per contact episode since
`ops.poundfe.impacts('on')`; `ops.poundfe.impacts('-file', 'impacts.csv')`
writes them too), `ops.poundfe.locateEvents('on', 6)` (impacts located inside
the step; `ops.poundfe.locateEvents('query')` the halvings, an int) and
`ops.poundfe.report()`; a setting returns None.

Recorders write their files at `wipe` and when Python exits (a write error
then is printed; the exit status stays Python's, doc/python.md).
"""

import atexit
import sys
import types

from . import _opensees

OpenSeesError = _opensees.OpenSeesError


def _call(name, arguments):
    """opensees_call, its refusal raised with the caller's file and line
    (the frame that called the command's function)."""
    try:
        return _opensees.opensees_call(name, arguments)
    except OpenSeesError as error:
        caller = sys._getframe(2)
        where = (caller.f_code.co_filename, caller.f_lineno)
        refusal = OpenSeesError(f"{error} ({where[0]}, line {where[1]})")
        refusal.command, refusal.file, refusal.line = error.command, where[0], where[1]
    raise refusal


def _command(name, supported):
    def command(*arguments):
        return _call(name, arguments)
    command.__name__ = command.__qualname__ = name
    command.__doc__ = (f"OpenSees's `{name}`: its Tcl words as arguments." if supported else
                       f"OpenSees's `{name}`: poundfe does not support it (OpenSeesError).")
    return command


def _dict_of(words):
    """A Tcl dict (names and numbers, a list or its text) as a dict."""
    if isinstance(words, str):
        words = [int(w) if w.isdigit() else w for w in words.split()]
    return dict(zip(words[::2], words[1::2]))


def _refuse_bools(name, arguments):
    """poundfe's commands take words and numbers: True or False (an int to
    Python) is refused with the caller's file and line."""
    if any(isinstance(argument, bool) for argument in arguments):
        caller = sys._getframe(2)
        where = (caller.f_code.co_filename, caller.f_lineno)
        refusal = OpenSeesError(f"{name}: True or False where a word or a number is due "
                                f"({where[0]}, line {where[1]})")
        refusal.command, refusal.file, refusal.line = name, where[0], where[1]
        raise refusal


def _poundfe_command(name):
    def command(*arguments):
        _refuse_bools(name, arguments)
        result = _call(name, arguments)
        if result is None:  # a setting (stepCutting, locateEvents on|off)
            return None
        if name == "poundfe::locateEvents":  # query: the most halvings, 0 when off
            return result
        if name == "poundfe::impacts":
            return [_dict_of(episode) for episode in (result or [])]
        return _dict_of(result)
    command.__name__ = command.__qualname__ = name.split("::")[1]
    command.__doc__ = f"poundfe's `{name}`: its Tcl words as arguments, a dict as result."
    return command


__all__ = ["OpenSeesError", "poundfe"]
poundfe = types.SimpleNamespace()
for _name, _supported in _opensees.opensees_commands():
    if _name.startswith("poundfe::"):
        setattr(poundfe, _name.split("::")[1], _poundfe_command(_name))
        continue
    globals()[_name] = _command(_name, _supported)
    __all__.append(_name)
del _name, _supported



def _finish():
    """Every recorder's file written when Python exits. Python ignores what
    an atexit function raises and keeps its exit status: a write error is
    printed once, as the OpenSeesError it is, and no recorder file appears."""
    try:
        _opensees.opensees_finish()
    except OpenSeesError as error:
        # sys.stderr itself: `print` here is OpenSees's command
        sys.stderr.write(f"poundfe.opensees.OpenSeesError: {error}\n")
        sys.stderr.flush()


atexit.register(_finish)
