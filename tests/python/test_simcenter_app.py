"""scripts/poundfe_simcenter.py, poundfe as a SimCenter simulation application,
against the files of SimCenterBackendApplications' earthquake workflow (the
schemas written out below; SimCenter is not installable here):

- the command-line contract --filenameAIM/--filenameSAM/--filenameEVENT/
  --filenameEDP/--filenameSIM [--getRV];
- EVENT.json (OpenSeesPreprocessor's reading of it): Events[0].timeSeries
  [{type "Value", name, dT, data, factor}], Events[0].pattern
  [{type "UniformAcceleration", timeSeries, dof}], Events[0].factor,
  Events[0].units {length, time}: acceleration = data x factor x factor in
  length/time^2;
- EDP.json (createEDP/standardEarthquakeEDP, filled as customPySimulation
  does): {"RandomVariables": [], "total_number_edp": N,
  "EngineeringDemandParameters": [{"name", "responses": [{"type", "cline",
  "floor" | "floor1"+"floor2", "dofs": [..], "scalar_data": [one per dof]}]}]},
  N the sum of len(dofs); results.out the N numbers in order.

Numbers: each EDP equals `poundfe run` of the same record written directly in
m/s^2 (exactly: the same doubles reach the same run; the script converts the
EVENT's in/s^2 times its factors, so the direct record is converted here the
same way, 1e-12 relative for the round-off of that product). Bad input: exit 1,
one line naming the file and the entry, EDP.json untouched.
"""

import csv
import json
import math
import os
import subprocess
import sys
import unittest

from common import POUNDFE, ROOT, TestCase

SCRIPT = os.path.join(ROOT, "scripts", "poundfe_simcenter.py")

MODEL = """subsection Model
  set Number of buildings = 2
  set Separations = 0.01
end
subsection Building 1
  set Name = tall
  set Type = shear
  set Number of storeys = 3
  set Floor masses = 1000
  set Storey stiffnesses = 5e5
end
subsection Building 2
  set Name = low
  set Type = shear
  set Number of storeys = 2
  set Floor masses = 1000
  set Storey stiffnesses = 3e5
end
subsection Contact
  set Law = linear
  set Stiffness = 5e8
end
subsection Time integration
  set Time step = 0.005
end
"""

STANDARD_TYPES = {"max_abs_acceleration", "max_rel_disp", "max_drift", "max_roof_drift",
                  "residual_drift", "residual_disp"}
POUNDING_TYPES = {"impact_count", "max_impact_force", "max_impact_velocity"}


def standard_edp(n):
    """EDP.json as createEDP/standardEarthquakeEDP writes it for floors 0..n, dof 1."""
    responses = []
    for f in range(n + 1):
        responses.append({"type": "max_abs_acceleration", "cline": "response", "floor": str(f),
                          "dofs": [1], "scalar_data": []})
        if f > 0:
            responses.append({"type": "max_rel_disp", "cline": "response", "floor": str(f),
                              "dofs": [1], "scalar_data": []})
            responses.append({"type": "max_drift", "cline": "response", "floor1": str(f - 1),
                              "floor2": str(f), "dofs": [1], "scalar_data": []})
    responses.append({"type": "max_roof_drift", "cline": "response", "floor1": "0",
                      "floor2": str(n), "dofs": [1], "scalar_data": []})
    return {"RandomVariables": [], "total_number_edp": 3 * n + 2,
            "EngineeringDemandParameters": [{"name": "quake-1", "responses": responses}]}


def check_edp_schema(test, edp, filled):
    test.assertEqual(edp["RandomVariables"], [])
    events = edp["EngineeringDemandParameters"]
    test.assertEqual(len(events), 1)
    total = 0
    for r in events[0]["responses"]:
        test.assertIn(r["type"], STANDARD_TYPES | POUNDING_TYPES)
        test.assertTrue("floor" in r or ("floor1" in r and "floor2" in r), r)
        test.assertTrue(r["dofs"] and all(d in (1, 2, 3) for d in r["dofs"]), r)
        test.assertEqual(len(r["scalar_data"]), len(r["dofs"]) if filled else 0, r)
        for x in r["scalar_data"]:
            test.assertTrue(isinstance(x, float) and math.isfinite(x), r)
        total += len(r["dofs"])
    test.assertEqual(edp["total_number_edp"], total)


