"""poundfe.run with Contact/Model = nonsmooth (rigid contact, Moreau-Jean)
against `poundfe run` of the same file: input/shear-pair-pounding.prm with
the pair 2 mm apart, e = 0.65, 4 s at 1e-3 s. The peaks, the gaps' summary
(impacts, impulses), summary.json's contact (the model, theta, the LCPs) and
the impact log, which poundfe.run keeps in memory, are the command line's
doubles to the last digit (reference: the command line's files; tolerance
none: the same engine and observers on the same input)."""

import os
import unittest

import poundfe
from common import TestCase, read_csv_text, read_summary, run_command_line

RIGID = {
    "Contact/Model": "nonsmooth",
    "Contact/Coefficient of restitution": "0.65",
    "Model/Separations": "0.002",
    "Ground motion/Stochastic/Duration": "4",
    "Output/Plots": "false",
}
FILE = os.path.join("input", "shear-pair-pounding.prm")


class RigidRunAgainstCommandLine(TestCase):
    def test_rigid_run_in_memory_is_the_command_lines(self):
        if "nonsmooth" not in run_command_line("--version")[1]:
            self.skipTest("this build has no Siconos: no rigid contact")
        sets = [a for path, value in RIGID.items() for a in ("--set", f"{path}={value}")]
        status, _, err = run_command_line("run", FILE, "--output", self.tmp, *sets)
        self.assertEqual(status, 0, err)
        summary = read_summary(self.tmp)
        results = poundfe.run(poundfe.read(FILE, RIGID))
        self.assertEqual(results.summary["contact"], summary["contact"])
        self.assertEqual(results.summary["contact"]["model"], "nonsmooth")
        impacts = 0
        for gap in summary["gaps"]:
            self.assertEqual(results.gaps[gap["label"]], gap)
            impacts += gap["impacts"]
        self.assertGreater(impacts, 0)
        for building in summary["buildings"]:
            self.assertIdentical(results.peaks[building["name"]]["drift_ratio"],
                                 [s["peak_drift_ratio"] for s in building["storeys"]],
                                 "peak drift ratio")
        header, rows = read_csv_text(os.path.join(self.tmp, "impacts.csv"))
        self.assertEqual(len(results.impacts), len(rows))
        self.assertIdentical(results.impacts["impulse_N_s"],
                             [float(r[header.index("impulse_N_s")]) for r in rows], "impulses")


if __name__ == "__main__":
    unittest.main()
