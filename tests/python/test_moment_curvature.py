"""poundfe.moment_curvature returns the curve `poundfe moment-curvature`
writes (the reference: the command line's moment_curvature.csv and
summary.json on the same example, read with Python's float), and a bad
section raises InputError with the command line's message."""

import os
import unittest

import numpy as np

import poundfe
from common import TestCase, read_csv_text, read_summary, run_command_line

EXAMPLE = os.path.join("input", "moment-curvature-rc-column.prm")


class MomentCurvature(TestCase):
    def test_the_curve_is_the_command_lines(self):
        status, _, err = run_command_line("moment-curvature", EXAMPLE, "--output", self.tmp)
        self.assertEqual(status, 0, err)
        header, rows = read_csv_text(os.path.join(self.tmp, "moment_curvature.csv"))
        table = np.array([[float(x) for x in row] for row in rows])
        curve = poundfe.moment_curvature(EXAMPLE)
        self.assertIsInstance(curve["moment"], np.ndarray)
        np.testing.assert_array_equal(curve["curvature"], table[:, 0])
        np.testing.assert_array_equal(curve["moment"], table[:, 1])
        np.testing.assert_array_equal(curve["tangent"], table[:, header.index("tangent_N_m2")])
        summary = read_summary(self.tmp)
        self.assertEqual(curve["ductility"], summary["curvature_ductility"])
        self.assertEqual(curve["peak"]["moment"], summary["peak"]["moment_N_m"])
        self.assertEqual([e[0] for e in curve["events"]], [e["what"] for e in summary["events"]])

    def test_a_bad_section_raises_the_command_lines_message(self):
        overrides = {"Sections/Section 1/Cover": 0.3}
        with self.assertRaises(poundfe.InputError) as raised:
            poundfe.moment_curvature(EXAMPLE, overrides)
        self.assertEqual(raised.exception.parameter, "Sections/Section 1/Cover")
        self.assertIn("must be less than half the depth", str(raised.exception))


if __name__ == "__main__":
    unittest.main()