class SimCenterApp(TestCase):
    def setUp(self):
        super().setUp()
        os.chdir(self.tmp)
        os.mkdir("model")
        with open("model/pair.prm", "w") as f:
            f.write(MODEL)
        self.acc_in = [400 * math.exp(-0.4 * 0.01 * k) * math.sin(9 * 0.01 * k) for k in range(800)]
        self.write("AIM.json", {"GeneralInformation": {"units": {"length": "m", "force": "N",
                                                                 "time": "sec"}}})
        self.write("SAM.json", {"mainScript": "pair.prm", "modelPath": os.path.abspath("model"),
                                "building": "tall"})
        self.write("EVENT.json", {"randomVariables": [], "Events": [{
            "name": "quake-1", "type": "Seismic", "dT": 0.01, "numSteps": 800, "factor": 2.0,
            "units": {"length": "in", "time": "sec"},
            "timeSeries": [{"type": "Value", "name": "accel-1", "dT": 0.01, "factor": 0.5,
                            "data": self.acc_in}],
            "pattern": [{"type": "UniformAcceleration", "timeSeries": "accel-1", "dof": 1}]}]})
        self.write("EDP.json", standard_edp(3))

    def write(self, name, data):
        with open(name, "w") as f:
            json.dump(data, f)

    def app(self, *extra):
        arguments = ["--filenameAIM", "AIM.json", "--filenameEVENT", "EVENT.json", "--filenameSAM",
                     "SAM.json", "--filenameEDP", "EDP.json", "--filenameSIM", "SIM.json", *extra]
        return subprocess.run([sys.executable, SCRIPT, *arguments], capture_output=True, text=True,
                              env={**os.environ, "POUNDFE": POUNDFE})

    def direct_run(self):
        """`poundfe run` of the same record in m/s^2: {(kind, building, n): value}."""
        with open("direct.txt", "w") as f:
            f.write("".join(f"{a * 0.5 * 2.0 * 0.0254!r}\n" for a in self.acc_in))
        sets = {"Ground motion/Type": "record", "Ground motion/Record/File": os.path.abspath("direct.txt"),
                "Ground motion/Record/Format": "text", "Ground motion/Record/Units": "m/s^2",
                "Ground motion/Record/Time step": "0.01", "Output/Plots": "false",
                "Output/VTU interval": "0"}
        command = [POUNDFE, "run", "model/pair.prm", "--output", "direct"]
        for k, v in sets.items():
            command += ["--set", f"{k}={v}"]
        done = subprocess.run(command, capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        with open("direct/drift_profile.csv") as f:
            drift = {int(r["storey"]): float(r["peak_drift_ratio"])
                     for r in csv.DictReader(f) if r["building"] == "tall"}
        with open("direct/acceleration_profile.csv") as f:
            accel = {int(r["floor"]): r for r in csv.DictReader(f) if r["building"] == "tall"}
        return drift, accel

    def test_get_rv_then_run(self):
        done = self.app("--getRV")
        self.assertEqual(done.returncode, 0, done.stderr)
        with open("SIM.json") as f:
            self.assertEqual(json.load(f), {})
        with open("EDP.json") as f:
            edp = json.load(f)
        check_edp_schema(self, edp, filled=False)
        pounding = [r for r in edp["EngineeringDemandParameters"][0]["responses"]
                    if r["type"] in POUNDING_TYPES]
        # the two gaps at the low building's floors 1 and 2, three demands each
        self.assertEqual(sorted((r["floor"], r["gap"], r["type"]) for r in pounding),
                         sorted((f, g, t) for f, g in (("1", "1"), ("2", "2")) for t in POUNDING_TYPES))
        done = self.app()
        self.assertEqual(done.returncode, 0, done.stderr)
        with open("EDP.json") as f:
            edp = json.load(f)
        check_edp_schema(self, edp, filled=True)
        responses = edp["EngineeringDemandParameters"][0]["responses"]
        with open("results.out") as f:
            results = [float(x) for x in f.read().split()]
        self.assertEqual(results, [x for r in responses for x in r["scalar_data"]])
        drift, accel = self.direct_run()
        peak = max(abs(a * 0.5 * 2.0 * 0.0254) for a in self.acc_in)
        for r in responses:
            value = r["scalar_data"][0]
            if r["type"] == "max_drift":
                self.assertEqual(value, drift[int(r["floor2"])])
            elif r["type"] == "max_abs_acceleration":  # m/s^2: the AIM's units
                expected = peak if r["floor"] == "0" else float(accel[int(r["floor"])]["peak_absolute_acc_m_s2"])
                self.assertAlmostEqual(value, expected, delta=1e-12 * expected)
            elif r["type"] == "max_rel_disp":
                self.assertEqual(value, float(accel[int(r["floor"])]["peak_floor_disp_m"]))
            elif r["type"] == "max_roof_drift":
                self.assertAlmostEqual(value, float(accel[3]["peak_floor_disp_m"]) / 9.0, delta=1e-15)
        impacts = sum(r["scalar_data"][0] for r in responses if r["type"] == "impact_count")
        self.assertGreater(impacts, 0)  # the pair pounds under this record

    def test_get_rv_without_an_edp_file_writes_the_standard_ones(self):
        os.remove("EDP.json")
        done = self.app("--getRV")
        self.assertEqual(done.returncode, 0, done.stderr)
        with open("EDP.json") as f:
            edp = json.load(f)
        check_edp_schema(self, edp, filled=False)
        types = {r["type"] for r in edp["EngineeringDemandParameters"][0]["responses"]}
        self.assertEqual(types, (STANDARD_TYPES - {"residual_disp"}) | POUNDING_TYPES)

    def test_bad_input(self):
        with open("EDP.json") as f:
            before = f.read()
        self.write("SAM.json", {"modelPath": "model"})
        done = self.app()
        self.assertEqual(done.returncode, 1)
        self.assertEqual(done.stderr.count("\n"), 1, done.stderr)
        self.assertIn("SAM.json: parameter 'mainScript'", done.stderr)
        self.write("SAM.json", {"mainScript": "pair.prm", "modelPath": "model"})
        with open("EVENT.json") as f:
            event = json.load(f)
        event["Events"][0]["pattern"][0]["dof"] = 3
        self.write("EVENT.json", event)
        done = self.app()
        self.assertEqual(done.returncode, 1)
        self.assertIn("EVENT.json: parameter 'Events[0].pattern[0].dof'", done.stderr)
        with open("EDP.json") as f:
            self.assertEqual(f.read(), before)
        self.assertFalse(os.path.exists("results.out"))
        self.assertFalse(os.path.exists("poundfe_run"))


if __name__ == "__main__":
    unittest.main()
