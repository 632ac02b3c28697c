"""A model built in Python is the same model as the .prm file it copies
(input/two-buildings.prm, over its first 4 s): the same doubles in every
series and the same impact log (reference: poundfe.run on the .prm, itself
checked against the command line in test_run.py; tolerance none: the same
reader gets the same entries)."""

import os
import unittest

import poundfe
from common import EXAMPLE, TestCase, run_command_line


def two_buildings():
    """input/two-buildings.prm, entry by entry."""
    model = poundfe.Model()
    model.set("Model", mass_matrix="lumped")
    frame = dict(type="frame", column_E=3.0e10, beam_E=3.0e10)
    # keywords (column_A -> "Column A") and a dict of names as written
    model.add_building({"Bouc-Wen": {"alpha": 0.005}}, name="A3", number_of_storeys=3, number_of_bays=2,
                       storey_heights=[3.5, 3.0, 3.0], bay_widths=6.0, column_A=0.16,
                       column_I=2.1333e-3, beam_A=0.15, beam_I=3.125e-3,
                       floor_masses=[40000, 40000, 30000], **frame,
                       hinges={"Locations": "column bases, beam ends", "Groups": [1, 2, 4, 6],
                               "Yield moment": [180e3, 140e3, 140e3, 110e3]},
                       damping={"Type": "modes", "Damping ratio": 0.05, "Modes": [1, 3]})
    model.add_building({"Name": "B2", "Type": "frame", "Number of storeys": 2,
                        "Number of bays": 1, "Storey heights": [3.5, 3.0], "Bay widths": 5.0,
                        "Column E": 2.5e10, "Column A": 0.09, "Column I": 6.75e-4,
                        "Beam E": 2.5e10, "Beam A": 0.12, "Beam I": 1.6e-3,
                        "Floor masses": [18000, 15000],
                        "Hinges": {"Locations": "column bases, beam ends", "Groups": [1, 2, 4],
                                   "Yield moment": [80e3, 100e3, 80e3]},
                        "Bouc-Wen": {"alpha": 0.005},
                        "Damping": {"Type": "modes", "Damping ratio": 0.03, "Modes": [1, 2]}})
    model.gaps(0.01, law="hertz-damp", stiffness=2.75e9, damping_from="calibrated",
               coefficient_of_restitution=0.65)
    model.ground_motion(type="kanai-tajimi", stochastic={
        "Soil": "medium", "Target PGA": 0.35, "Peak factor": 3.0, "Duration": 20,
        "Envelope": "jennings", "Rise end": 2, "Plateau end": 10, "Decay rate": 0.3,
        "Seed": 2026})
    model.set("Time integration", time_step=0.001, linear_solver="eigen-ldlt")
    model.set("Output", output_interval=0.005)
    return model


class ModelInPython(TestCase):
    def test_same_numbers_as_the_prm_file(self):
        short = {"Time integration/End time": 4}
        from_file = poundfe.run(poundfe.read(EXAMPLE, overrides=short))
        built = two_buildings()
        from_python = poundfe.run(built.input(overrides=short))
        self.assertGreater(len(from_file.impacts), 0)
        self.assertEqual(sorted(from_python.series), sorted(from_file.series))
        for stem, table in from_file.series.items():
            self.assertEqual(from_python.series[stem].names, table.names)
            self.assertIdentical(from_python.series[stem].data, table.data, stem)
        for name in from_file.impacts.dtype.names:
            if from_file.impacts[name].dtype.kind == "f":  # an impact not ended: NaN
                self.assertIdentical(from_python.impacts[name], from_file.impacts[name], name)
            else:
                self.assertEqual(list(from_python.impacts[name]), list(from_file.impacts[name]), name)

    def test_written_file_runs_on_the_command_line(self):
        path = os.path.join(self.tmp, "built.prm")
        two_buildings().write(path)
        status, out, err = run_command_line("modal", path, "--output", os.path.join(self.tmp, "m"))
        self.assertEqual(status, 0, err)
        self.assertIdentical(poundfe.modal(path).frequencies, poundfe.modal(EXAMPLE).frequencies,
                             "frequencies")

    def test_bad_entry_is_the_readers_message(self):
        model = two_buildings()
        model.buildings[0]["Floor masses"] = [40000, 40000]  # three storeys
        with self.assertRaisesRegex(poundfe.InputError, "Building 1/Floor masses") as caught:
            model.input()
        self.assertTrue(caught.exception.file.endswith("model.prm"))
        with self.assertRaisesRegex(poundfe.InputError, r"model\.prm:\d+: parameter "
                                    r"'Building 1/Colour': No entry with name <Colour>"):
            bad = two_buildings()
            bad.buildings[0]["Colour"] = "red"
            bad.input()


if __name__ == "__main__":
    unittest.main()
