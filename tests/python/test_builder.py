"""The model builder: keywords looked up in the program's own declarations
(acronyms such as PGA right, "did you mean" for a typo), NumPy values, the
reader's errors pointing at the caller's line, Model.from_file and
Input.write reading back to the same entries (reference: the reader's
entry-by-entry values, Input.values; tolerance none: text for text)."""

import os
import tempfile
import unittest

import numpy as np

import poundfe
from common import EXAMPLE, TestCase


class KeywordTable(TestCase):
    def test_generated_from_the_declarations(self):
        table = poundfe.keyword_table("Ground motion/Stochastic")
        self.assertEqual(table["target_pga"], "Target PGA")
        self.assertEqual(poundfe.keyword_table("Time integration")["time_step"], "Time step")
        self.assertEqual(poundfe.keyword_table("Building 3")["bouc_wen"], "Bouc-Wen")
        model = poundfe.Model().set("Ground motion/Stochastic", target_pga=0.3)
        self.assertEqual(model.sections["Ground motion"]["Stochastic"], {"Target PGA": 0.3})

    def test_did_you_mean(self):
        with self.assertRaisesRegex(poundfe.InputError,
                                    r"'Time integration' has no entry or subsection 'time_stepp'; "
                                    r"did you mean time_step \('Time step'\)"):
            poundfe.Model().set("Time integration", time_stepp=0.001)
        with self.assertRaisesRegex(poundfe.InputError, r"did you mean floor_masses"):
            poundfe.Model().add_building(floor_mases=[1, 2])


class Values(TestCase):
    def test_numpy_scalars_and_arrays(self):
        model = poundfe.Model()
        model.add_building(name="S", type="shear", number_of_storeys=np.int64(2),
                           storey_heights=np.float64(3.0), floor_masses=np.array([2e4, 1.5e4]),
                           storey_stiffnesses=np.array([3e7, np.float32(2.5e7)]))
        text = model.text()
        self.assertIn("set Number of storeys = 2\n", text)
        self.assertIn("set Floor masses = 20000.0, 15000.0\n", text)
        self.assertIn("set Storey heights = 3.0\n", text)
        values = dict(model.input().values)
        self.assertEqual(values["Building 1/Floor masses"], "20000.0, 15000.0")
        with self.assertRaisesRegex(TypeError, "1-D"):
            model = poundfe.Model()
            model.add_building(floor_masses=np.ones((2, 2)))
            model.text()

    def test_error_points_at_the_call(self):
        model = poundfe.Model()
        model.add_building(name="S", type="shear", number_of_storeys=2, storey_heights=3.0,
                           floor_masses=[2e4, 2e4, 2e4], storey_stiffnesses=3e7)  # three masses
        with self.assertRaises(poundfe.InputError) as caught:
            model.input()
        message = str(caught.exception)
        self.assertIn("Building 1/Floor masses", message)
        self.assertIn(f"set at {os.path.abspath(__file__)}:", message)
        self.assertNotIn("poundfe-model-", message)  # no temporary directory
        self.assertEqual(caught.exception.file, "model.prm")


class WithoutFiles(TestCase):
    """The reader parses a Model's text itself: no temporary file (tempfile's
    directory is a plain file here, so that any use of it fails), and a bad
    value is named by its entry, the Model's line and the caller's line."""

    def setUp(self):
        super().setUp()
        self.blocked = os.path.join(self.tmp, "not-a-directory")
        with open(self.blocked, "w") as f:
            f.write("tempfile must not be used\n")
        self.saved_tempdir, tempfile.tempdir = tempfile.tempdir, self.blocked

    def tearDown(self):
        tempfile.tempdir = self.saved_tempdir
        super().tearDown()

    def bad_model(self):
        model = poundfe.Model.from_file(EXAMPLE)
        model.set("Time integration", time_step=-0.001)  # refused by the entry's range
        return model

    def assertPointsAtTheCall(self, caught):
        message = str(caught.exception)
        self.assertIn("Time integration/Time step", message)
        self.assertIn(f"set at {os.path.abspath(__file__)}:", message)
        self.assertNotIn(self.tmp, message)
        # no temporary file named: the text is called model.prm, with no
        # directory (the repository itself may lie under /tmp)
        self.assertNotIn("/model.prm", message)
        self.assertEqual(caught.exception.file, "model.prm")
        self.assertEqual(sorted(os.listdir(self.tmp)), ["not-a-directory"])

    def test_input_and_run_read_no_file(self):
        self.assertEqual(len(poundfe.Model.from_file(EXAMPLE).input().buildings), 2)
        with self.assertRaises(poundfe.InputError) as caught:
            self.bad_model().input()
        self.assertPointsAtTheCall(caught)
        with self.assertRaises(poundfe.InputError) as caught:
            poundfe.run(self.bad_model())
        self.assertPointsAtTheCall(caught)

    def test_command_refuses_before_any_file(self):
        with self.assertRaises(poundfe.InputError) as caught:
            poundfe.spectrum(self.bad_model())
        self.assertPointsAtTheCall(caught)


