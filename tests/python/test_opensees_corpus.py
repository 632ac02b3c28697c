"""poundfe.opensees against `poundfe opensees`: scripts of the Tcl corpus
(tests/opensees/) rewritten in OpenSeesPy's form (tests/opensees/python/,
only the import line differs from an OpenSeesPy script) write the Tcl runs'
recorder files byte for byte: a linear portal frame (gravity, eigen,
Rayleigh damping, a record), a pounding pair through a zero-length gap
(ElasticPPGap, ImpactMaterial), a fibre frame with gravity then a record
(Fiber sections and a Plain pattern filled by the commands after them), a
shallow arch followed past its limit point by ArcLength under constraints
Plain and Penalty, an elastic portal whose nodes and members made after
`rayleigh` are undamped (2D and 3D). The same command procedures run both:
a difference would be in how the values reach them."""

import os
import subprocess
import sys
import tempfile

from common import POUNDFE, ROOT, TestCase

CORPUS = os.path.join(ROOT, "tests", "opensees")
sys.path.insert(0, os.path.join(CORPUS, "python"))

import arc_length_arch  # noqa: E402
import fibre_frame_record  # noqa: E402
import portal_frame  # noqa: E402
import pounding_sticks  # noqa: E402
import rayleigh_later  # noqa: E402


