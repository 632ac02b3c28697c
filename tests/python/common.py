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
    """(header, rows of str) of a CSV file (blank and '#' lines left out)."""
    with open(path, newline="") as f:
        rows = [row for row in csv.reader(f) if row and not row[0].startswith("#")]
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


def tables_of_directory(directory):
    """{stem: (header, rows of str)} of every CSV file under `directory`
    ("sub/stem" for a subdirectory's)."""
    tables = {}
    for root, _, files in os.walk(directory):
        for name in files:
            if name.endswith(".csv"):
                path = os.path.join(root, name)
                stem = os.path.splitext(os.path.relpath(path, directory))[0]
                tables[stem.replace(os.sep, "/")] = read_csv_text(path)
    return tables


def without_clock(summary):
    """summary.json without what depends on the clock (wall times, rates)."""
    if isinstance(summary, dict):
        return {k: without_clock(v) for k, v in summary.items()
                if "wall" not in k and "per_second" not in k and k != "timing"}
    if isinstance(summary, list):
        return [without_clock(v) for v in summary]
    return summary


def without_place(summary):
    """summary.json without output/directory: where the files went."""
    if isinstance(summary, dict) and isinstance(summary.get("output"), dict):
        summary = {**summary, "output": {k: v for k, v in summary["output"].items()
                                         if k != "directory"}}
    return summary


class CommandTestCase(TestCase):
    """A command from Python against the same command on the command line."""

    def assertSameAsCommandLine(self, python_name, file, overrides, command=None,
                                realizations=None):
        """Runs `poundfe COMMAND FILE --set ... [--realizations N]` and
        poundfe.<python_name>(FILE, overrides=..., realizations=N): every
        CSV table the command line wrote is in the result, its numbers the
        same doubles (its texts the same), and summary.json the same but for
        the clock and the directory the files went to (none for results in
        memory); no summary.json on either side for a command that writes
        none. Returns the result."""
        import poundfe
        command = command or python_name.replace("_", "-")
        from poundfe.model import _value_text
        sets = [a for path, value in overrides.items()
                for a in ("--set", f"{path}={_value_text(value)}")]
        if realizations:
            sets += ["--realizations", str(realizations)]
        cli = os.path.join(self.tmp, "cli")
        status, _, err = run_command_line(command, file, "--output", cli, *sets)
        self.assertEqual(status, 0, err)
        result = getattr(poundfe, python_name)(file, overrides=overrides, realizations=realizations)
        expected_summary = (read_summary(cli) if os.path.exists(os.path.join(cli, "summary.json"))
                            else None)
        self.assertEqual(result.status, (expected_summary or {}).get("status"))
        expected = tables_of_directory(cli)
        self.assertGreater(len(expected), 0, "the command wrote no table")
        self.assertEqual(sorted(result.tables), sorted(expected))
        for stem, (header, rows) in expected.items():
            self.assertTableIdentical(result.tables[stem], header, rows, stem)
        self.assertEqual(without_place(without_clock(result.summary)),
                         without_place(without_clock(expected_summary)))
        return result

    def assertTableIdentical(self, table, header, rows, what):
        """A result's table (Table or structured array) against a CSV's
        header and rows: numbers by Python's float() ('' as NaN), texts as
        they are."""
        import numpy as np
        import poundfe
        header = [name or "index" for name in header]  # a demand table's row numbers
        if header[0] == "index" and rows and rows[0][0] == "Units":  # its units row
            self.assertIsInstance(table, poundfe.DemandTable, what)
            self.assertEqual(table.units, dict(zip(header[1:], rows[0][1:])), f"{what}: units")
            rows = rows[1:]
        if isinstance(table, poundfe.Table) and not any("wall" in name for name in header):
            self.assertEqual(table.names, header, what)
            self.assertIdentical(table.data, [[float(x) for x in row] for row in rows], what)
            return
        self.assertEqual(len(table), len(rows), what)
        if isinstance(table, poundfe.Table):
            self.assertEqual(table.names, header, what)
            table = {name: table.data[:, i] for i, name in enumerate(header)}
        else:
            self.assertEqual(list(table.dtype.names), header, what)
        for i, name in enumerate(header):
            column = [row[i] for row in rows]
            if "wall" in name:  # the clock's
                continue
            if table[name].dtype.kind == "f":
                self.assertIdentical(table[name], [float(x) if x else np.nan for x in column],
                                     f"{what}: {name}")
            else:
                self.assertEqual(list(table[name]), column, f"{what}: {name}")
