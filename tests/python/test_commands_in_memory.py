"""The commands whose row takes results in memory (spectrum, montecarlo,
sweep, separation) write no file from Python unless given output=: no
temporary directory (tempfile's directory is a plain file here, so that any
use of it fails), nothing in the input's Output/Directory; their tables and
summary come from memory and their report says so. The same doubles as the
command line's files are checked by test_commands_study.py and
test_commands_random.py, which now go through memory too. A command whose
row does not take it still works through a temporary directory, and
_core.command_in_memory refuses it with the command line's kind of message.
Reference: the row's in_memory column (doc/architecture.md, "Commands and
the guard")."""

import os
import tempfile
import unittest

import poundfe
from poundfe import _core
from common import EXAMPLE, TestCase

QUIET = {"Output/Plots": False}
SMALL = "tests/cli/montecarlo-small.prm"
# python name: (input, overrides of a short call, a table it leaves)
CALLS = {
    "spectrum": ("input/three-storey-shear.prm", {}, "spectrum"),
    "montecarlo": (SMALL, {"Monte Carlo/Realizations": 2,
                           "Ground motion/Stochastic/Duration": 1}, "realizations"),
    "separation": ("tests/cli/separation-sdof-pair.prm", {}, "separation"),
}


class CommandsInMemory(TestCase):
    def setUp(self):
        super().setUp()
        # any temporary directory the call made would fail: its parent is a file
        self.blocked = os.path.join(self.tmp, "not-a-directory")
        with open(self.blocked, "w") as f:
            f.write("tempfile must not be used\n")
        self.saved_tempdir, tempfile.tempdir = tempfile.tempdir, self.blocked

    def tearDown(self):
        tempfile.tempdir = self.saved_tempdir
        super().tearDown()

    def assertNoFile(self, name, file, overrides, stem):
        directory = os.path.join(self.tmp, "would-be-output")
        result = getattr(poundfe, name)(
            file, overrides={**QUIET, **overrides, "Output/Directory": directory})
        self.assertFalse(os.path.exists(directory), f"{name} wrote {directory}")
        self.assertEqual(sorted(os.listdir(self.tmp)), ["not-a-directory"], name)
        self.assertIsNone(result.output)
        self.assertEqual(result.status, "completed")
        self.assertIn(stem + ".csv", result.files)
        self.assertIn("summary.json", result.files)
        self.assertGreater(len(result.tables[stem]), 0, name)
        self.assertIn("results in memory", result.report)
        return result

    def test_no_file_without_output(self):
        for name, (file, overrides, stem) in CALLS.items():
            with self.subTest(command=name):
                self.assertNoFile(name, file, overrides, stem)

    def test_sweep_no_file(self):
        path = os.path.join(self.tmp, "sweep.prm")
        with open(EXAMPLE) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(text + "subsection Sweep\n  set Parameter = Model/Separations\n"
                           "  set Values = 0.005, 0.02\nend\n")
        directory = os.path.join(self.tmp, "would-be-output")
        result = poundfe.sweep(path, overrides={**QUIET, "Time integration/End time": 0.5,
                                                "Output/Directory": directory})
        self.assertFalse(os.path.exists(directory))
        self.assertEqual(sorted(os.listdir(self.tmp)), ["not-a-directory", "sweep.prm"])
        self.assertEqual(len(result.sweep), 2)
        self.assertIn("results in memory", result.report)

    def test_output_still_writes_files(self):
        kept = os.path.join(self.tmp, "kept")
        result = poundfe.spectrum("input/three-storey-shear.prm", output=kept, overrides=QUIET)
        self.assertEqual(result.output, kept)
        self.assertTrue(os.path.exists(os.path.join(kept, "spectrum.csv")))
        in_memory = poundfe.spectrum("input/three-storey-shear.prm", overrides=QUIET)
        self.assertEqual(in_memory.spectrum.dtype, result.spectrum.dtype)
        for name in result.spectrum.dtype.names:
            self.assertIdentical(in_memory.spectrum[name], result.spectrum[name], name)
        # the files but the output directory's manifest (.poundfe-files)
        self.assertEqual(in_memory.files, [f for f in result.files if f != ".poundfe-files"])

    def test_rows_without_memory(self):
        self.assertTrue(_core.in_memory("montecarlo"))
        self.assertFalse(_core.in_memory("fragility"))
        with self.assertRaisesRegex(ValueError, "results in memory belong to .*montecarlo"):
            _core.command_in_memory("fragility", [SMALL])
        tempfile.tempdir = self.saved_tempdir  # a row without memory goes through files
        result = poundfe.fragility(SMALL, overrides={**QUIET, "Fragility/Realizations per level": 1,
                                                     "Fragility/PGA levels": 0.1,
                                                     "Ground motion/Stochastic/Duration": 1})
        self.assertIsNone(result.output)
        self.assertEqual(result.status, "completed")


if __name__ == "__main__":
    unittest.main()
