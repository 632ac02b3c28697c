"""The commands whose row takes results in memory (spectrum, montecarlo,
sweep, separation, dynamic_form, reliability, switching, bifurcation,
site_hazard, fragility, stationary_pdf, pushover, ground_motion, subset,
mitigation, ida, msa, modal) write no file from Python unless given output=: no temporary
directory (tempfile's directory is a plain file here, so that any use of it
fails), nothing in the input's Output/Directory; their tables and summary
come from memory and their report says so. The same doubles as the command
line's files are checked by test_commands_study.py, test_commands_random.py
and test_commands_analysis.py, which now go through memory too. A row
without it (select-records) is refused by _core.command_in_memory with the
command line's kind of message.
Reference: the row's in_memory column (doc/architecture.md, "Commands and
the guard")."""

import os
import signal
import tempfile
import threading
import unittest

import poundfe
from poundfe import _core
from common import EXAMPLE, TestCase

poundfe.Input  # the core loaded now (poundfe loads it at its first name), before any timer

QUIET = {"Output/Plots": False}
SMALL = "tests/cli/montecarlo-small.prm"
IDA = "tests/cli/ida/ida-small.prm"
# python name: (input, overrides of a short call, a table it leaves)
CALLS = {
    "spectrum": ("input/three-storey-shear.prm", {}, "spectrum"),
    "montecarlo": (SMALL, {"Monte Carlo/Realizations": 2,
                           "Ground motion/Stochastic/Duration": 1}, "realizations"),
    "separation": ("tests/cli/separation-sdof-pair.prm", {}, "separation"),
    "dynamic_form": ("tests/cli/dynamic-form-sdof.prm", {}, "design_point"),
    "reliability": ("input/thesis-cantilever-reliability.prm", {}, "estimates"),
    "switching": ("tests/cli/switching-belt.prm", {}, "trajectory"),
    "bifurcation": ("input/linear-bifurcation.prm", {}, "bifurcation_classification"),
    "site_hazard": ("input/site-hazard.prm", {}, "hazard_curve"),
    "fragility": (SMALL, {"Fragility/Realizations per level": 1, "Fragility/PGA levels": 0.1,
                          "Ground motion/Stochastic/Duration": 1}, "fragility_points"),
    "pushover": ("input/pushover-frame.prm", {}, "pushover"),
    "mitigation": ("input/mitigation-shear-pair.prm", {}, "mitigation"),
    "subset": (SMALL, {"Subset simulation/Samples per level": 10, "Subset simulation/Maximum levels": 2,
                       "Ground motion/Stochastic/Duration": 1}, "subset_runs"),
    "ida": (IDA, {"IDA/Runs per record": 2, "IDA/Demand intensities": 0.2}, "ida"),
    "msa": (IDA, {"MSA/Intensities": 0.2, "MSA/Cloud": True}, "msa"),
    "modal": (EXAMPLE, {}, "mode_shapes"),
    "stationary_pdf": ("tests/cli/stationary-linear.prm",
                       {"Stationary PDF/Number of realizations": 2,
                        "Ground motion/Stochastic/Duration": 220}, "pdf"),
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
        # modal's summary.json has no status (as the command line's)
        expected = (None,) if name == "modal" else ("completed", "completed with warnings")
        self.assertIn(result.status, expected)
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

    def test_ground_motion_no_file(self):
        # the one command without a summary.json of its own
        directory = os.path.join(self.tmp, "would-be-output")
        for realizations, stem in ((None, "ground_motion"), (2, "ensemble_psd")):
            result = poundfe.ground_motion(EXAMPLE, realizations=realizations, overrides={
                **QUIET, "Output/Directory": directory})
            self.assertFalse(os.path.exists(directory))
            self.assertEqual(sorted(os.listdir(self.tmp)), ["not-a-directory"])
            self.assertIsNone(result.summary)
            self.assertGreater(len(result.tables[stem]), 0)
            self.assertIn("results in memory", result.report)

    def test_fragility_levels_in_memory(self):
        # each level's realizations, as pga_<a>g/realizations.csv would hold them
        file, overrides, _ = CALLS["fragility"]
        result = self.assertNoFile("fragility", file, overrides, "fragility_points")
        self.assertIn("pga_0.1g/realizations.csv", result.files)
        self.assertEqual(len(result.tables["pga_0.1g/realizations"]), 1)

    def test_p_bifurcation_in_memory(self):
        # one stationary PDF per value, each under its folder's names
        file, overrides, _ = CALLS["stationary_pdf"]
        result = self.assertNoFile("stationary_pdf", file,
                                   {**overrides, "Stationary PDF/Parameter": "Ground motion/Stochastic/D",
                                    "Stationary PDF/Values": "0.1, 0.2"}, "p_bifurcation")
        for value in ("0.1", "0.2"):
            self.assertIn(f"Ground_motion_Stochastic_D_{value}/pdf.csv", result.files)
            self.assertIn(f"Ground_motion_Stochastic_D_{value}/realizations.csv", result.files)

    def test_interrupted_fragility_keeps_its_partial_level(self):
        # Ctrl-C stops the command as SIGINT stops the command line's: the
        # levels done and the interrupted level's realizations so far (which
        # a run into files keeps to resume from) come with KeyboardInterrupt
        file, overrides, _ = CALLS["fragility"]
        overrides = {**overrides, "Fragility/Realizations per level": 400,
                     "Fragility/PGA levels": "0.1, 0.2, 0.3, 0.4"}
        timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt) as caught:
                poundfe.fragility(file, overrides={**QUIET, **overrides})
        finally:
            timer.cancel()
        result = caught.exception.result
        self.assertEqual(result.status, "interrupted")
        self.assertEqual(sorted(os.listdir(self.tmp)), ["not-a-directory"])
        levels = sorted(stem for stem in result.tables if stem.endswith("/realizations"))
        self.assertEqual(len(levels), result.summary["completed_levels"] + 1)
        self.assertLess(len(result.tables[levels[-1]]), 400)
        # the signal is forgotten: the next command runs to its end
        again = poundfe.fragility(file, overrides={**QUIET, **CALLS["fragility"][1]})
        self.assertEqual(again.status, "completed")

    def test_journals_in_memory(self):
        # the texts of journal/ a run into files resumes from: every run once
        file, overrides, _ = CALLS["ida"]
        ida = self.assertNoFile("ida", file, overrides, "ida")
        self.assertEqual(len(ida.tables["journal/realizations"]), len(ida.ida))
        self.assertTrue(any(f.startswith("demands_") and f.endswith("_im1.csv") for f in ida.files))
        file, overrides, _ = CALLS["msa"]
        msa = self.assertNoFile("msa", file, overrides, "msa")
        self.assertEqual(len(msa.tables["journal/stripes/realizations"]), len(msa.msa))
        self.assertEqual(len(msa.tables["journal/cloud/realizations"]), len(msa.cloud))

    def test_modal_shapes_without_vtu(self):
        # the shapes as arrays; the drawn ones (modes.pvd) only with output=
        modes = self.assertNoFile("modal", EXAMPLE, {}, "mode_shapes")
        self.assertFalse(any(f.endswith((".pvd", ".vtu")) for f in modes.files))
        self.assertEqual(modes.shapes.shape, (60, 6))
        self.assertEqual(modes.buildings[0].shapes.shape[0], len(modes.buildings[0].equations))

    def test_rows_without_memory(self):
        self.assertTrue(_core.in_memory("montecarlo"))
        self.assertTrue(_core.in_memory("ida"))
        self.assertFalse(_core.in_memory("select-records"))
        with self.assertRaisesRegex(ValueError, "results in memory belong to .*montecarlo"):
            _core.command_in_memory("select-records", [IDA])


if __name__ == "__main__":
    unittest.main()
