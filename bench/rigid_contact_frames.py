#!/usr/bin/python3
"""Rigid contact at ten times the penalty's step on frames with hinges (doc/benchmarks.md,
"Rigid contact at ten times the penalty's step"): an input with frames (massless rotations,
Bouc-Wen hinges), by default the default example input/two-buildings.prm, run
  - with its penalty law (Contact section as written; Steps per contact = 0 and Event
    refinement = 0, so the step is the one given) at the steps PENALTY_STEPS: the converged
    step h_p is the largest whose peak drifts, and those of every finer step, lie within 1 %
    of the finest penalty run's;
  - with Contact/Model = nonsmooth (e = the input's Coefficient of restitution, theta =
    1/2) at 10 h_p, h_p and h_p / 10.
Also run: the buildings 1 m apart (no contact) with Newmark at 10 h_p and at the finest
penalty step, the error the frames and the record leave at 10 h_p to any contact model.
Printed: every storey's peak drift ratio per run, steps, wall time and the cost per step,
the largest relative difference of the nonsmooth run at 10 h_p from the finer nonsmooth
runs and from the converged penalty run; with --callgrind, the instructions per step of
the penalty at h_p and the nonsmooth at h_p (valgrind --tool=callgrind, the difference of
two runs ending CALLGRIND_ENDS apart over their difference in steps: the set-up cancels).

Every run factors with Linear solver = eigen-ldlt (the same sparse factor for both models
on large inputs such as input/city-block.prm, where the rigid stepper's J is sparse). A run
that fails (exit 2) is reported and left out of the comparisons.

  bench/rigid_contact_frames.py [INPUT] [--callgrind]
  POUNDFE (binary, default build/poundfe), WORK (default /tmp/rigid_contact_frames),
  PENALTY_STEPS (default 1e-3,5e-4,2.5e-4,1.25e-4), NONSMOOTH_FACTORS (the nonsmooth runs'
  steps over h_p, default 10,1,0.1), END (End time, default: the input's), CALLGRIND_ENDS
  (default 2,3),
  STIFFNESS (Contact/Stiffness of the penalty law, default: the input's), SAMPLE (a generated
  motion's Sample interval, default 0.01 s: its white noise is otherwise drawn at the time
  step, a different record at each step)"""
import json, os, re, subprocess, sys

BIN = os.environ.get('POUNDFE', 'build/poundfe')
WORK = os.environ.get('WORK', '/tmp/rigid_contact_frames')
args = [a for a in sys.argv[1:] if not a.startswith('--')]
INPUT = args[0] if args else 'input/two-buildings.prm'
CALLGRIND = '--callgrind' in sys.argv
BASE = open(INPUT).read()
PENALTY_STEPS = [float(h) for h in os.environ.get(
    'PENALTY_STEPS', '1e-3,5e-4,2.5e-4,1.25e-4').split(',')]
END = os.environ.get('END')
STIFFNESS = os.environ.get('STIFFNESS')
SAMPLE = os.environ.get('SAMPLE', '0.01')
NONSMOOTH_FACTORS = [float(f) for f in os.environ.get('NONSMOOTH_FACTORS', '10,1,0.1').split(',')]
CALLGRIND_ENDS = tuple(float(t) for t in os.environ.get('CALLGRIND_ENDS', '2,3').split(','))


def set_in(text, section, name, value):
    """`set name = value` in `subsection section`, replacing it or added at its start."""
    pattern = rf'(subsection {section}\n(?:(?!end\n)[^\n]*\n)*?) *set {name} *=[^\n]*\n'
    if re.search(pattern, text):
        return re.sub(pattern, rf'\g<1>  set {name} = {value}\n', text, count=1)
    if f'subsection {section}\n' not in text:
        return text + f'subsection {section}\n  set {name} = {value}\nend\n'
    return text.replace(f'subsection {section}\n', f'subsection {section}\n  set {name} = {value}\n', 1)


def prm(name, h, nonsmooth, end=None, apart=False):
    text = set_in(BASE, 'Time integration', 'Time step', h)
    if apart:  # the buildings 1 m apart: the structure alone, no contact
        text = set_in(text, 'Model', 'Separations', 1.0)
    if 'subsection Stochastic\n' in text:  # the same record at every step
        text = set_in(text, 'Stochastic', 'Sample interval', SAMPLE)
    text = set_in(text, 'Contact', 'Steps per contact', 0)
    text = set_in(text, 'Contact', 'Event refinement', 0)
    if STIFFNESS:
        text = set_in(text, 'Contact', 'Stiffness', STIFFNESS)
    if end or END:
        text = set_in(text, 'Time integration', 'End time', end or END)
    text = set_in(text, 'Time integration', 'Linear solver', 'eigen-ldlt')
    if nonsmooth:
        text = set_in(text, 'Contact', 'Model', 'nonsmooth')
    for setting in ('Plots = false', 'VTU interval = 0', 'Number of modes = 0'):
        text = set_in(text, 'Output', *setting.split(' = '))
    os.makedirs(WORK, exist_ok=True)
    path = os.path.join(WORK, name + '.prm')
    open(path, 'w').write(text)
    return path


