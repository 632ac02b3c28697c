#!/usr/bin/python3
"""Rigid contact at a coarse step (doc/benchmarks.md, "Rigid contact at ten times the
penalty's step"): input/shear-pair-pounding.prm (a 3- and a 2-storey shear building 1 cm
apart, 10 s of Kanai-Tajimi motion) run
  - with its linear penalty law (Kn = 5e8 N/m) at h = 1e-4 s, Steps per contact = 0
    (an impact of pi sqrt(m_eff / Kn) = 3.1 ms spans 31 steps: the step the law needs);
  - with Contact/Model = nonsmooth (e = 0.65) at 1e-3 s (ten times it), 1e-4 and 1e-5 s.
Printed: every storey's peak drift ratio, the largest relative difference of the coarse
nonsmooth run from the fine ones and from the penalty run, steps, wall time and the cost
per step (wall time / steps).

  bench/rigid_contact_step.py        # POUNDFE (binary, default build/poundfe), WORK (/tmp)"""
import json, os, re, subprocess, sys

BIN = os.environ.get('POUNDFE', 'build/poundfe')
WORK = os.environ.get('WORK', '/tmp/rigid_contact_step')
BASE = open('input/shear-pair-pounding.prm').read()


def variant(name, h, nonsmooth):
    text = re.sub(r'(set Time step *=).*', rf'\g<1> {h}', BASE)
    text = re.sub(r'(set Steps per contact *=).*', r'\g<1> 0', text)
    if nonsmooth:
        text = text.replace('subsection Contact\n', 'subsection Contact\n  set Model = nonsmooth\n'
                            '  set Coefficient of restitution = 0.65\n', 1)
    text = text.replace('subsection Output\n', 'subsection Output\n  set Plots = false\n', 1)
    os.makedirs(WORK, exist_ok=True)
    path = os.path.join(WORK, name + '.prm')
    open(path, 'w').write(text)
    out = os.path.join(WORK, name)
    subprocess.run([BIN, 'run', path, '--output', out], check=True, capture_output=True)
    s = json.load(open(os.path.join(out, 'summary.json')))
    drifts = [st['peak_drift_ratio'] for b in s['buildings'] for st in b['storeys']]
    a = s['analysis']
    return drifts, a['steps'], a['wall_time_s'], s


def worst(a, b):
    return max(abs(x / y - 1) for x, y in zip(a, b))


runs = {'penalty 1e-4': variant('penalty-1e-4', 1e-4, False)}
for h in ('1e-3', '1e-4', '1e-5'):
    runs['nonsmooth ' + h] = variant('nonsmooth-' + h, float(h), True)
print(f"{'run':16} {'steps':>7} {'wall s':>7} {'us/step':>8}  peak drift ratios")
for name, (d, n, wall, _) in runs.items():
    print(f"{name:16} {n:7d} {wall:7.3f} {1e6 * wall / n:8.2f}  " + ' '.join(f'{x:.5f}' for x in d))
coarse = runs['nonsmooth 1e-3'][0]
for ref in ('nonsmooth 1e-4', 'nonsmooth 1e-5', 'penalty 1e-4'):
    print(f"nonsmooth 1e-3 against {ref}: largest drift difference {worst(coarse, runs[ref][0]):.4f}")
p, r = runs['penalty 1e-4'], runs['nonsmooth 1e-4']
print(f"cost per step, nonsmooth / penalty at 1e-4 s: {(r[2] / r[1]) / (p[2] / p[1]):.2f}")