class CorpusTest(TestCase):
    def run_both(self, script, run, files, *arguments):
        """The Tcl script under `poundfe opensees` and `run` (its Python
        form) into two directories; their files compared byte for byte;
        the Tcl run's standard output and `run`'s value."""
        tcl, python = os.path.join(self.tmp, "tcl"), os.path.join(self.tmp, "python")
        os.mkdir(tcl)
        os.mkdir(python)
        done = subprocess.run([POUNDFE, "opensees", os.path.join(CORPUS, script), tcl, *arguments],
                              capture_output=True, text=True)
        self.assertEqual(done.returncode, 0, done.stderr)
        value = run(python, *arguments)
        for name in files:
            with open(os.path.join(tcl, name), "rb") as a, open(os.path.join(python, name), "rb") as b:
                expected, actual = a.read(), b.read()
            self.assertGreater(len(expected), 1000, name)
            self.assertEqual(actual, expected, name)
        return done.stdout, value

    def test_portal_frame(self):
        _, eigenvalues = self.run_both("portal_frame.tcl", portal_frame.run,
                                       ["portal_disp.out", "portal_base.out"])
        with open(os.path.join(self.tmp, "tcl", "portal_eigen.out")) as f:
            self.assertEqual(eigenvalues, [float(v) for v in f.read().split()])

    def test_pounding_pair(self):
        for law in ("ElasticPPGap", "ImpactMaterial"):
            with self.subTest(law=law):
                stdout, (status, time) = self.run_both(
                    "pounding_sticks.tcl", pounding_sticks.run,
                    [f"pounding_{law}.out", f"pounding_{law}_vel.out"], law)
                self.assertEqual(status, 0)
                # the script's getTime: OpenSees's six decimals; Python's float
                self.assertIn(f"status 0 time {time:f} ", stdout)
                for name in os.listdir(self.tmp):
                    subprocess.run(["rm", "-rf", os.path.join(self.tmp, name)], check=True)

    def test_poundfe_namespace(self):
        """ops.poundfe: the pounding pair's energy balance closes (1e-8 of
        the largest term: the Newton test's 1e-10 m left in each step's
        equilibrium), its kinetic term is 1/2 m v^2 of nodeVel (to
        round-off), and the impact log has the contact episodes of the
        gap's recorded stress history (their number, the peak force)."""
        import poundfe.opensees as ops
        self.addCleanup(ops.wipe)
        status, _ = pounding_sticks.run(self.tmp, "ElasticPPGap", keep=True)
        self.assertEqual(status, 0)
        energy = ops.poundfe.energy()
        self.assertEqual(set(energy), {"input", "kinetic", "elements", "damping", "contact",
                                       "residual", "relative_residual"})
        self.assertLess(energy["relative_residual"], 1e-8)
        kinetic = 0.5 * 1.0e5 * (ops.nodeVel(2, 1) ** 2 + ops.nodeVel(4, 1) ** 2)
        self.assertAlmostEqual(energy["kinetic"] / kinetic, 1.0, delta=1e-12)
        impacts = ops.poundfe.impacts()
        report = ops.poundfe.report()
        self.assertGreaterEqual(report["steps"], 4000)  # the process's analyses
        ops.wipe()  # the recorders' files written
        with open(os.path.join(self.tmp, "pounding_ElasticPPGap_gap.out")) as f:
            stress = [abs(float(line.split()[1])) for line in f if line.strip()]
        episodes = sum(1 for a, b in zip([0.0] + stress, stress) if a == 0 and b > 0)
        self.assertGreater(episodes, 0)
        self.assertEqual(len(impacts), episodes)
        self.assertEqual({i["element"] for i in impacts}, {3})
        self.assertIsInstance(impacts[0]["element"], int)
        self.assertAlmostEqual(max(i["peak_force"] for i in impacts) / max(stress), 1.0,
                               delta=1e-12)
        with self.assertRaises(ops.OpenSeesError):
            ops.poundfe.impacts("-frobnicate")
        with self.assertRaises(ops.OpenSeesError):  # wipe turned it off
            ops.poundfe.energy()
        self.assertIsNone(ops.poundfe.energy("on"))
        self.assertIsNone(ops.poundfe.energy("off"))
        self.assertIsNone(ops.poundfe.stepCutting("on", 4))
        self.assertIsNone(ops.poundfe.stepCutting("off"))

    def test_locate_events(self):
        """ops.poundfe.locateEvents: with it on (6 halvings) every contact
        episode of the impact log starts and ends inside a recorded
        sub-step of at most dt/64 (the run without it has none such:
        its steps are dt's), the balance still closes to 1e-8; query gives
        the halvings, 0 when off; a setting out of range, or True, raises."""
        import poundfe.opensees as ops
        self.addCleanup(ops.wipe)
        self.assertEqual(ops.poundfe.locateEvents("query"), 0)
        for levels in (0, 6):
            status, _ = pounding_sticks.run(self.tmp, "ElasticPPGap", keep=True, locate=levels)
            self.assertEqual(status, 0)
            self.assertEqual(ops.poundfe.locateEvents("query"), levels)
            self.assertLess(ops.poundfe.energy()["relative_residual"], 1e-8)
            impacts = ops.poundfe.impacts()
            ops.wipe()  # the recorders' files written
            with open(os.path.join(self.tmp, "pounding_ElasticPPGap.out")) as f:
                times = [float(line.split()[0]) for line in f if line.strip()]
            events = [i["start_time"] for i in impacts] + \
                     [i["end_time"] for i in impacts if i["end_time"] >= 0]
            self.assertGreater(len(events), 2)
            # the shortest recorded step that holds it (an episode of the
            # damaged gap starts where the step whose force is its first begins)
            finest = [min(b - a for a, b in zip(times, times[1:]) if a <= t <= b) for t in events]
            if levels:
                self.assertLessEqual(max(finest), 0.002 / 64 * (1 + 1e-9))
            else:
                self.assertGreater(min(finest), 0.002 * (1 - 1e-9))
        self.assertEqual(ops.poundfe.locateEvents("query"), 0)  # wipe turned it off
        self.assertIsNone(ops.poundfe.locateEvents("on"))
        self.assertEqual(ops.poundfe.locateEvents("query"), 4)
        self.assertIsNone(ops.poundfe.locateEvents("off"))
        for hostile in (("on", -1), ("on", 99), ("on", "x"), ("sometimes",), ("on", True)):
            with self.assertRaises(ops.OpenSeesError):
                ops.poundfe.locateEvents(*hostile)
        self.assertEqual(ops.poundfe.locateEvents("query"), 0)  # True refused, not taken as 1

    def test_fibre_frame_gravity_then_record(self):
        stdout, (status, roof) = self.run_both(
            "fibre_frame_record.tcl", fibre_frame_record.run,
            ["frame_disp.out", "frame_base.out", "frame_section.out", "frame_beam.out"])
        self.assertEqual(status, 0)
        self.assertIn(f"frame: status 0 roof {roof!r} ", stdout)

    def test_objects_made_after_rayleigh(self):
        for variant in ("2d", "3d"):
            with self.subTest(variant=variant):
                self.run_both("rayleigh_later.tcl", rayleigh_later.run,
                              ["disp.out", "tip.out", "force.out"], variant)
                for name in os.listdir(self.tmp):
                    subprocess.run(["rm", "-rf", os.path.join(self.tmp, name)], check=True)

    def test_refused_command_keeps_settings(self):
        """A caught refusal leaves the settings before it: Transformation
        keeps the equalDOF (node 3's uy is node 2's), LoadControl 1.0 its
        two steps of a linear frame, the column shortened by 2 L / EA =
        3e-6 (to round-off, 1e-12 relative)."""
        import poundfe.opensees as ops
        ops.wipe()
        ops.model('basic', '-ndm', 2, '-ndf', 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 0.0, 3.0)
        ops.node(3, 4.0, 3.0)
        ops.fix(1, 1, 1, 1)
        ops.geomTransf('Linear', 1)
        ops.element('elasticBeamColumn', 1, 1, 2, 0.01, 2.0e8, 1.0e-4, 1)
        ops.element('elasticBeamColumn', 2, 2, 3, 0.01, 2.0e8, 1.0e-4, 1)
        ops.equalDOF(2, 3, 2)
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(3, 1.0, -1.0, 0.0)
        ops.test('NormDispIncr', 1e-10, 20)
        ops.constraints('Transformation')
        ops.integrator('LoadControl', 1.0)
        for refused in (('constraints', 'Penalty', 1.0e10), ('integrator', 'ArcLength', -1.0, 0.0),
                        ('integrator', 'DisplacementControl', 3, 2, 0.1, 0, 0.1, 0.1)):
            with self.assertRaises(ops.OpenSeesError):
                getattr(ops, refused[0])(*refused[1:])
        ops.analysis('Static')
        self.assertEqual(ops.analyze(2), 0)
        self.assertEqual(ops.getTime(), 2.0)
        self.assertAlmostEqual(ops.nodeDisp(2, 2) / -3e-6, 1.0, delta=1e-12)
        self.assertEqual(ops.nodeDisp(3, 2), ops.nodeDisp(2, 2))
        ops.wipe()

    def test_arc_length_arch(self):
        for handler in ([], ["Penalty", "1.0e12", "1.0e12"]):
            with self.subTest(handler=handler):
                arguments = ["0.01", "0.0005", "45", *handler]
                stdout, (status, lam) = self.run_both(
                    "arc_length_arch.tcl", arc_length_arch.run, ["apex.out", "support.out"],
                    *arguments)
                self.assertEqual(status, 0)
                self.assertIn(f"arch: analyze 0 lambda {lam:f} ", stdout)
                for name in os.listdir(self.tmp):
                    subprocess.run(["rm", "-rf", os.path.join(self.tmp, name)], check=True)
