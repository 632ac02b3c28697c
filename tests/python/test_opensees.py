"""poundfe.opensees, OpenSeesPy's calling conventions: the types of the
results (float, list of floats, int, list of ints, None), list arguments
(a Path series' values as a list, a tuple, a NumPy array or words of their
own; NumPy scalars), the errors (OpenSeesError naming the command and the
caller's line; a command poundfe lacks; a bad argument), `wipe` between two
models, the commands made from the core's own list, a 3D fibre section
with '-GJ' filled by later calls (a cantilever against its closed form),
twoNodeLink, Series and ViscousDamper made with OpenSeesPy's words, and
zeroLengthSection (OpenSeesPy's 2D -orient) and corotTruss against their
closed forms, rigidLink beam and an elasticBeamColumn's -cMass against
theirs."""

import json
import math
import os
import shutil
import sys
import tempfile

import numpy as np

import poundfe
import poundfe.opensees as ops

from common import TestCase


def sdof(k=100.0, mass=1.0):
    """Fresh: a spring of stiffness k from a fixed node 1 to node 2."""
    ops.wipe()
    ops.model('basic', '-ndm', 1, '-ndf', 1)
    ops.node(1, 0.0)
    ops.node(2, 0.0, '-mass', mass)
    ops.fix(1, 1)
    ops.uniaxialMaterial('Elastic', 1, k)
    ops.element('zeroLength', 1, 1, 2, '-mat', 1, '-dir', 1)


def static_analysis(steps=1):
    ops.constraints('Plain')
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 10)
    ops.algorithm('Newton')
    ops.integrator('LoadControl', 1.0 / steps)
    ops.analysis('Static')


def record_history(values_argument, spacing=('-dt', 0.01)):
    """Node 2's displacements of an SDOF under a Path record given by
    `values_argument(values)`, a tuple of the timeSeries arguments after
    -values, and `spacing`'s arguments before them."""
    sdof(k=400.0)
    values = [math.sin(0.3 * i) for i in range(51)]
    ops.timeSeries('Path', 1, *spacing, '-values', *values_argument(values), '-factor', 2.0)
    ops.pattern('UniformExcitation', 1, 1, '-accel', 1)
    ops.constraints('Plain')
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 10)
    ops.algorithm('Newton')
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    history = []
    for _ in range(50):
        ops.analyze(1, 0.01)
        history.append(ops.nodeDisp(2, 1))
    return history