def run(name, h, nonsmooth, apart=False):
    out = os.path.join(WORK, name)
    r = subprocess.run([BIN, 'run', prm(name, h, nonsmooth, apart=apart), '--output', out],
                       capture_output=True, text=True)
    if r.returncode == 2:  # a numerical failure: reported, left out
        print(f"{name}: failed: {r.stderr.strip().splitlines()[-1]}")
        return None
    r.check_returncode()
    s = json.load(open(os.path.join(out, 'summary.json')))
    drifts = [st['peak_drift_ratio'] for b in s['buildings'] for st in b['storeys']]
    a = s['analysis']
    return drifts, a['steps'], a['wall_time_s']


def instructions_per_step(name, h, nonsmooth):
    counts = []
    for end in CALLGRIND_ENDS:
        path = prm(f'{name}-cg{end:g}', h, nonsmooth, end)
        out = os.path.join(WORK, f'{name}-cg{end:g}')
        r = subprocess.run(['valgrind', '--tool=callgrind', f'--callgrind-out-file={out}.cg',
                            BIN, 'run', path, '--output', out], check=True, capture_output=True,
                           text=True)
        ir = int(re.search(r'Collected : (\d+)', r.stderr).group(1))
        steps = json.load(open(os.path.join(out, 'summary.json')))['analysis']['steps']
        counts.append((ir, steps))
    return (counts[1][0] - counts[0][0]) / (counts[1][1] - counts[0][1])


def worst(a, b):
    return max(abs(x / y - 1) for x, y in zip(a, b) if y != 0)


def row(name, result):
    if result is None:
        return
    d, n, wall = result
    peaks = ' '.join(f'{x:.5f}' for x in d) if len(d) <= 8 else \
        f'{len(d)} storeys, largest {max(d):.5f}'
    print(f"{name:20} {n:8d} {wall:8.3f} {1e6 * wall / n:8.2f}  " + peaks)


print(f"{INPUT}; load average {os.getloadavg()[0]:.2f} at the start")
print(f"{'run':20} {'steps':>8} {'wall s':>8} {'us/step':>8}  peak drift ratios")
penalty = {h: run(f'penalty-{h:g}', h, False) for h in PENALTY_STEPS}
for h, r in penalty.items():
    row(f'penalty {h:g}', r)
finest = penalty[min(PENALTY_STEPS)][0]
# the largest step from which every finer step stays within 1 % of the finest run
h_p = min(PENALTY_STEPS)
for h in sorted(PENALTY_STEPS)[1:]:
    if worst(penalty[h][0], finest) > 0.01:
        break
    h_p = h
print(f"penalty's converged step h_p = {h_p:g} s (peaks within 1 % of the run at "
      f"{min(PENALTY_STEPS):g} s: {worst(penalty[h_p][0], finest):.4f})")
# the structure alone (Newmark, no contact) at 10 h_p against its finest step: what the
# frames and the record's sampling leave to any contact model at 10 h_p
apart_fine = run(f'apart-{min(PENALTY_STEPS):g}', min(PENALTY_STEPS), False, apart=True)
apart_coarse = run(f'apart-{10 * h_p:g}', 10 * h_p, False, apart=True)
row(f'apart {min(PENALTY_STEPS):g}', apart_fine)
row(f'apart {10 * h_p:g}', apart_coarse)
print(f"no contact (1 m apart), Newmark at {10 * h_p:g} against {min(PENALTY_STEPS):g}: largest "
      f"drift difference {worst(apart_coarse[0], apart_fine[0]):.4f}")
rigid = {}
for factor in NONSMOOTH_FACTORS:
    h = h_p * factor
    rigid[factor] = run(f'nonsmooth-{h:g}', h, True)
    row(f'nonsmooth {h:g}', rigid[factor])
rigid = {f: r for f, r in rigid.items() if r is not None}
coarsest = max(rigid) if rigid else None
if coarsest is not None:
    coarse = rigid[coarsest][0]
    for factor in sorted(rigid)[:-1]:
        print(f"nonsmooth {coarsest * h_p:g} against nonsmooth {h_p * factor:g}: largest drift "
              f"difference {worst(coarse, rigid[factor][0]):.4f}")
    print(f"nonsmooth {coarsest * h_p:g} against penalty {h_p:g}: largest drift difference "
          f"{worst(coarse, penalty[h_p][0]):.4f}")
    print(f"whole run (wall), nonsmooth at {coarsest * h_p:g} s / penalty at {h_p:g} s: "
          f"{rigid[coarsest][2] / penalty[h_p][2]:.2f}")
if 1 in rigid:
    p, r = penalty[h_p], rigid[1]
    print(f"cost per step (wall), nonsmooth / penalty at {h_p:g} s: "
          f"{(r[2] / r[1]) / (p[2] / p[1]):.2f}")
if CALLGRIND:
    ip = instructions_per_step('penalty', h_p, False)
    ir = instructions_per_step('nonsmooth', h_p, True)
    print(f"instructions per step (callgrind, steps between t = {CALLGRIND_ENDS[0]:g} and "
          f"{CALLGRIND_ENDS[1]:g} s at {h_p:g} s): penalty {ip:.0f}, nonsmooth {ir:.0f}, "
          f"ratio {ir / ip:.2f}")
