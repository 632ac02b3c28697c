"""Every row of the command table is honoured alike by the command line and
by poundfe.command, which share one dispatcher (commands/dispatch.h): for
each command, each call its row forbids (Time integration/Partition =
buildings without the partition column, Output/Field format = xdmf without
field output, --realizations without it, --set for a command that reads no
file) is refused by both with the same message (the command line's
"poundfe: error: MESSAGE" is the Python exception's MESSAGE), exit status 1
and nothing written; and a call the row allows goes through both (exit
status 0, the same files). The rows are written out here, independently of
the table, and checked against the usage text the table prints.
Reference: the rows below (doc/architecture.md, "Commands and the guard")."""

import os
import unittest

import poundfe
from common import EXAMPLE, TestCase, run_command_line

CLI = os.path.join("tests", "cli")
PARTITION = ("Time integration/Partition", "buildings")
XDMF = ("Output/Field format", "xdmf")

QUIET = {"Output/Plots": "false"}  # no gnuplot: the same files whatever is installed
SHORT = {"Ground motion/Stochastic/Duration": 1}
# name: (input, its rules, the overrides of a short call it allows)
ROWS = {
    "run": (EXAMPLE, {"partition", "fields"},
            {**QUIET, **SHORT, "Time integration/Nonlinear solver": "krylov-newton"}),
    "modal": (EXAMPLE, {"fields"}, QUIET),
    "pushover": (os.path.join("input", "pushover-frame.prm"), set(), QUIET),
    "ground-motion": (EXAMPLE, {"realizations"}, QUIET),
    "spectrum": (EXAMPLE, {"realizations"}, QUIET),
    "montecarlo": (os.path.join(CLI, "montecarlo-small.prm"), set(),
                   {**QUIET, **SHORT, "Monte Carlo/Realizations": 1}),
    "subset": (os.path.join("input", "subset-drift.prm"), set(),
               {**QUIET, "Subset simulation/Samples per level": 20}),
    "fragility": (os.path.join(CLI, "montecarlo-small.prm"), set(),
                  {**QUIET, **SHORT, "Fragility/Realizations per level": 1,
                   "Fragility/PGA levels": 0.1}),
    "ida": (os.path.join(CLI, "ida", "ida-small.prm"), set(), {**QUIET, "IDA/Runs per record": 2}),
    "msa": (os.path.join(CLI, "ida", "ida-small.prm"), set(), {**QUIET, "MSA/Intensities": 0.2}),
    "select-records": (os.path.join(CLI, "ida", "ida-small.prm"), set(),
                       {**QUIET, "Selection/Records": 1, "Selection/Scale limits": "0.01, 100"}),
    "stationary-pdf": (os.path.join(CLI, "stationary-linear.prm"), set(),
                       {**QUIET, "Stationary PDF/Number of realizations": 2}),
    "sweep": (os.path.join(CLI, "3d-commands.prm"), set(), QUIET),
    "bifurcation": (os.path.join("input", "linear-bifurcation.prm"), set(),
                    {**QUIET, "Bifurcation/Values": "linspace 5 15 2"}),
    "site-hazard": (os.path.join("input", "site-hazard.prm"), set(), QUIET),
    "separation": (os.path.join(CLI, "separation-sdof-pair.prm"), set(), QUIET),
    "mitigation": (os.path.join("input", "mitigation-shear-pair.prm"), set(),
                   {**QUIET, "Monte Carlo/Realizations": 1}),
    "reliability": (os.path.join("input", "thesis-cantilever-reliability.prm"), set(),
                    {**QUIET, "Reliability/Methods": "FORM"}),
    "dynamic-form": (os.path.join(CLI, "dynamic-form-sdof.prm"), set(), QUIET),
    "switching": (os.path.join(CLI, "switching-belt.prm"), set(), QUIET),
    "moment-curvature": (os.path.join("input", "moment-curvature-rc-column.prm"), set(),
                         {**QUIET, "Moment curvature/Steps": 30}),
    "export-opensees": (os.path.join("input", "three-storey-shear.prm"), set(), QUIET),
}
SCRIPT_ROWS = {"opensees"}  # CommandRule::script_arguments
NO_FILE = {"opensees": [os.path.join("tests", "opensees", "modes.tcl")],
           "print-parameters": [], "template": ["frame"]}


def set_options(overrides):
    words = []
    for path, value in overrides.items():
        words += ["--set", f"{path}={poundfe.model._value_text(value)}"]
    return words


def files_under(directory):
    """The files and directories under `directory`, relative to it, sorted."""
    found = []
    for top, directories, files in os.walk(directory):
        found += [os.path.relpath(os.path.join(top, f), directory) for f in directories + files]
    return sorted(found)


