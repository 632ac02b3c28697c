"""The probabilistic commands from Python (poundfe.montecarlo, subset,
fragility, stationary_pdf) against the same commands on the command line:
every table the command line writes is in the result object, its numbers
the same doubles, summary.json the same but for the clock (reference: the
command line's files parsed with Python's float(); tolerance none: the same
dispatcher on the same input)."""

import unittest

from common import CommandTestCase

SMALL = "tests/cli/montecarlo-small.prm"
QUIET = {"Output/Plots": False}


class ProbabilisticCommands(CommandTestCase):
    def test_montecarlo(self):
        result = self.assertSameAsCommandLine("montecarlo", SMALL,
                                              {**QUIET, "Monte Carlo/Realizations": 3})
        self.assertEqual(len(result.realizations), 3)

    def test_subset(self):
        self.assertSameAsCommandLine("subset", SMALL, {**QUIET, "Subset simulation/Samples per level": 10,
                                                       "Subset simulation/Maximum levels": 2})

    def test_fragility(self):
        self.assertSameAsCommandLine("fragility", SMALL,
                                     {**QUIET, "Fragility/Realizations per level": 2})

    def test_stationary_pdf(self):
        self.assertSameAsCommandLine("stationary_pdf", "tests/cli/stationary-linear.prm", QUIET)


if __name__ == "__main__":
    unittest.main()
