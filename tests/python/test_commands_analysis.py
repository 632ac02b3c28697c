"""The analysis commands from Python (poundfe.reliability, dynamic_form,
bifurcation, switching, pushover, ground_motion, ida, msa) against the same
commands on the command line, and poundfe.modal's modes (in memory) against
`poundfe modal`'s summary.json and mode_shapes*.csv: the same doubles (reference: the command
line's files parsed with Python's float() and json; tolerance none). Also
how a command takes an Input or a Model, keeps its files with output=, and
to_dataframe without pandas."""

import json
import os
import sys
import unittest
from unittest import mock

import numpy as np

import poundfe
from common import (EXAMPLE, CommandTestCase, read_summary, run_command_line, tables_of_directory,
                    without_place)

QUIET = {"Output/Plots": False}
IDA = "tests/cli/ida/ida-small.prm"


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
        self.assertIsNone(modes.output)
        self.assertEqual(without_place(modes.summary), without_place(summary))
        expected = tables_of_directory(out)
        self.assertEqual(sorted(modes.tables), sorted(expected))
        for stem, (header, rows) in expected.items():
            self.assertTableIdentical(modes.tables[stem], header, rows, stem)
        self.assertIdentical(modes.frequencies, summary["modes"]["frequencies_hz"], "frequencies")
        self.assertIdentical(modes.periods, summary["modes"]["periods_s"], "periods")
        _, shapes = expected["mode_shapes"]
        self.assertIdentical(modes.omega, [float(row[1]) for row in shapes], "omega")
        self.assertIdentical(modes.shapes.T, [[float(x) for x in row[2:]] for row in shapes],
                             "shapes")
        for building, expected_building in zip(modes.buildings, summary["buildings"]):
            self.assertEqual(building.name, expected_building["name"])
            self.assertIdentical(building.frequencies, expected_building["modes"]["frequencies_hz"],
                                 building.name)
            header, rows = expected["mode_shapes_" + building.name]
            self.assertEqual(building.equations, header[2:])
            self.assertIdentical(building.shapes.T, [[float(x) for x in row[2:]] for row in rows],
                                 building.name)

    def test_modal_output_keeps_the_drawn_shapes(self):
        kept = os.path.join(self.tmp, "kept")
        modes = poundfe.modal(EXAMPLE, output=kept)
        self.assertEqual(modes.output, kept)
        self.assertTrue(os.path.exists(os.path.join(kept, "modes.pvd")))
        self.assertIdentical(modes.shapes, poundfe.modal(EXAMPLE).shapes, "shapes")

    def test_ida(self):
        self.assertSameAsCommandLine("ida", IDA, {**QUIET, "IDA/Runs per record": 2,
                                                  "IDA/Demand intensities": 0.2})

    def test_msa(self):
        # with the demand tables of each stripe and of the cloud (common.py
        # checks their units against the files' units rows)
        msa = self.assertSameAsCommandLine("msa", IDA, {**QUIET, "MSA/Intensities": "0.1, 0.3",
                                                        "MSA/Cloud": True,
                                                        "Output/Demand tables": True})
        self.assertIn("demands_B1_cloud", msa.tables)
        self.assertEqual(msa.summary["demand_tables"][-1]["cloud"], True)

    def test_demand_tables_are_numbers_with_their_units_apart(self):
        # pelicun's units row is no row of the array: every column float64,
        # the units as table.units (reference: the units poundfe declares
        # per demand type, output/demand_table.cc: PID rad, PFA g)
        ida = poundfe.ida(IDA, overrides={**QUIET, "IDA/Runs per record": 2,
                                          "IDA/Demand intensities": 0.2})
        table = ida.tables["demands_B1_im1"]
        self.assertIsInstance(table, poundfe.DemandTable)
        self.assertEqual([table.dtype[name].kind for name in table.dtype.names],
                         ["f"] * len(table.dtype.names))
        self.assertEqual(table.units["1-PID-1-1"], "rad")
        self.assertEqual(table.units["1-PFA-0-1"], "g")
        self.assertEqual(sorted(table.units), sorted(set(table.dtype.names) - {"index"}))
        self.assertEqual(list(table["index"]), list(range(len(table))))
        self.assertEqual(table[:1].units, table.units)  # a slice keeps them
        # a column and its reductions are plain NumPy, not tables
        column = table["1-PID-1-1"]
        self.assertIs(type(column), np.ndarray)
        self.assertIs(type(column.max()), np.float64)
        self.assertIs(type(np.mean(column)), np.float64)
        self.assertIs(type(column * 2), np.ndarray)
        self.assertEqual(json.loads(json.dumps({"max": column.max()}))["max"],
                         max(float(x) for x in column))

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

    def test_two_threads_run_commands_in_turn(self):
        import threading
        file = "tests/cli/dynamic-form-sdof.prm"
        results, errors = [None, None], []

        def run(i):
            try:
                results[i] = poundfe.dynamic_form(file, overrides=QUIET)
            except BaseException as error:  # reported below
                errors.append(error)

        threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        self.assertEqual(errors, [])
        self.assertIdentical(results[0].design_point["x_star"], results[1].design_point["x_star"],
                             "two threads")

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
