"""arc_length_arch.tcl in OpenSeesPy's form: a shallow two-member arch of
corotational elastic beams followed past its limit point by ArcLength.
    python3 arc_length_arch.py OUTPUT_DIR <s alpha steps <handler words>>
Only the import line differs from an OpenSeesPy script."""
import sys

import poundfe.opensees as ops


def run(out, s=0.01, alpha=0.0005, steps=45, *handler):
    """The recorders' files in `out`; analyze's value and the load factor."""
    ops.wipe()
    ops.model('basic', '-ndm', 2, '-ndf', 3)
    ops.node(1, 0.0, 0.0)
    ops.node(2, 1.0, 0.1)
    ops.node(3, 2.0, 0.0)
    ops.fix(1, 1, 1, 0)
    ops.fix(3, 1, 1, 0)
    ops.geomTransf('Corotational', 1)
    ops.element('elasticBeamColumn', 1, 1, 2, 1.0, 200000.0, 1.0e-4, 1)
    ops.element('elasticBeamColumn', 2, 2, 3, 1.0, 200000.0, 1.0e-4, 1)
    ops.timeSeries('Linear', 1)
    ops.pattern('Plain', 1, 1)
    ops.load(2, 0.0, -1.0, 0.0)
    ops.recorder('Node', '-file', f'{out}/apex.out', '-time', '-precision', 16,
                 '-node', 2, '-dof', 2, 'disp')
    ops.recorder('Node', '-file', f'{out}/support.out', '-time', '-precision', 16,
                 '-node', 1, '-dof', 1, 2, 'reaction')
    ops.constraints(*(handler or ('Plain',)))
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 30)
    ops.algorithm('Newton')
    ops.integrator('ArcLength', float(s), float(alpha))
    ops.analysis('Static')
    ok = ops.analyze(int(steps))
    lam = ops.getTime()
    ops.wipe()
    return ok, lam


if __name__ == "__main__":
    print(run(*sys.argv[1:]))
