"""pounding_sticks.tcl in OpenSeesPy's form: two single-storey sticks
(T = 0.5 s and 1.0 s, 5 % damping in their own springs) 10 mm apart,
pounding through a zero-length gap (ElasticPPGap or ImpactMaterial) under
the synthetic record.
    python3 pounding_sticks.py OUTPUT_DIR ElasticPPGap|ImpactMaterial
Only the import line differs from an OpenSeesPy script."""
import math
import sys

import poundfe.opensees as ops

from record import synthetic_record


def run(out, law, keep=False, locate=0):
    """The recorders' files in `out`; analyze's status and the final time.
    keep: the gap's stress recorded too, poundfe's energy balance and
    impact log on, and the domain left for the caller's queries (its
    `wipe` writes the files). locate: poundfe::locateEvents on with that
    many halvings (0: off)."""
    ops.wipe()
    ops.model('basic', '-ndm', 1, '-ndf', 1)
    pi = 3.14159265358979
    m = 1.0e5
    ops.node(1, 0.0)
    ops.node(2, 0.0, '-mass', m)
    ops.node(3, 0.0)
    ops.node(4, 0.0, '-mass', m)
    ops.fix(1, 1)
    ops.fix(3, 1)
    k2 = m * math.pow(2 * pi / 0.5, 2)
    k4 = m * math.pow(2 * pi / 1.0, 2)
    ops.uniaxialMaterial('Elastic', 1, k2, 0.05 * 2 * math.sqrt(k2 * m))
    ops.uniaxialMaterial('Elastic', 2, k4, 0.05 * 2 * math.sqrt(k4 * m))
    ops.element('zeroLength', 1, 1, 2, '-mat', 1, '-dir', 1)
    ops.element('zeroLength', 2, 3, 4, '-mat', 2, '-dir', 1)
    # the gap closes when node 2 moves 10 mm more than node 4 (u4 - u2 < -0.01)
    if law == 'ElasticPPGap':
        ops.uniaxialMaterial('ElasticPPGap', 3, 2.0e9, -4.0e6, -0.01, 0.1, 'damage')
    else:
        ops.uniaxialMaterial('ImpactMaterial', 3, 2.0e9, 6.0e8, -0.002, -0.01)
    ops.element('zeroLength', 3, 2, 4, '-mat', 3, '-dir', 1)
    dt, n = 0.002, 4000
    ops.timeSeries('Path', 1, '-dt', dt, '-values', synthetic_record(dt, n, 0.6))
    ops.pattern('UniformExcitation', 1, 1, '-accel', 1)
    ops.recorder('Node', '-file', f'{out}/pounding_{law}.out', '-time', '-precision', 16,
                 '-node', 2, 4, '-dof', 1, 'disp')
    ops.recorder('Node', '-file', f'{out}/pounding_{law}_vel.out', '-time', '-precision', 16,
                 '-node', 2, 4, '-dof', 1, 'vel')
    if keep:
        ops.recorder('Element', '-file', f'{out}/pounding_{law}_gap.out', '-time', '-precision',
                     16, '-ele', 3, 'material', 1, 'stress')
        ops.poundfe.energy('on')
        ops.poundfe.impacts('on')
    ops.constraints('Plain')
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-10, 50)
    ops.algorithm('Newton')
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    if locate:
        ops.poundfe.locateEvents('on', locate)
    status = ops.analyze(n, dt)
    time = ops.getTime()
    if not keep:
        ops.wipe()
    return status, time


if __name__ == '__main__':
    print(run(sys.argv[1], sys.argv[2]))
