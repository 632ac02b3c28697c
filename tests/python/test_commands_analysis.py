"""The analysis commands from Python (poundfe.reliability, dynamic_form,
bifurcation, switching, pushover, ground_motion) against the same commands
on the command line, and poundfe.modal's modes (computed in memory) against
`poundfe modal`'s summary.json: the same doubles (reference: the command
line's files parsed with Python's float() and json; tolerance none). Also
how a command takes an Input or a Model, keeps its files with output=, and
to_dataframe without pandas."""

import os
import sys
import unittest
from unittest import mock

import poundfe
from common import EXAMPLE, CommandTestCase, read_summary, run_command_line

QUIET = {"Output/Plots": False}


class AnalysisCommands(CommandTestCase):
    def test_reliability(self):
        self.assertSameAsCommandLine("reliability", "input/thesis-cantilever-reliability.prm", QUIET)

    def test_dynamic_form(self):
        self.assertSameAsCommandLine("dynamic_form", "tests/cli/dynamic-form-sdof.prm", QUIET)

    def test_bifurcation(self):
        self.assertSameAsCommandLine("bifurcation", "input/linear-bifurcation.prm", QUIET)

    def test_switching(self):
        self.assertSameAsCommandLine("switching", "tests/cli/switching-belt.prm", QUIET)

    def test_pushover(self):
        self.assertSameAsCommandLine("pushover", "input/pushover-frame.prm", QUIET)

    def test_ground_motion(self):
        self.assertSameAsCommandLine("ground_motion", EXAMPLE, QUIET)
        self.assertSameAsCommandLine("ground_motion", EXAMPLE, QUIET, realizations=2)

    def test_modal_in_memory(self):
        out = os.path.join(self.tmp, "modal")
        status, _, err = run_command_line("modal", EXAMPLE, "--output", out)
        self.assertEqual(status, 0, err)
        summary = read_summary(out)
        modes = poundfe.modal(EXAMPLE)
        self.assertIdentical(modes.frequencies, summary["modes"]["frequencies_hz"], "frequencies")
        self.assertIdentical(modes.periods, summary["modes"]["periods_s"], "periods")
        for building, expected in zip(modes.buildings, summary["buildings"]):
            self.assertEqual(building.name, expected["name"])
            self.assertIdentical(building.frequencies, expected["modes"]["frequencies_hz"],
                                 building.name)

    def test_input_model_and_output(self):
        file = "tests/cli/dynamic-form-sdof.prm"
        by_name = poundfe.dynamic_form(file, overrides=QUIET)
        self.assertIsNone(by_name.output)
        by_input = poundfe.dynamic_form(poundfe.read(file, overrides=QUIET))
        by_model = poundfe.dynamic_form(poundfe.Model.from_file(file, overrides=QUIET))
        kept = os.path.join(self.tmp, "kept")
        with_output = poundfe.dynamic_form(file, output=kept, overrides=QUIET)
        self.assertEqual(with_output.output, kept)
        self.assertTrue(os.path.exists(os.path.join(kept, "summary.json")))
        for other in (by_input, by_model, with_output):
            self.assertIdentical(other.design_point["x_star"], by_name.design_point["x_star"],
                                 "design point")
            self.assertEqual(other.summary["beta"], by_name.summary["beta"])

    def test_report_kept_not_printed(self):
        import tempfile
        with tempfile.TemporaryFile() as captured:
            saved = os.dup(1)
            os.dup2(captured.fileno(), 1)
            try:
                result = poundfe.dynamic_form("tests/cli/dynamic-form-sdof.prm", overrides=QUIET)
            finally:
                os.dup2(saved, 1)
                os.close(saved)
            captured.seek(0)
            self.assertEqual(captured.read(), b"")
        self.assertIn("dynamic FORM: beta = 2.02652", result.report)

    def test_to_dataframe_without_pandas(self):
        result = poundfe.dynamic_form("tests/cli/dynamic-form-sdof.prm", overrides=QUIET)
        with mock.patch.dict(sys.modules, {"pandas": None}):
            with self.assertRaisesRegex(ImportError, "to_dataframe needs pandas"):
                result.to_dataframe("design_point")

    def test_bad_input_raises_the_readers_message(self):
        with self.assertRaisesRegex(poundfe.InputError, "Number of buildings"):
            poundfe.montecarlo(EXAMPLE, overrides={"Model/Number of buildings": "many"})


if __name__ == "__main__":
    unittest.main()
