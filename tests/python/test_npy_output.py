"""Output/Format = npy read back by NumPy: every time series the CSV run writes
is a .npy file that numpy.load reads (its header's shape the final row count)
with the same doubles, bit for bit, as Python's correctly rounded float() of
the CSV text, and the column names of <stem>.columns.txt equal the CSV header."""

import os
import unittest

from common import TestCase, read_csv_text, read_summary, run_command_line

# The Bouc-Wen single storey (hinge states and a phase portrait besides the
# drifts, floors and energy) and the shear pair with linear gaps (contact
# forces), each half a second long, a row every step.
CASES = [("input/bouc-wen-sdof.prm", ["Time integration/End time=0.5",
                                      "Output/Output interval=0.002"]),
         ("bench/shear-pair-linear.prm", ["Time integration/End time=0.5"])]


def csv_time_series(directory):
    """{stem: (header, rows)} of the CSV files whose first column is time."""
    tables = {}
    for name in sorted(os.listdir(directory)):
        if name.endswith(".csv"):
            header, rows = read_csv_text(os.path.join(directory, name))
            if header[0] == "time_s":
                tables[name[:-4]] = (header, rows)
    return tables


class NpyOutput(TestCase):

    def run_format(self, file, sets, output_format):
        out = os.path.join(self.tmp, output_format)
        arguments = [a for s in sets + [f"Output/Format={output_format}", "Output/Plots=false"]
                     for a in ("--set", s)]
        status, _, err = run_command_line("run", file, "--output", out, *arguments)
        self.assertEqual(status, 0, err)
        self.assertEqual(read_summary(out)["status"], "completed")
        return out

    def test_numpy_reads_the_csv_doubles_to_the_bit(self):
        import numpy as np
        for file, sets in CASES:
            with self.subTest(file=file):
                csv_dir = self.run_format(file, sets, "csv")
                npy_dir = self.run_format(file, sets, "npy")
                tables = csv_time_series(csv_dir)
                self.assertGreaterEqual(len(tables), 5, file)
                for stem, (header, rows) in tables.items():
                    npy = os.path.join(npy_dir, stem + ".npy")
                    self.assertFalse(os.path.exists(os.path.join(npy_dir, stem + ".csv")), stem)
                    data = np.load(npy, allow_pickle=False)
                    self.assertEqual(data.dtype, np.dtype("<f8"), stem)
                    self.assertEqual(data.shape, (len(rows), len(header)), stem)
                    with open(os.path.join(npy_dir, stem + ".columns.txt")) as f:
                        self.assertEqual(f.read().split("\n")[:-1], header, stem)
                    expected = np.array([[float(x) for x in row] for row in rows])
                    # bit for bit: the same 8 bytes, so -0.0 against 0.0 counts too
                    self.assertTrue(np.array_equal(data.view(np.uint64),
                                                   expected.view(np.uint64)), stem)


if __name__ == "__main__":
    unittest.main()
