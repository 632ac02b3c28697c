"""The study commands from Python (poundfe.sweep, separation, mitigation,
site_hazard, spectrum) against the same commands on the command line: every
table is in the result object, its numbers the same doubles, summary.json
the same but for the clock (reference: the command line's files parsed
with Python's float(); tolerance none: the same dispatcher on the same
input)."""

import os
import unittest

import poundfe
from common import EXAMPLE, CommandTestCase

QUIET = {"Output/Plots": False}


class StudyCommands(CommandTestCase):
    def test_sweep(self):
        path = os.path.join(self.tmp, "sweep.prm")
        with open(EXAMPLE) as f:
            text = f.read()
        with open(path, "w") as f:
            f.write(text + "subsection Sweep\n  set Parameter = Model/Separations\n"
                           "  set Values = 0.005, 0.02\nend\n")
        self.assertSameAsCommandLine("sweep", path, {**QUIET, "Time integration/End time": 2})

    def test_separation(self):
        self.assertSameAsCommandLine("separation", "tests/cli/separation-sdof-pair.prm", QUIET)

    def test_mitigation(self):
        self.assertSameAsCommandLine("mitigation", "input/mitigation-shear-pair.prm", QUIET)

    def test_site_hazard(self):
        self.assertSameAsCommandLine("site_hazard", "input/site-hazard.prm", QUIET)

    def test_spectrum(self):
        self.assertSameAsCommandLine("spectrum", "input/three-storey-shear.prm", QUIET)


if __name__ == "__main__":
    unittest.main()