class ConventionsTest(TestCase):
    def tearDown(self):
        ops.wipe()
        super().tearDown()

    def test_return_types(self):
        ops.wipe()
        self.assertEqual(ops.getNodeTags(), [])  # a list, also empty
        self.assertEqual(ops.getEleTags(), [])
        sdof(k=100.0)
        self.assertIsNone(ops.node(3, 1.0))
        ops.fix(3, 1)
        self.assertEqual(ops.getNodeTags(), [1, 2, 3])
        self.assertTrue(all(type(t) is int for t in ops.getNodeTags()))
        self.assertEqual(ops.getEleTags(), [1])
        self.assertEqual(ops.nodeCoord(3), [1.0])
        ops.timeSeries('Linear', 1)
        self.assertIsNone(ops.pattern('Plain', 1, 1))
        ops.load(2, 50.0)  # into pattern 1: OpenSeesPy has no body
        static_analysis(steps=2)
        status = ops.analyze(2)
        self.assertIs(type(status), int)
        self.assertEqual(status, 0)
        u = ops.nodeDisp(2, 1)
        self.assertIs(type(u), float)
        self.assertAlmostEqual(u, 0.5, delta=1e-15)
        self.assertEqual(ops.nodeDisp(2), [u])
        self.assertIs(type(ops.getTime()), float)
        self.assertEqual(ops.getTime(), 1.0)
        self.assertEqual(ops.eleForce(1), [-50.0, 50.0])
        self.assertEqual(ops.eleForce(1, 2), 50.0)
        self.assertIsNone(ops.reactions())
        self.assertEqual(ops.nodeReaction(1, 1), -50.0)
        eigenvalues = ops.eigen(1)
        self.assertIsInstance(eigenvalues, list)  # a list, also of one mode
        self.assertAlmostEqual(eigenvalues[0], 100.0, delta=1e-12)

    def test_queries_return_types(self):
        sdof()
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(2, 50.0)
        directory = tempfile.mkdtemp()
        envelope = os.path.join(directory, 'envelope.out')
        tag = ops.recorder('EnvelopeNode', '-file', envelope, '-node', 2, '-dof', 1, 'disp')
        self.assertIs(type(tag), int)
        static_analysis(steps=2)
        ops.test('NormDispIncr', 1.0e-12, 6)
        ops.analyze(1)
        self.assertEqual(ops.testIter(), 2)  # linear: the second increment is 0
        norms = ops.testNorm()
        self.assertEqual(len(norms), 6)
        self.assertAlmostEqual(norms[0], 0.25, delta=1e-15)
        self.assertEqual(norms[1:], [0.0] * 5)
        self.assertEqual((ops.getNP(), ops.getPID()), (1, 0))
        self.assertIs(type(ops.getTime()), float)  # OpenSeesPy's float, not Tcl's text
        self.assertIsNone(ops.remove('recorder', tag))  # its file written now
        self.assertEqual(np.loadtxt(envelope).tolist(), [0.25, 0.25, 0.25])
        shutil.rmtree(directory)

    def test_failed_analysis_is_a_negative_int(self):
        sdof()
        ops.uniaxialMaterial('Steel01', 2, 10.0, 100.0, 0.01)
        ops.element('zeroLength', 2, 1, 2, '-mat', 2, '-dir', 1)
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(2, 50.0)
        static_analysis()
        ops.test('NormDispIncr', 1.0e-14, 1)  # Steel01 yields: one iteration is not enough
        status = ops.analyze(1)
        self.assertIs(type(status), int)
        self.assertLess(status, 0)
        self.assertEqual(ops.getTime(), 0.0)

    def test_list_arguments(self):
        as_list = record_history(lambda v: (v,))
        self.assertGreater(max(abs(u) for u in as_list), 1e-4)
        for form, argument in [("tuple", lambda v: (tuple(v),)),
                               ("NumPy array", lambda v: (np.array(v),)),
                               ("words of their own", lambda v: tuple(v)),
                               ("NumPy scalars", lambda v: tuple(np.array(v)))]:
            with self.subTest(form=form):
                self.assertEqual(record_history(argument), as_list)

    def test_numpy_scalars(self):
        ops.wipe()
        ops.model('basic', '-ndm', np.int64(2), '-ndf', np.int32(3))
        ops.node(np.int64(7), np.float64(0.25), np.float32(0.5))
        self.assertEqual(ops.getNodeTags(), [7])
        self.assertEqual(ops.nodeCoord(7), [0.25, 0.5])
        ops.fix(7, True, True, False)  # a bool is an integer, as OpenSeesPy takes it

    def test_unsupported_command(self):
        self.assertIn("printA", ops.__all__)
        with self.assertRaises(ops.OpenSeesError) as raised:
            ops.printA()  # the line named below
        line = sys._getframe().f_lineno - 1
        error = raised.exception
        self.assertEqual(str(error), f"printA: poundfe does not support it ({__file__}, line {line})")
        self.assertEqual((error.command, error.file, error.line), ("printA", __file__, line))
        self.assertIs(ops.OpenSeesError, poundfe._opensees.OpenSeesError)
        self.assertFalse(issubclass(ops.OpenSeesError, ValueError))  # as OpenSeesPy's: an Exception
        with self.assertRaises(AttributeError):
            ops.notAnOpenSeesCommand  # noqa: B018
        self.assertNotIn("exit", ops.__all__)  # a script's commands only

    def test_print_model_json(self):
        """printModel -JSON as OpenSeesPy's: the model's numbers as given here,
        in OpenSees's layout, read back with json (exact: shortest round-trip
        text); print -node appends OpenSees's node text to its file."""
        ops.wipe()
        ops.model('basic', '-ndm', 2, '-ndf', 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 0.3, 3.1, '-mass', 12.7, 12.7, 0.0)
        ops.fix(1, 1, 1, 1)
        ops.geomTransf('PDelta', 4)
        ops.uniaxialMaterial('Steel02', 5, 355.1, 2.1e5, 0.013, 18.5, 0.9, 0.15)
        ops.element('elasticBeamColumn', 3, 1, 2, 0.0123, 2.07e11, 2.5e-4, 4)
        ops.element('truss', 6, 1, 2, 0.0051, 5)
        with tempfile.TemporaryDirectory() as work:
            path = os.path.join(work, "model.json")
            ops.printModel('-JSON', '-file', path)
            with open(path) as f:
                model = json.load(f)["StructuralAnalysisModel"]
            ops.print('-file', os.path.join(work, "nodes.txt"), '-node', 1)
            ops.print('-file', os.path.join(work, "nodes.txt"), '-node', 1)
            with open(os.path.join(work, "nodes.txt")) as f:
                nodes = f.read()
        self.assertEqual(model["geometry"]["nodes"],
                         [{"name": 1, "ndf": 3, "crd": [0.0, 0.0]},
                          {"name": 2, "ndf": 3, "crd": [0.3, 3.1], "mass": [12.7, 12.7, 0.0]}])
        self.assertEqual(model["geometry"]["elements"],
                         [{"name": 3, "type": "ElasticBeam2d", "nodes": [1, 2], "E": 2.07e11,
                           "A": 0.0123, "Iz": 2.5e-4, "massperlength": 0, "release": 0,
                           "crdTransformation": "4"},
                          {"name": 6, "type": "Truss", "nodes": [1, 2], "A": 0.0051,
                           "massperlength": 0, "material": "5"}])
        self.assertEqual(model["properties"]["uniaxialMaterials"],
                         [{"name": "5", "type": "Steel02", "E": 2.1e5, "fy": 355.1, "b": 0.013,
                           "R0": 18.5, "cR1": 0.9, "cR2": 0.15, "a1": 0, "a2": 1, "a3": 0,
                           "a4": 1, "sigini": 0}])
        self.assertEqual(model["properties"]["crdTransformations"],
                         [{"name": "4", "type": "PDeltaCrdTransf2d"}])
        node_1 = "\n Node: 1\n\tCoordinates  : 0 0 \n\tDisps: 0 0 0 \n\tVelocities   : 0 0 0 \n\n"
        self.assertEqual(nodes, node_1 * 2)

    def test_errors_name_command_and_line(self):
        sdof()
        with self.assertRaises(ops.OpenSeesError) as raised:
            ops.node(1, 0.0)
        self.assertRegex(str(raised.exception), r"^node: node 1 exists already \(.*test_opensees\.py, line \d+\)$")
        with self.assertRaises(ops.OpenSeesError) as raised:
            ops.node(5, {"x": 1.0})
        self.assertTrue(str(raised.exception).startswith(
            "node: argument 2 is a dict, not a number, a string or a list"))
        with self.assertRaises(ops.OpenSeesError) as raised:
            ops.node(5.0, 1.0)  # a tag is an integer
        self.assertIn("expected an integer", str(raised.exception))
        ops.wipe()
        ops.model('basic', '-ndm', 1, '-ndf', 1)
        ops.node(1, 0.0)
        with self.assertRaises(ops.OpenSeesError) as raised:
            ops.load(1, 1.0)
        self.assertIn("a load needs a Plain pattern before it", str(raised.exception))

    def test_fibre_section_filled_by_later_commands(self):
        ops.wipe()
        ops.model('basic', '-ndm', 2, '-ndf', 3)
        ops.uniaxialMaterial('Elastic', 1, 2.0e8)
        ops.section('Fiber', 1)
        with self.assertRaises(ops.OpenSeesError) as raised:
            ops.node(1, 0.0, 0.0)  # the section closes here, empty
        self.assertIn("section Fiber 1 has no fibre", str(raised.exception))
        ops.section('Fiber', 2)
        ops.fiber(0.1, 0.0, 0.01, 1)
        ops.fiber(-0.1, 0.0, 0.01, 1)
        ops.beamIntegration('Lobatto', 1, 2, 3)  # section 2 exists now
        with self.assertRaises(ops.OpenSeesError) as raised:
            ops.patch('rect', 1, 1, 1, -0.1, -0.1, 0.1, 0.1)
        self.assertTrue(str(raised.exception).startswith(
            "patch: patch needs a section Fiber before it"))

    def test_fibre_section_in_3d_with_gj(self):
        # OpenSeesPy's section('Fiber', tag, '-GJ', GJ) and its patch after
        # it, on a 3D forceBeamColumn cantilever along Z (vecxz X: local z
        # is X): the tip's PL^3/3EIy with the fibres' own Iy, and TL/GJ
        ops.wipe()
        ops.model('basic', '-ndm', 3, '-ndf', 6)
        length, modulus, torsion, b, h, n_z = 2.0, 2.0e11, 3.0e7, 0.3, 0.4, 6
        ops.node(1, 0.0, 0.0, 0.0)
        ops.node(2, 0.0, 0.0, length)
        ops.fix(1, 1, 1, 1, 1, 1, 1)
        ops.uniaxialMaterial('Elastic', 1, modulus)
        ops.section('Fiber', 1, '-GJ', torsion)
        ops.patch('rect', 1, 8, n_z, -h / 2, -b / 2, h / 2, b / 2)
        ops.geomTransf('Linear', 1, 1.0, 0.0, 0.0)
        ops.beamIntegration('Lobatto', 1, 1, 5)
        ops.element('forceBeamColumn', 1, 1, 2, 1, 1)
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(2, 1.0e3, 0.0, 0.0, 0.0, 0.0, 2.0e2)
        static_analysis()
        self.assertEqual(ops.analyze(1), 0)
        inertia_y = h * b ** 3 / 12 * (1 - 1.0 / n_z ** 2)
        self.assertAlmostEqual(ops.nodeDisp(2, 1) / (1.0e3 * length ** 3 / (3 * modulus * inertia_y)),
                               1.0, delta=1e-9)
        self.assertAlmostEqual(ops.nodeDisp(2, 6) / (2.0e2 * length / torsion), 1.0, delta=1e-9)

    def test_link_and_damper_arguments(self):
        # twoNodeLink with its options and a ViscousDamper, Series: made as
        # OpenSeesPy makes them, the link's basicForce as a list
        sdof()
        ops.uniaxialMaterial('ViscousDamper', 2, 1.0e3, 50.0, 0.5)
        ops.uniaxialMaterial('Series', 3, 1, 1, '-iter', 5, 1.0e-12)
        ops.element('twoNodeLink', 2, 1, 2, '-mat', 3, '-dir', 1, '-doRayleigh')
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(2, 10.0)
        static_analysis()
        self.assertEqual(ops.analyze(1), 0)
        # the spring (100) beside the Series of two (50): 10/150
        self.assertAlmostEqual(ops.nodeDisp(2, 1), 10.0 / 150.0, delta=1e-14)
        force = ops.eleResponse(2, 'basicForce')
        self.assertIsInstance(force, list)
        self.assertAlmostEqual(force[0], 50.0 * 10.0 / 150.0, delta=1e-11)

    def test_domain_commands(self):
        """reset, reactions('-dynamic'), a Path of times and VariableTransient
        through the same command table as the Tcl scripts."""
        uniform = record_history(lambda values: (values,))
        # the same record at its times 0, 0.01, ...: the same interpolation
        # but for the round-off of i * 0.01 against t / 0.01
        def at_times(values):
            return (values, '-time', [0.01 * i for i in range(len(values))])
        at_times_history = record_history(at_times, spacing=())
        self.assertLess(max(abs(a - b) for a, b in zip(uniform, at_times_history)),
                        1e-12 * max(map(abs, uniform)))
        # the free node's dynamic reaction is its unbalance: 0 once converged
        ops.reactions('-dynamic')
        self.assertLess(abs(ops.nodeReaction(2, 1)), 1e-9 * abs(ops.nodeReaction(1, 1)))
        # reset: the record again from time 0 gives the same history exactly
        ops.reset()
        self.assertEqual((ops.getTime(), ops.nodeDisp(2, 1)), (0.0, 0.0))
        again = []
        for _ in range(50):
            ops.analyze(1, 0.01)
            again.append(ops.nodeDisp(2, 1))
        self.assertEqual(again, at_times_history)
        ops.wipeAnalysis()
        ops.analysis('VariableTransient')
        self.assertEqual(ops.analyze(5, 0.01, 0.001, 0.02, 1), 0)

    def test_zero_length_section_and_corot_truss(self):
        # zeroLengthSection with OpenSeesPy's 2D -orient (x alone: y across
        # it): x along Y takes the vertical load as P (u = F/EA) and the
        # moment as Mz (theta = M/EI)
        ops.wipe()
        ops.model('basic', '-ndm', 2, '-ndf', 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 0.0, 0.0)
        ops.fix(1, 1, 1, 1)
        ops.fix(2, 1, 0, 0)
        ops.section('Elastic', 1, 2.0e11, 0.01, 1.0e-4)
        ops.element('zeroLengthSection', 1, 1, 2, 1, '-orient', 0.0, 1.0, 0.0)
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(2, 0.0, 1.0e5, 2.0e4)
        static_analysis()
        self.assertEqual(ops.analyze(1), 0)
        self.assertAlmostEqual(ops.nodeDisp(2, 2), 1.0e5 / 2.0e9, delta=1e-18)
        self.assertAlmostEqual(ops.nodeDisp(2, 3), 2.0e4 / 2.0e7, delta=1e-16)
        self.assertEqual(len(ops.eleResponse(1, 'section', 'force')), 2)
        # corotTruss from (0, 0) to (3, 4) on a roller (node 2's Y fixed)
        # pushed along X by P: its new length L = |(3 + u, 4)| takes
        # EA (L - 5)/5 (3 + u)/L = P, large enough to turn the bar visibly
        ops.wipe()
        ops.model('basic', '-ndm', 2, '-ndf', 2)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 3.0, 4.0)
        ops.fix(1, 1, 1)
        ops.fix(2, 0, 1)
        ops.uniaxialMaterial('Elastic', 1, 2.0e11)
        ops.element('corotTruss', 1, 1, 2, 1.0e-3, 1, '-rho', 0.0, '-cMass', 1)
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(2, 2.0e7, 0.0)
        static_analysis(4)
        self.assertEqual(ops.analyze(4), 0)
        u = ops.nodeDisp(2, 1)
        length = math.hypot(3.0 + u, 4.0)
        force = 2.0e8 * (length - 5.0) / 5.0
        self.assertGreater(u, 0.5)
        self.assertAlmostEqual(force * (3.0 + u) / length / 2.0e7, 1.0, delta=1e-12)
        self.assertAlmostEqual(ops.eleResponse(1, 'deformation')[0], length - 5.0, delta=1e-14)
        self.assertAlmostEqual(ops.eleResponse(1, 'axialForce')[0] / force, 1.0, delta=1e-12)

    def test_modal_damping_of_one_mode_is_mass_proportional(self):
        # one mode (k 400, m 1: omega 20): modalDamping 0.05 gives
        # C = 2 zeta omega m = 2.0, the same as rayleigh 2.0 0 0 0
        def history(damping):
            sdof(k=400.0)
            ops.eigen('-fullGenLapack', 1)
            damping()
            values = [math.sin(0.3 * i) for i in range(101)]
            ops.timeSeries('Path', 1, '-dt', 0.01, '-values', *values)
            ops.pattern('UniformExcitation', 1, 1, '-accel', 1)
            ops.constraints('Plain')
            ops.numberer('Plain')
            ops.system('BandGeneral')
            ops.test('NormDispIncr', 1.0e-12, 10)
            ops.algorithm('Newton')
            ops.integrator('Newmark', 0.5, 0.25)
            ops.analysis('Transient')
            result = []
            for _ in range(100):
                self.assertEqual(ops.analyze(1, 0.01), 0)
                result.append(ops.nodeDisp(2, 1))
            return result
        modal = history(lambda: ops.modalDamping(0.05))
        rayleigh = history(lambda: ops.rayleigh(2.0, 0.0, 0.0, 0.0))
        undamped = history(lambda: None)
        peak = max(abs(x) for x in rayleigh)
        self.assertLess(max(abs(a - b) for a, b in zip(modal, rayleigh)), 1e-13 * peak)
        self.assertGreater(max(abs(a - b) for a, b in zip(undamped, rayleigh)), 0.01 * peak)

    def test_rigid_link_beam_and_consistent_mass(self):
        # a cantilever column (L up Y) whose top carries, by rigidLink beam,
        # node 3 at offset a along X; -V at node 3 reaches the top as -V
        # and the moment -V a: theta = -V a L/EI, the top's
        # u = V a L^2/(2 EI), and node 3's v = -V L/EA + a theta
        E, A, I, L, a, V = 2.0e11, 0.01, 1.0e-4, 3.0, 0.8, 1.0e5
        ops.wipe()
        ops.model('basic', '-ndm', 2, '-ndf', 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 0.0, L)
        ops.node(3, a, L)
        ops.fix(1, 1, 1, 1)
        ops.geomTransf('Linear', 1)
        ops.element('elasticBeamColumn', 1, 1, 2, A, E, I, 1, '-mass', 50.0, '-cMass')
        ops.rigidLink('beam', 2, 3)
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(3, 0.0, -V, 0.0)
        static_analysis()
        ops.constraints('Transformation')
        ops.analysis('Static')
        self.assertEqual(ops.analyze(1), 0)
        theta = -V * a * L / (E * I)
        self.assertAlmostEqual(ops.nodeDisp(2, 3) / theta, 1.0, delta=1e-12)
        self.assertAlmostEqual(ops.nodeDisp(2, 1) / (V * a * L**2 / (2 * E * I)), 1.0, delta=1e-12)
        v = -V * L / (E * A) + a * theta
        self.assertAlmostEqual(ops.nodeDisp(3, 2) / v, 1.0, delta=1e-12)
        self.assertEqual(ops.nodeDisp(3, 3), ops.nodeDisp(2, 3))
        # the column's consistent mass alone: its first eigenvalue is the
        # least of the one-element cantilever's bending pair K phi =
        # lambda M phi, K = EI/L^3 [12 -6L; -6L 4L^2], M = m L/420 [156
        # -22L; -22L 4L^2] (the sway and the rotation of the top)
        stiffness = E * I / L**3 * np.array([[12.0, -6 * L], [-6 * L, 4 * L * L]])
        mass = 50.0 * L / 420.0 * np.array([[156.0, -22 * L], [-22 * L, 4 * L * L]])
        expected = min(np.linalg.eigvals(np.linalg.solve(mass, stiffness)).real)
        self.assertAlmostEqual(ops.eigen('-fullGenLapack', 1)[0] / expected, 1.0, delta=1e-10)

    def test_wipe_between_two_models(self):
        recorded = os.path.join(self.tmp, "first.out")
        sdof(k=100.0)
        ops.recorder('Node', '-file', recorded, '-time', '-node', 2, '-dof', 1, 'disp')
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(2, 10.0)
        static_analysis()
        self.assertEqual(ops.analyze(1), 0)
        first = ops.nodeDisp(2, 1)
        ops.wipe()  # the recorder's file written, the domain empty
        with open(recorded) as f:
            self.assertEqual([float(v) for v in f.read().split()], [1.0, first])
        self.assertEqual((ops.getNodeTags(), ops.getEleTags(), ops.getTime()), ([], [], 0.0))
        sdof(k=400.0)  # the same tags again
        ops.timeSeries('Linear', 1)
        ops.pattern('Plain', 1, 1)
        ops.load(2, 10.0)
        static_analysis()
        self.assertEqual(ops.analyze(1), 0)
        self.assertAlmostEqual(first, 0.1, delta=1e-15)
        self.assertAlmostEqual(ops.nodeDisp(2, 1), 0.025, delta=1e-15)