class CommandRules(TestCase):
    def refused_alike(self, name, file, overrides, realizations=None, arguments=None):
        """The command line and poundfe.command refuse the call with one
        message; neither writes its output directory."""
        arguments = [file] if arguments is None else arguments
        cli_out, py_out = os.path.join(self.tmp, "cli"), os.path.join(self.tmp, "py")
        extra = ["--realizations", str(realizations)] if realizations else []
        options = ["--output", cli_out, *set_options(overrides), *extra]
        # a script's command: the words after the script are the script's own
        words = [*options, *arguments] if name in SCRIPT_ROWS else [*arguments, *options]
        status, _, err = run_command_line(name, *words)
        what = f"{name} {overrides} {extra}"
        self.assertEqual(status, 1, f"{what}: {err}")
        self.assertTrue(err.startswith("poundfe: error: "), f"{what}: {err}")
        with self.assertRaises(ValueError) as caught:  # InputError is a ValueError
            poundfe.command(name, *arguments, output=py_out, realizations=realizations,
                            overrides=overrides)
        self.assertEqual(err, f"poundfe: error: {caught.exception}\n", what)
        self.assertFalse(os.path.exists(cli_out), f"{what}: the command line wrote")
        self.assertFalse(os.path.exists(py_out), f"{what}: Python wrote")
        return str(caught.exception)

    def test_forbidden_calls_are_refused_alike(self):
        for name, (file, rules, _) in ROWS.items():
            with self.subTest(command=name):
                if "partition" not in rules:
                    message = self.refused_alike(name, file, dict([PARTITION]))
                    self.assertIn(f"only 'run' takes it, not '{name}'", message)
                if "fields" not in rules:
                    message = self.refused_alike(name, file, dict([XDMF]))
                    self.assertIn(f"xdmf chooses the field output of 'run' and 'modal'; '{name}'",
                                  message)
                if "realizations" not in rules:
                    message = self.refused_alike(name, file, {}, realizations=2)
                    self.assertEqual(message, "--realizations belongs to ground-motion and spectrum")
        for name, arguments in NO_FILE.items():
            with self.subTest(command=name):
                self.refused_alike(name, None, {}, realizations=2, arguments=arguments)
                message = self.refused_alike(name, None, {"Output/Plots": "false"},
                                             arguments=arguments)
                self.assertIn(f"'{name}' reads none", message)

    def test_allowed_calls_go_through_both(self):
        """Each row's own column used where it has one (Partition = buildings
        for run, xdmf for modal, --realizations 2 for ground-motion and
        spectrum), the plain call otherwise."""
        for name, (file, rules, overrides) in ROWS.items():
            with self.subTest(command=name):
                allowed = dict(overrides)
                if "partition" in rules:
                    allowed.update([PARTITION])
                if "fields" in rules:
                    allowed.update([XDMF])
                realizations = 2 if "realizations" in rules else None
                cli_out, py_out = os.path.join(self.tmp, name, "cli"), os.path.join(self.tmp, name, "py")
                extra = ["--realizations", "2"] if realizations else []
                status, _, err = run_command_line(name, file, "--output", cli_out,
                                                  *set_options(allowed), *extra)
                self.assertEqual(status, 0, f"{name}: {err}")
                self.assertEqual(poundfe.command(name, file, output=py_out,
                                                 realizations=realizations, overrides=allowed), 0)
                self.assertEqual(files_under(py_out), files_under(cli_out), name)
                if "fields" in rules:
                    self.assertTrue(any(f.endswith(".xdmf") for f in files_under(cli_out)), name)
        for name, arguments in NO_FILE.items():
            with self.subTest(command=name):
                status, out, err = run_command_line(name, *arguments)
                self.assertEqual(status, 0, f"{name}: {err}")
                self.assertTrue(out)

    def test_unknown_entry_refused_as_the_reader_does(self):
        """--set and poundfe.command's overrides of an entry that does not
        exist: the message of poundfe.read's overrides (the file's reader)."""
        overrides = {"Building 1/Storey stiffnes": 4e6}
        with self.assertRaises(poundfe.InputError) as read:
            poundfe.read(EXAMPLE, overrides)
        message = self.refused_alike("modal", EXAMPLE, overrides)
        self.assertEqual(message, str(read.exception))
        self.assertIn("No entry with name <Storey stiffnes> in 'Building 1' "
                      "(did you mean 'Storey stiffnesses'?)", message)

    def test_the_usage_text_lists_the_rows(self):
        status, usage, _ = run_command_line("--help")
        self.assertEqual(status, 0)
        self.assertEqual([line.split()[0] for line in usage.splitlines()
                          if line.startswith("  ") and not line.startswith("   ")],
                         list(ROWS) + list(NO_FILE))
        text = " ".join(usage.split())
        self.assertIn("Partition = buildings is taken only by 'run',", text)
        self.assertIn("Output/Field format = xdmf only by 'run' and 'modal'.", text)
        self.assertIn("montecarlo, subset, fragility, ida, msa, stationary-pdf, separation and mitigation "
                      "resume when run again", text)


if __name__ == "__main__":
    unittest.main()
