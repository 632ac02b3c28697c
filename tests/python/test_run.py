"""poundfe.run against `poundfe run` on the default example (two frames that
pound, 20000 steps, 17 impacts): every recorded series, the peaks, the
impact log and the modes, which poundfe.run keeps in memory (no file
written), are the command line's doubles, to the last digit (reference: the
command line's files, parsed with Python's float(); tolerance none: the
same engine and observers on the same input must give the same numbers)."""

import os
import unittest

import numpy as np

import poundfe
from common import EXAMPLE, TestCase, read_csv_text, read_summary, run_command_line


class RunAgainstCommandLine(TestCase):
    @classmethod
    def setUpClass(cls):
        import tempfile
        cls.cli_scratch = tempfile.TemporaryDirectory(prefix="poundfe-cli-")
        cls.cli = cls.cli_scratch.name
        os.chdir(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
        status, _, err = run_command_line("run", EXAMPLE, "--output", cls.cli)
        assert status == 0, err
        cls.calls = []
        # in memory: no file or directory may appear in the temporary area
        import tempfile
        cls.empty = tempfile.TemporaryDirectory(prefix="poundfe-empty-")
        previous, tempfile.tempdir = tempfile.tempdir, cls.empty.name
        try:
            cls.results = poundfe.run(poundfe.read(EXAMPLE), callback=cls.calls.append, every=100)
        finally:
            tempfile.tempdir = previous
        cls.left = os.listdir(cls.empty.name)
        cls.empty.cleanup()

    @classmethod
    def tearDownClass(cls):
        cls.cli_scratch.cleanup()

    def test_every_series_identical(self):
        csv_files = [f for f in os.listdir(self.cli) if f.endswith(".csv")]
        checked = 0
        for name in csv_files:
            header, rows = read_csv_text(os.path.join(self.cli, name))
            if header[0] != "time_s":
                continue
            table = self.results.series[name[:-4]]
            self.assertEqual(table.names, header, name)
            self.assertIdentical(table.data, [[float(x) for x in row] for row in rows], name)
            checked += 1
        self.assertEqual(checked, 7)  # drift, floors (2), ground motion, energy, hinges, contact
        self.assertEqual(len(self.results.drift), 4001)  # every 0.005 s over 20 s

    def test_peaks_identical(self):
        summary = read_summary(self.cli)
        for building in summary["buildings"]:
            peaks = self.results.peaks[building["name"]]
            storeys = building["storeys"]
            self.assertIdentical(peaks["drift_ratio"], [s["peak_drift_ratio"] for s in storeys],
                                 "peak drift ratio")
            self.assertIdentical(peaks["floor_acceleration"],
                                 [s["peak_absolute_floor_acceleration_m_s2"] for s in storeys],
                                 "peak floor acceleration")
            self.assertEqual(peaks["roof_displacement"], building["peak_roof_displacement_m"])
        for gap in summary["gaps"]:
            self.assertEqual(self.results.gaps[gap["label"]], gap)
        self.assertEqual(self.results.summary["energy"], summary["energy"])

    def test_impact_log_identical(self):
        header, rows = read_csv_text(os.path.join(self.cli, "impacts.csv"))
        impacts = self.results.impacts
        self.assertEqual(list(impacts.dtype.names), header)
        self.assertEqual(len(impacts), 17)
        for i, name in enumerate(header):
            column = [row[i] for row in rows]
            if impacts[name].dtype.kind == "f":
                self.assertIdentical(impacts[name], [float(x) for x in column], name)
            else:
                self.assertEqual(list(impacts[name]), column, name)

    def test_modes_identical(self):
        modes = read_summary(self.cli)["modes"]
        self.assertIdentical(self.results.modes.frequencies, modes["frequencies_hz"], "frequencies")
        self.assertIdentical(self.results.modes.periods, modes["periods_s"], "periods")
        self.assertEqual(self.results.modes.shapes.shape, (60, 6))  # 60 equations, 6 modes

    def test_callback_every_100_steps(self):
        # step 0 and every 100th of 20000 steps
        self.assertEqual([s.step for s in self.calls], list(range(0, 20001, 100)))
        # its floor response is the recorder's row at the same time (rows every 5 steps)
        table = self.results.floor_displacement
        for state in self.calls[::10]:
            row = state.step // 5
            self.assertEqual(table.time[row], state.time)
            self.assertIdentical(state.floor_displacement, table.values[row], f"t = {state.time}")
        self.assertEqual(self.calls[-1].n_impacts, 17)

    def test_output_directory_holds_the_command_line_files(self):
        results = poundfe.run(EXAMPLE, output=self.tmp)
        self.assertEqual(sorted(os.listdir(self.tmp)), sorted(os.listdir(self.cli)))
        for name in ("drift.csv", "floor_acceleration.csv", "contact_force.csv", "impacts.csv"):
            with open(os.path.join(self.tmp, name)) as a, open(os.path.join(self.cli, name)) as b:
                self.assertEqual(a.read(), b.read(), name)
        self.assertIdentical(results.drift.data, self.results.drift.data, "drift")

    def test_in_memory_writes_nothing(self):
        self.assertEqual(self.left, [])
        self.assertEqual(self.results.summary["output"]["files"][-1], "summary.json")
        self.assertFalse(self.results.drift.data.flags["OWNDATA"])  # moved, not copied

    def test_callback_by_building(self):
        state = self.calls[50]
        self.assertEqual(list(state.buildings), ["A3", "B2"])
        self.assertEqual(len(state.buildings["A3"]["floor_displacement"]), 3)
        self.assertIdentical(np.concatenate([b["floor_displacement"]
                                             for b in state.buildings.values()]),
                             state.floor_displacement, "floors by building")

    def test_floor_spectra_and_residual_drift_in_memory(self):
        file = "input/floor-spectra.prm"
        short = {"Time integration/End time": 2, "Output/Plots": False,
                 "Output/Recorders/Record": "floor displacement; residual drift"}
        sets = [a for p, v in short.items()
                for a in ("--set", f"{p}={poundfe.model._value_text(v)}")]
        status, _, err = run_command_line("run", file, "--output", self.tmp, *sets)
        self.assertEqual(status, 0, err)
        results = poundfe.run(poundfe.read(file, overrides=short))
        checked = 0
        for name in os.listdir(self.tmp):
            if not name.endswith(".csv"):
                continue
            header, rows = read_csv_text(os.path.join(self.tmp, name))
            stem = name[:-4]
            table = results.series.get(stem)
            if table is None:
                table = results.impacts if stem == "impacts" else results.tables[stem]
            if isinstance(table, poundfe.Table):
                self.assertIdentical(table.data, [[float(x) for x in r] for r in rows], stem)
            else:
                self.assertEqual(list(table.dtype.names), header, stem)
                for i, column in enumerate(header):
                    if table[column].dtype.kind == "f":
                        self.assertIdentical(table[column], [float(r[i]) for r in rows],
                                             f"{stem}: {column}")
                    else:
                        self.assertEqual(list(table[column]), [r[i] for r in rows], stem)
            checked += 1
        self.assertIn("floor_spectra", results.tables)
        self.assertIn("residual_drift", results.tables)
        self.assertGreaterEqual(checked, 5)

    def test_callback_exception_stops_the_run(self):
        calls = []

        def stop_at_300(state):
            calls.append(state.step)
            if state.step == 300:
                raise ZeroDivisionError("stop here")

        with self.assertRaisesRegex(ZeroDivisionError, "stop here"):
            poundfe.run(EXAMPLE, callback=stop_at_300, every=100)
        self.assertEqual(calls, [0, 100, 200, 300])


if __name__ == "__main__":
    unittest.main()
