"""poundfe.run(..., output=dir) stopped by Ctrl-C (KeyboardInterrupt) leaves
its directory as the command line's interrupted run does: every file its
summary.json and its manifest list exists (but gnuplot's scratch files, removed
after drawing as always), and summary.json says "interrupted";
the KeyboardInterrupt still reaches the caller. Two ways in: raised inside
the callback (Ctrl-C while Python code runs), and a real SIGINT that
arrives while poundfe steps (seen by the check every 256 steps).
poundfe.command, the command line's own dispatcher, raises it too (not the
exit status 130), its result the files written so far; poundfe.run's
KeyboardInterrupt holds its results so far (in memory too) as `result`.
Reference: the directory itself (what exists afterwards)."""

import os
import signal
import threading
import unittest

import poundfe
from common import EXAMPLE, TestCase, read_summary

poundfe.Input  # the core loaded now (poundfe loads it at its first name), before any timer


class InterruptedRun(TestCase):
    def check_directory(self, directory):
        summary = read_summary(directory)
        self.assertEqual(summary["status"], "interrupted")
        files = summary["output"]["files"]
        self.assertIn("summary.json", files)
        absent = [name for name in files if not os.path.exists(os.path.join(directory, name))]
        self.assertEqual(absent, [], "in summary.json but absent")
        # the manifest too (gnuplot's scratch files are listed before they
        # are made, so that a killed gnuplot's go, and removed after drawing)
        with open(os.path.join(directory, ".poundfe-files")) as f:
            listed = [line.strip() for line in f if line.strip()]
        scratch = {".plots.gp", ".plots.log"}
        missing = [name for name in listed
                   if name not in scratch and not os.path.exists(os.path.join(directory, name))]
        self.assertEqual(missing, [], "listed but absent")
        temporaries = [n for n in os.listdir(directory) if n.endswith(".tmp")]
        self.assertEqual(temporaries, [])
        return summary

    def test_keyboard_interrupt_in_the_callback(self):
        directory = os.path.join(self.tmp, "callback")

        def callback(state):
            if state.step >= 1000:
                raise KeyboardInterrupt

        with self.assertRaises(KeyboardInterrupt):
            poundfe.run(poundfe.read(EXAMPLE), output=directory, callback=callback, every=100)
        self.check_directory(directory)

    def test_sigint_while_poundfe_steps(self):
        directory = os.path.join(self.tmp, "signal")
        timers = []

        def start(state):  # step 0 only: then poundfe steps without Python code
            timer = threading.Timer(0.3, os.kill, (os.getpid(), signal.SIGINT))
            timer.start()
            timers.append(timer)

        with self.assertRaises(KeyboardInterrupt) as caught:
            poundfe.run(poundfe.read(EXAMPLE), output=directory, callback=start, every=10**9)
        for timer in timers:
            timer.join()
        self.check_directory(directory)
        self.check_result_so_far(caught.exception, directory)

    def check_result_so_far(self, exception, directory):
        # the results so far ride on the KeyboardInterrupt, as a command's
        # result does: the summary's status and steps (reference: the files)
        result = exception.result
        self.assertIsInstance(result, poundfe.Results)
        self.assertEqual(result.status, "interrupted")
        if directory is not None:
            self.assertEqual(read_summary(directory)["status"], result.status)
        self.assertGreater(result.steps, 0)
        self.assertGreater(len(result.drift), 1)
        self.assertLess(result.drift.time[-1], 200)

    def test_sigint_in_memory_keeps_the_results_so_far(self):
        timer = threading.Timer(0.5, os.kill, (os.getpid(), signal.SIGINT))
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt) as caught:
                poundfe.run(poundfe.read(EXAMPLE, overrides={"Time integration/End time": 200}))
        finally:
            timer.cancel()
        self.check_result_so_far(caught.exception, None)

    def test_command_raises_keyboard_interrupt(self):
        # poundfe.command raises where the command line exits 130, with the
        # files written so far as its result (before: it returned 130)
        directory = os.path.join(self.tmp, "command")
        timer = threading.Timer(1.0, os.kill, (os.getpid(), signal.SIGINT))
        timer.start()
        try:
            with self.assertRaises(KeyboardInterrupt) as caught:
                poundfe.command("run", EXAMPLE, output=directory,
                                overrides={"Time integration/End time": 200})
        finally:
            timer.cancel()
        result = caught.exception.result
        self.assertIsInstance(result, poundfe.CommandResult)
        self.assertEqual(result.status, "interrupted")
        self.assertEqual(result.output, directory)
        self.assertLess(result.drift.time[-1], 200)
        self.check_directory(directory)


if __name__ == "__main__":
    unittest.main()
