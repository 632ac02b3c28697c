"""portal_frame.tcl in OpenSeesPy's form: a 2D elastic portal frame (6 m
bay, 3 m columns), gravity in ten LoadControl steps, loadConst, then the
synthetic record with Rayleigh damping (Newton, NormDispIncr).
    python3 portal_frame.py OUTPUT_DIR
Only the import line differs from an OpenSeesPy script."""
import math
import sys

import poundfe.opensees as ops

from record import synthetic_record


def run(out):
    """The recorders' files in `out`; the two eigenvalues."""
    ops.wipe()
    ops.model('basic', '-ndm', 2, '-ndf', 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 6.0, 0.0)
    ops.node(3, 0.0, 3.0, '-mass', 2.0e4, 2.0e4, 0.0)
    ops.node(4, 6.0, 3.0, '-mass', 2.0e4, 2.0e4, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    ops.geomTransf('Linear', 1)
    E = 2.0e11
    ops.element('elasticBeamColumn', 1, 1, 3, 0.01, E, 2.0e-4, 1)
    ops.element('elasticBeamColumn', 2, 2, 4, 0.01, E, 2.0e-4, 1)
    ops.element('elasticBeamColumn', 3, 3, 4, 0.012, E, 4.0e-4, 1)
    ops.timeSeries('Linear', 1)
    ops.pattern('Plain', 1, 1)
    ops.load(3, 0.0, -1.962e5, 0.0)
    ops.load(4, 0.0, -1.962e5, 0.0)
    ops.recorder('Node', '-file', f'{out}/portal_disp.out', '-time', '-precision', 16,
                 '-node', 3, 4, '-dof', 1, 2, 3, 'disp')
    ops.recorder('Node', '-file', f'{out}/portal_base.out', '-time', '-precision', 16,
                 '-node', 1, 2, '-dof', 1, 2, 3, 'reaction')
    ops.constraints('Plain')
    ops.numberer('RCM')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 10)
    ops.algorithm('Newton')
    ops.integrator('LoadControl', 0.1)
    ops.analysis('Static')
    ops.analyze(10)
    ops.loadConst('-time', 0.0)
    eigenvalues = ops.eigen(2)
    w1, w2 = math.sqrt(eigenvalues[0]), math.sqrt(eigenvalues[1])
    xi = 0.02
    ops.rayleigh(2 * xi * w1 * w2 / (w1 + w2), 0.0, 2 * xi / (w1 + w2), 0.0)
    dt, n = 0.01, 800
    ops.timeSeries('Path', 2, '-dt', dt, '-values', *synthetic_record(dt, n))
    ops.pattern('UniformExcitation', 2, 1, '-accel', 2)
    ops.wipeAnalysis()
    ops.constraints('Plain')
    ops.numberer('RCM')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 10)
    ops.algorithm('Newton')
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    ops.analyze(n, dt)
    ops.wipe()  # the recorders' files written
    return eigenvalues


if __name__ == '__main__':
    print(run(sys.argv[1]))
