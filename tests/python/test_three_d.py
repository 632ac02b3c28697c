"""poundfe.run and poundfe.modal on a 3D model carry both horizontal
directions and the twist: Results.peaks has the y and θz peaks of
summary.json's storeys, every series has its columns along x, y and about z
(the command line's, to the last digit), and Modes has the mass ratios along
y and about z (reference: the command line's summary.json and CSV files on
input/3d-torsional-shear-pair.prm; tolerance none: the same engine)."""

import os
import tempfile
import unittest

import poundfe
from common import TestCase, read_csv_text, read_summary, run_command_line

PAIR = os.path.join("input", "3d-torsional-shear-pair.prm")


class ThreeDimensionalResults(TestCase):
    @classmethod
    def setUpClass(cls):
        cls.cli_scratch = tempfile.TemporaryDirectory(prefix="poundfe-cli-")
        cls.cli = cls.cli_scratch.name
        os.chdir(os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__)))))
        status, _, err = run_command_line("run", PAIR, "--output", cls.cli)
        assert status == 0, err
        cls.results = poundfe.run(poundfe.read(PAIR))

    @classmethod
    def tearDownClass(cls):
        cls.cli_scratch.cleanup()

    def test_peaks_along_y_and_about_z(self):
        summary = read_summary(self.cli)
        for building in summary["buildings"]:
            peaks = self.results.peaks[building["name"]]
            storeys = building["storeys"]
            for key, field in (("drift_ratio_y", "peak_drift_ratio_y"),
                               ("floor_acceleration_y", "peak_absolute_floor_acceleration_y_m_s2"),
                               ("floor_displacement_y", "peak_floor_displacement_y_m"),
                               ("floor_rotation", "peak_floor_rotation_rad")):
                self.assertIdentical(peaks[key], [s[field] for s in storeys], key)
            self.assertGreater(max(peaks["floor_rotation"]), 0, "the pair twists")

    def test_series_along_every_direction(self):
        for name in ("floor_displacement", "drift", "floor_acceleration", "ground_motion"):
            header, rows = read_csv_text(os.path.join(self.cli, name + ".csv"))
            table = self.results.series[name]
            self.assertEqual(table.names, header, name)
            self.assertIdentical(table.data, [[float(x) for x in row] for row in rows], name)
            self.assertTrue(any(n.endswith("_x_m_s2") or "_x" in n for n in header), name)
            self.assertTrue(any("_y" in n for n in header), f"{name}: no column along y")
        self.assertIn("tor2_floor1_rot_z_rad", self.results.series["floor_displacement"].names)

    def test_modes_along_y_and_about_z(self):
        summary = read_summary(self.cli)
        modes = self.results.modes
        self.assertIdentical(modes.participating_mass_ratio_y,
                             summary["modes"]["participating_mass_ratio_y"], "y")
        self.assertIdentical(modes.participating_mass_ratio_rz,
                             summary["modes"]["participating_mass_ratio_rz"], "rz")
        alone = poundfe.modal(poundfe.read(PAIR))
        self.assertIdentical(alone.participating_mass_ratio_y, modes.participating_mass_ratio_y, "modal")
        self.assertTrue(all(label.endswith(("_ux", "_uy", "_rz")) for label in alone.equations))


if __name__ == "__main__":
    unittest.main()
