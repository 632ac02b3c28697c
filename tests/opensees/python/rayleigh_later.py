"""rayleigh_later.tcl in OpenSeesPy's form: an elastic portal under the
synthetic record with `rayleigh` given before a gable is made (its node and
member undamped), then a beam and a cantilever arm with its tip node removed
and made again (undamped), a region's factors on the gable, and (2d) a truss
with a consistent mass on moved nodes.
    python3 rayleigh_later.py OUTPUT_DIR 2d|3d
Only the import line differs from an OpenSeesPy script."""
import sys

import poundfe.opensees as ops

from record import synthetic_record


def frame(variant):
    """The model's nodes and transformations; the column's, beam's, apex's
    and tip's arguments and the recorded DOFs."""
    if variant == "2d":
        ops.model('basic', '-ndm', 2, '-ndf', 3)
        ops.node(1, 0.0, 0.0)
        ops.node(2, 6.0, 0.0)
        ops.node(3, 0.0, 4.0, '-mass', 2.0e4, 2.0e4, 0.0)
        ops.node(4, 6.0, 4.0, '-mass', 2.0e4, 2.0e4, 0.0)
        ops.fix(1, 1, 1, 1)
        ops.fix(2, 1, 1, 1)
        ops.geomTransf('Linear', 1)
        return ([0.06, 2.1e11, 4.5e-4, 1], [0.02, 2.1e11, 4.0e-4, 1, '-mass', 300.0],
                [3.0, 7.0, '-mass', 5.0e3, 5.0e3, 10.0],
                [7.5, 4.0, '-mass', 4.0e3, 4.0e3, 5.0], [1, 2, 3])
    ops.model('basic', '-ndm', 3, '-ndf', 6)
    ops.node(1, 0.0, 0.0, 0.0)
    ops.node(2, 6.0, 0.0, 0.0)
    ops.node(3, 0.0, 0.0, 4.0, '-mass', 2.0e4, 2.0e4, 2.0e4, 0.0, 0.0, 0.0)
    ops.node(4, 6.0, 0.0, 4.0, '-mass', 2.0e4, 2.0e4, 2.0e4, 0.0, 0.0, 0.0)
    ops.fix(1, 1, 1, 1, 1, 1, 1)
    ops.fix(2, 1, 1, 1, 1, 1, 1)
    ops.geomTransf('Linear', 1, 0, -1, 0)
    ops.geomTransf('Linear', 2, 1, 0, 0)
    return ([0.06, 2.1e11, 8.1e10, 5.0e-4, 4.5e-4, 3.0e-4, 2],
            [0.02, 2.1e11, 8.1e10, 5.0e-4, 3.0e-4, 4.0e-4, 1, '-mass', 300.0],
            [3.0, 0.5, 7.0, '-mass', 5.0e3, 5.0e3, 5.0e3, 10.0, 10.0, 10.0],
            [7.5, 0.0, 4.0, '-mass', 4.0e3, 4.0e3, 4.0e3, 5.0, 5.0, 5.0], [1, 2, 3, 4, 5, 6])


def run(out, variant):
    """The recorders' files in `out`."""
    ops.wipe()
    column, beam, apex, tip, dofs = frame(variant)
    ops.element('elasticBeamColumn', 1, 1, 3, *column)
    ops.element('elasticBeamColumn', 2, 2, 4, *column)
    ops.element('elasticBeamColumn', 3, 3, 4, *beam)
    ops.node(6, *tip)
    ops.element('elasticBeamColumn', 6, 4, 6, *beam)
    ops.timeSeries('Path', 1, '-dt', 0.01, '-values', *synthetic_record(0.01, 300, 0.6),
                   '-factor', 9.81)
    ops.pattern('UniformExcitation', 1, 1, '-accel', 1)
    if variant == "3d":
        ops.timeSeries('Path', 2, '-dt', 0.01, '-values', *synthetic_record(0.01, 300, 0.25),
                       '-factor', 9.81)
        ops.pattern('UniformExcitation', 2, 2, '-accel', 2)
    ops.rayleigh(0.4, 0.002, 0.0, 0.0)
    ops.node(5, *apex)
    ops.element('elasticBeamColumn', 4, 3, 5, *beam)
    ops.recorder('Node', '-file', f'{out}/disp.out', '-time', '-precision', 16,
                 '-node', 3, 4, 5, '-dof', *dofs, 'disp')
    ops.constraints('Plain')
    ops.numberer('RCM')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-10, 25)
    ops.algorithm('Newton')
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    ops.analyze(80, 0.01)
    ops.remove('element', 3)
    ops.element('elasticBeamColumn', 3, 3, 4, *beam)
    ops.remove('element', 6)
    ops.remove('node', 6)
    ops.node(6, *tip)
    ops.element('elasticBeamColumn', 6, 4, 6, *beam)
    ops.region(1, '-ele', 4, '-rayleigh', 0.3, 0.003, 0.0, 0.0)
    if variant == "2d":
        ops.uniaxialMaterial('Elastic', 1, 2.1e11)
        ops.element('truss', 5, 4, 5, 5.0e-4, 1, '-rho', 400.0, '-cMass', 1, '-doRayleigh', 1)
    ops.recorder('Node', '-file', f'{out}/tip.out', '-time', '-precision', 16,
                 '-node', 6, '-dof', *dofs, 'disp')
    ops.recorder('Element', '-file', f'{out}/force.out', '-time', '-precision', 16,
                 '-ele', 3, 4, 6, 'force')
    ops.analyze(120, 0.01)
    ops.wipe()


if __name__ == "__main__":
    run(sys.argv[1], sys.argv[2])
