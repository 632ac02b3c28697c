"""Errors reach Python as exceptions with the command line's messages (the
reference: the command line's stderr on the same file, after its
"poundfe: error: " or "poundfe: numerical failure: " prefix), and
poundfe.command runs a command of the table as the command line does."""

import os
import unittest

import numpy as np

import poundfe
from common import EXAMPLE, TestCase, read_csv_text, read_summary, run_command_line

BAD = os.path.join("tests", "cli", "bad", "damping-ratio.prm")
NEWTON_FAILURE = os.path.join("tests", "cli", "newton-failure.prm")
MECHANISM = os.path.join("tests", "cli", "mechanism.prm")


def command_line_message(arguments, prefix):
    status, _, err = run_command_line(*arguments)
    line = err.strip().splitlines()[-1]
    assert line.startswith(prefix), err
    return status, line[len(prefix):]


class Errors(TestCase):
    def test_input_error_is_the_command_line_message(self):
        status, message = command_line_message(["run", BAD, "--output", self.tmp],
                                               "poundfe: error: ")
        self.assertEqual(status, 1)
        with self.assertRaises(poundfe.InputError) as caught:
            poundfe.read(BAD)
        self.assertIsInstance(caught.exception, ValueError)
        self.assertEqual(str(caught.exception), message)
        self.assertEqual((caught.exception.file, caught.exception.line, caught.exception.parameter),
                         (BAD, 12, "Building 1/Damping/Damping ratio"))

    def test_bad_override(self):
        with self.assertRaisesRegex(poundfe.InputError, "Model/Gap.*No entry with name <Gap> in 'Model'"):
            poundfe.read(EXAMPLE, overrides={"Model/Gap": 0.02})
        with self.assertRaisesRegex(poundfe.InputError, "must be zero or positive, got -1"):
            poundfe.read(EXAMPLE, overrides={"Model/Separations": -1})

    def test_numerical_failure_keeps_the_results_so_far(self):
        status, message = command_line_message(["run", NEWTON_FAILURE, "--output", self.tmp],
                                               "poundfe: numerical failure: ")
        self.assertEqual(status, 2)
        with self.assertRaises(poundfe.NumericalError) as caught:
            poundfe.run(NEWTON_FAILURE)
        self.assertIsInstance(caught.exception, RuntimeError)
        # the command line adds where the results went; Python hands them over
        self.assertEqual(str(caught.exception) + " (results up to that time are written)", message)
        results = caught.exception.results
        self.assertEqual((results.status, results.steps), ("failed", 3))
        header, rows = read_csv_text(os.path.join(self.tmp, "floor_displacement.csv"))
        self.assertIdentical(results.floor_displacement.data,
                             [[float(x) for x in row] for row in rows], "floor displacement")

    def test_mechanism_in_modal(self):
        status, message = command_line_message(["modal", MECHANISM, "--output", self.tmp],
                                               "poundfe: numerical failure: ")
        self.assertEqual(status, 2)
        with self.assertRaises(poundfe.NumericalError) as caught:
            poundfe.modal(MECHANISM)
        self.assertEqual(str(caught.exception), message)


class Commands(TestCase):
    def test_modal_command_and_modal_function(self):
        cli = os.path.join(self.tmp, "cli")
        py = os.path.join(self.tmp, "py")
        self.assertEqual(run_command_line("modal", EXAMPLE, "--output", cli)[0], 0)
        self.assertEqual(poundfe.command("modal", EXAMPLE, output=py), 0)
        self.assertEqual(sorted(os.listdir(py)), sorted(os.listdir(cli)))
        self.assertEqual(read_summary(py), read_summary(cli))
        modes = poundfe.modal(EXAMPLE)
        summary = read_summary(cli)
        self.assertIdentical(modes.frequencies, summary["modes"]["frequencies_hz"], "frequencies")
        for building, expected in zip(modes.buildings, summary["buildings"]):
            self.assertEqual(building.name, expected["name"])
            self.assertIdentical(building.periods, expected["modes"]["periods_s"], "periods")
            self.assertEqual(building.rayleigh, (expected["rayleigh_a0"], expected["rayleigh_a1"]))
        # mass-normalised shapes of 60 equations; the labels name the rows
        self.assertEqual(modes.shapes.shape, (60, 6))
        self.assertEqual(len(modes.equations), 60)
        self.assertTrue(modes.equations[0].startswith("A3_node"))

    def test_command_input_error_writes_nothing(self):
        out = os.path.join(self.tmp, "out")
        with self.assertRaisesRegex(poundfe.InputError, "Damping ratio"):
            poundfe.command("run", BAD, output=out)
        self.assertFalse(os.path.exists(out))

    def test_unknown_command_and_arguments(self):
        with self.assertRaisesRegex(ValueError, "unknown command 'runn'"):
            poundfe.command("runn", EXAMPLE)
        with self.assertRaisesRegex(ValueError, "needs exactly one parameter file"):
            poundfe.command("run")
        with self.assertRaisesRegex(ValueError, "realizations belongs to"):
            poundfe.command("run", EXAMPLE, realizations=3)


