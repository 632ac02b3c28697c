"""What the Python tests share: the command line (POUNDFE, set by ctest) run
into a temporary directory, and its files read with Python's own float()
(correctly rounded: the CSV files hold each double's shortest exact text)."""

import csv
import json
import os
import subprocess
import tempfile
import unittest

ROOT = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
POUNDFE = os.path.abspath(os.environ.get("POUNDFE", os.path.join(ROOT, "build", "poundfe")))
EXAMPLE = os.path.join("input", "two-buildings.prm")


def run_command_line(*arguments):
    """`poundfe ARGUMENTS...` from the repository's root: (status, stdout, stderr)."""
    done = subprocess.run([POUNDFE, *arguments], cwd=ROOT, capture_output=True, text=True)
    return done.returncode, done.stdout, done.stderr


def read_csv_text(path):
    """(header, rows of str) of a CSV file."""
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


def read_summary(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        return json.load(f)


class TestCase(unittest.TestCase):
    """Runs from the repository's root in a fresh temporary directory."""

    def setUp(self):
        self.previous = os.getcwd()
        os.chdir(ROOT)
        self.scratch = tempfile.TemporaryDirectory(prefix="poundfe-test-")
        self.tmp = self.scratch.name

    def tearDown(self):
        os.chdir(self.previous)
        self.scratch.cleanup()

    def assertIdentical(self, actual, expected, what):
        """Equal doubles, element by element (NaN equal to NaN)."""
        import numpy as np
        actual, expected = np.asarray(actual, dtype=float), np.asarray(expected, dtype=float)
        self.assertEqual(actual.shape, expected.shape, what)
        same = (actual == expected) | (np.isnan(actual) & np.isnan(expected))
        if not same.all():
            i = np.argwhere(~same)[0]
            self.fail(f"{what}: differs at {tuple(i)}: {actual[tuple(i)]!r} != {expected[tuple(i)]!r}")
