"""fibre_frame_record.tcl in OpenSeesPy's form (committed-stiffness
damping, Newton, Newmark): a two-storey, one-bay RC frame of fibre
forceBeamColumns, gravity by LoadControl in 10 steps, loadConst -time 0,
then 6 s of the synthetic record scaled by 1.5.
    python3 fibre_frame_record.py OUTPUT_DIR
Only the import line differs from an OpenSeesPy script; the fibre section
and the gravity pattern are filled by the commands after them, as
OpenSeesPy has no script bodies."""
import sys

import poundfe.opensees as ops

from record import synthetic_record


def rc_materials():
    ops.uniaxialMaterial('Concrete01', 1, -30.0e3, -0.002, -6.0e3, -0.005)
    ops.uniaxialMaterial('Concrete01', 2, -39.0e3, -0.0026, -32.0e3, -0.02)
    ops.uniaxialMaterial('Steel02', 3, 450.0e3, 2.0e8, 0.01, 18.0, 0.925, 0.15)


def rc_section(tag, b, h, cover, nbars, area):
    """rc_section.tcl's rectangle: cover 1, core 2, bars 3."""
    y1, z1 = h / 2.0, b / 2.0
    yc, zc = y1 - cover, z1 - cover
    ops.section('Fiber', tag)
    ops.patch('rect', 2, 10, 1, -yc, -zc, yc, zc)
    ops.patch('rect', 1, 10, 1, -y1, zc, y1, z1)
    ops.patch('rect', 1, 10, 1, -y1, -z1, y1, -zc)
    ops.patch('rect', 1, 2, 1, -y1, -zc, -yc, zc)
    ops.patch('rect', 1, 2, 1, yc, -zc, y1, zc)
    ops.layer('straight', 3, nbars, area, yc, zc, yc, -zc)
    ops.layer('straight', 3, nbars, area, -yc, zc, -yc, -zc)
    ops.layer('straight', 3, 2, area, 0.0, zc, 0.0, -zc)


def run(out):
    """The recorders' files in `out`; analyze's status and the roof's
    final displacement."""
    ops.wipe()
    ops.model('basic', '-ndm', 2, '-ndf', 3)
    W, H = 6.0, 3.0
    ops.node(1, 0.0, 0.0)
    ops.node(2, W, 0.0)
    ops.node(3, 0.0, H, '-mass', 30.0, 30.0, 0.0)
    ops.node(4, W, H, '-mass', 30.0, 30.0, 0.0)
    ops.node(5, 0.0, 2 * H, '-mass', 25.0, 25.0, 0.0)
    ops.node(6, W, 2 * H, '-mass', 25.0, 25.0, 0.0)
    ops.fix(1, 1, 1, 1)
    ops.fix(2, 1, 1, 1)
    rc_materials()
    rc_section(1, 0.4, 0.4, 0.04, 3, 3.14e-4)
    rc_section(2, 0.3, 0.5, 0.04, 3, 2.01e-4)
    ops.geomTransf('PDelta', 1)
    ops.geomTransf('Linear', 2)
    ops.beamIntegration('Lobatto', 1, 1, 5)
    ops.beamIntegration('Lobatto', 2, 2, 5)
    for tag, i, j, transf, integration in [(1, 1, 3, 1, 1), (2, 2, 4, 1, 1), (3, 3, 5, 1, 1),
                                           (4, 4, 6, 1, 1), (5, 3, 4, 2, 2), (6, 5, 6, 2, 2)]:
        ops.element('forceBeamColumn', tag, i, j, transf, integration)
    ops.recorder('Node', '-file', f'{out}/frame_disp.out', '-time', '-precision', 12,
                 '-node', 3, 5, '-dof', 1, 2, 3, 'disp')
    ops.recorder('Node', '-file', f'{out}/frame_base.out', '-time', '-precision', 12,
                 '-node', 1, 2, '-dof', 1, 2, 3, 'reaction')
    ops.recorder('Element', '-file', f'{out}/frame_section.out', '-time', '-precision', 12,
                 '-ele', 1, 2, 'section', 1, 'force')
    ops.recorder('Element', '-file', f'{out}/frame_beam.out', '-time', '-precision', 12,
                 '-ele', 5, 'localForce')
    ops.timeSeries('Linear', 1)
    ops.pattern('Plain', 1, 1)
    ops.load(3, 0.0, -300.0, 0.0)
    ops.load(4, 0.0, -300.0, 0.0)
    ops.load(5, 0.0, -250.0, 0.0)
    ops.load(6, 0.0, -250.0, 0.0)
    ops.constraints('Plain')
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 50)
    ops.algorithm('Newton')
    ops.integrator('LoadControl', 0.1)
    ops.analysis('Static')
    ops.analyze(10)
    ops.loadConst('-time', 0.0)
    ops.wipeAnalysis()
    w1, w2, zeta = 6.9, 22.0, 0.05
    a0, a1 = 2 * zeta * w1 * w2 / (w1 + w2), 2 * zeta / (w1 + w2)
    ops.rayleigh(a0, 0.0, 0.0, a1)
    ops.timeSeries('Path', 2, '-dt', 0.01, '-values', synthetic_record(0.01, 600, 1.5))
    ops.pattern('UniformExcitation', 2, 1, '-accel', 2)
    ops.constraints('Plain')
    ops.numberer('Plain')
    ops.system('BandGeneral')
    ops.test('NormDispIncr', 1.0e-12, 50)
    ops.algorithm('Newton')
    ops.integrator('Newmark', 0.5, 0.25)
    ops.analysis('Transient')
    status = ops.analyze(600, 0.01)
    roof = ops.nodeDisp(5, 1)
    ops.wipe()
    return status, roof


if __name__ == '__main__':
    print(run(sys.argv[1]))