class BadPythonInput(TestCase):
    """Wrong types, NaN, huge strings, re-entry and threads: a Python
    exception (the command line's message where the reader decides),
    never a crash of the interpreter."""

    def assertSameAsSet(self, path, value, text):
        """poundfe.read with {path: value} raises the message of the
        command line's `--set path=text` on the same file."""
        status, message = command_line_message(
            ["modal", EXAMPLE, "--output", self.tmp, "--set", f"{path}={text}"], "poundfe: error: ")
        self.assertEqual(status, 1)
        with self.assertRaises(poundfe.InputError) as caught:
            poundfe.read(EXAMPLE, overrides={path: value})
        self.assertEqual(str(caught.exception), message)

    def test_nan_and_huge_values(self):
        self.assertSameAsSet("Model/Separations", float("nan"), "nan")
        self.assertSameAsSet("Model/Separations", np.float64("inf"), "inf")
        huge = "9" * 100000
        self.assertSameAsSet("Model/Separations", huge, huge)
        name = "x" * 100000  # a name may be long: read as it is
        read = poundfe.read(EXAMPLE, overrides={"Building 1/Name": name})
        self.assertEqual(dict(read.values)["Building 1/Name"], name)
        self.assertEqual(read.buildings[0], name)

    def test_wrong_types(self):
        with self.assertRaisesRegex(TypeError, "overrides"):
            poundfe.read(EXAMPLE, overrides=[1, 2])
        with self.assertRaisesRegex(TypeError, "overrides: a path is a str"):
            poundfe.read(EXAMPLE, overrides={3: 1})
        with self.assertRaises(TypeError):
            poundfe.run(42)
        with self.assertRaisesRegex(TypeError, "callback"):
            poundfe.run(EXAMPLE, callback="not a function")
        with self.assertRaisesRegex(ValueError, "every"):
            poundfe.run(EXAMPLE, callback=print, every=0)
        with self.assertRaises(TypeError):
            poundfe.command("modal", EXAMPLE, realizations="three")

    def test_callback_reentering_run(self):
        short = poundfe.read(EXAMPLE, overrides={"Time integration/End time": 0.05})

        def again(state):
            poundfe.run(short)

        with self.assertRaisesRegex(RuntimeError, "callback cannot start another run"):
            poundfe.run(short, callback=again, every=10)
        self.assertEqual(poundfe.run(short).status, "completed")  # usable afterwards

    def test_keyboard_interrupt_in_memory(self):
        short = poundfe.read(EXAMPLE, overrides={"Time integration/End time": 0.5})

        def interrupt(state):
            if state.step == 200:
                raise KeyboardInterrupt

        with self.assertRaises(KeyboardInterrupt):
            poundfe.run(short, callback=interrupt, every=100)
        self.assertEqual(poundfe.run(short).status, "completed")  # usable afterwards

    def test_two_threads(self):
        import threading
        short = poundfe.read(EXAMPLE, overrides={"Time integration/End time": 0.5})
        results, errors = [None, None], []

        def run(i):
            try:
                results[i] = poundfe.run(short)
            except BaseException as error:  # reported below
                errors.append(error)

        threads = [threading.Thread(target=run, args=(i,)) for i in range(2)]
        for thread in threads:
            thread.start()
        for thread in threads:
            thread.join()
        self.assertEqual(errors, [])
        self.assertIdentical(results[0].drift.data, results[1].drift.data, "two threads")


if __name__ == "__main__":
    unittest.main()