class PatternErrors(TestCase):
    """A value the entry's pattern refuses (NaN, text for a number, an
    infinite step) is named by its whole entry path and the caller's line,
    as a range check's error is."""

    def assertNamed(self, model, parameter, call=lambda model: model.input()):
        with self.assertRaises(poundfe.InputError) as caught:
            call(model)
        error = caught.exception
        self.assertEqual(error.parameter, parameter)
        self.assertIn(f"parameter '{parameter}'", str(error))
        self.assertIn("does not match", str(error))
        self.assertTrue(error.origin.startswith(os.path.abspath(__file__) + ":"), error.origin)
        self.assertIn(f"(set at {error.origin})", str(error))
        self.assertEqual(error.file, "model.prm")

    def test_nan_text_and_infinity(self):
        model = poundfe.Model.from_file(EXAMPLE)
        model.add_building(name="C", type="shear", number_of_storeys=1, storey_heights=3.0,
                           floor_masses=5000, storey_stiffnesses=np.array([np.nan]))
        self.assertNamed(model, "Building 3/Storey stiffnesses")
        self.assertNamed(model, "Building 3/Storey stiffnesses", poundfe.modal)
        model = poundfe.Model.from_file(EXAMPLE).set("Contact", stiffness="stiff")
        self.assertNamed(model, "Contact/Stiffness")
        model = poundfe.Model.from_file(EXAMPLE).set("Time integration", time_step=float("inf"))
        self.assertNamed(model, "Time integration/Time step", poundfe.spectrum)


class RelativeFiles(TestCase):
    """A Model's relative file names are taken against the working directory
    also by a command, which reads the model from a temporary file: the
    names the reader finds (Input.input_files) are written absolute, in the
    text and in the overrides."""

    IDA = "tests/cli/ida/ida-small.prm"
    SHORT = {"MSA/Intensities": 0.2, "MSA/Cloud": False}

    def test_suite_relative_to_the_working_directory(self):
        model = poundfe.Model.from_file(self.IDA).set("IDA", suite="tests/cli/ida/suite.csv")
        self.assertIn(("IDA/Suite", "tests/cli/ida/suite.csv"), model.input().input_files)
        self.assertGreater(len(poundfe.msa(model, overrides=self.SHORT).msa), 0)
        model = poundfe.Model.from_file(self.IDA)
        self.assertTrue(os.path.isabs(model.sections["IDA"]["Suite"]))
        overrides = dict(self.SHORT, **{"IDA/Suite": "tests/cli/ida/suite.csv"})
        self.assertGreater(len(poundfe.msa(model, overrides=overrides).msa), 0)

    def test_every_named_file_field(self):
        sections = {"Nodal forces": {"Tabulated": "1 2 0 0 f.csv; 2 1 0 0 /abs/g.csv"},
                    "Ground motion": {"Record": {"File": "r.AT2"}}}
        files = [("Nodal forces/Tabulated", "f.csv"), ("Nodal forces/Tabulated", "/abs/g.csv"),
                 ("Ground motion/Record/File", "r.AT2")]
        out = poundfe.model.absolute_files(sections, files, "/base")
        self.assertEqual(out["Nodal forces"]["Tabulated"], "1 2 0 0 /base/f.csv; 2 1 0 0 /abs/g.csv")
        self.assertEqual(out["Ground motion"]["Record"]["File"], "/base/r.AT2")
        self.assertEqual(sections["Ground motion"]["Record"]["File"], "r.AT2")  # a copy


class FromFileAndWrite(TestCase):
    def test_model_from_file_is_the_same_input(self):
        original = poundfe.read(EXAMPLE)
        model = poundfe.Model.from_file(EXAMPLE)
        self.assertEqual(len(model.buildings), 2)
        self.assertEqual(model.input().values, original.values)

    def test_input_write_reads_back(self):
        original = poundfe.read(EXAMPLE, overrides={"Model/Separations": 0.02})
        path = os.path.join(self.tmp, "written.prm")
        original.write(path)
        again = poundfe.read(path)
        self.assertEqual(again.values, original.values)
        self.assertEqual(dict(again.values)["Model/Separations"], "0.02")


if __name__ == "__main__":
    unittest.main()
