#!/usr/bin/python3
"""Coarse steps (issue 23 item 5; doc/benchmarks.md): step cuts, the most Newton
iterations in a step and the worst relative peak error against the Delta t = 1e-4 s run
(drift ratio and absolute acceleration of every storey, each gap's peak force) of four
shear pairs with Jankowski gaps under El Centro 180 deg scaled to 0.5 g (10 s).

  bench/coarse_steps.py ["TIME INTEGRATION SETS" ["CONTACT SETS" [LABEL]]]

sets separated by ';', e.g. "set Steps per shortest period = 50"; environment:
POUNDFE (binary), RECORD (the AT2 file), DTS (time steps, default 1e-2,1e-3,5e-5),
WORK (run directories, default /tmp/coarse_steps)."""
import json, subprocess, sys, os, itertools
BIN = os.environ.get('POUNDFE', 'build/poundfe')
REC = os.environ.get('RECORD', '/work/shared/records/IELC180.AT2')
WORK = os.environ.get('WORK', '/tmp/coarse_steps')

def building(i, name, n, k, zeta=0.05):
    return f"""subsection Building {i}
  set Name = {name}
  set Type = shear
  set Number of storeys = {n}
  set Storey heights = 3.0
  set Floor masses = 1000
  set Storey stiffnesses = {k}
  subsection Damping
    set Type = modes
    set Damping ratio = {zeta}
    set Modes = 1, 2
  end
end
"""

def prm(model, dt, extra_ti='', extra_contact='', end=10):
    n1, k1, n2, k2, gap = model
    return f"""subsection Model
  set Number of buildings = 2
  set Separations = {gap}
end
{building(1,'left',n1,k1)}{building(2,'right',n2,k2)}
subsection Ground motion
  set Type = record
  subsection Record
    set File = {REC}
    set Target PGA = 0.5
  end
end
subsection Contact
  set Law = jankowski
  set Stiffness = 2.75e9
{extra_contact}
end
subsection Time integration
  set Time step = {dt}
  set End time = {end}
  set Maximum number of steps = 10000000
{extra_ti}
end
subsection Output
  set Directory = out
  set Output interval = {dt}
  set VTU interval = 0
end
"""

def run(model, dt, tag, **kw):
    d = f'{WORK}/{tag}'
    os.makedirs(d, exist_ok=True)
    f = f'{d}/in.prm'
    open(f, 'w').write(prm(model, dt, **kw))
    r = subprocess.run([BIN, 'run', f, '--output', d + '/out'], capture_output=True, text=True)
    if r.returncode != 0:
        return None, r.stderr[-400:]
    return json.load(open(d + '/out/summary.json')), ''

def peaks(s):
    p = {}
    for b in s['buildings']:
        for st in b['storeys']:
            p[f"{b['name']}.drift{st['storey']}"] = st['peak_drift_ratio']
            p[f"{b['name']}.acc{st['storey']}"] = st['peak_absolute_floor_acceleration_m_s2']
    for g in s['gaps']:
        p[g['label'] + '.F'] = g['peak_force_N']
    return p

def errors(p, ref):
    e = {}
    for k, v in ref.items():
        if v != 0:
            e[k] = abs(p[k] - v) / abs(v)
    return e

if __name__ == '__main__':
    models = {
        'A2-2 gap5': (2, 1e6, 2, 4e6, 0.005),
        'A2-2 gap20': (2, 1e6, 2, 4e6, 0.02),
        'B3-2 gap2': (3, 5e6, 2, 3e6, 0.002),
        'B3-2 gap5': (3, 5e6, 2, 3e6, 0.005),
    }
    extra_ti = sys.argv[1].replace(';','\n') if len(sys.argv) > 1 else ''
    extra_contact = sys.argv[2].replace(';','\n') if len(sys.argv) > 2 else ''
    label = sys.argv[3] if len(sys.argv) > 3 else 'base'
    refdt = 1e-4
    DTS = [float(x) for x in os.environ.get("DTS", "1e-2,1e-3,5e-5").split(",")]
    for name, m in models.items():
        key = name.replace(' ', '_')
        ref, err = run(m, refdt, key + '_ref_' + label, extra_ti=extra_ti, extra_contact=extra_contact)
        if ref is None:
            print(name, 'ref failed', err); continue
        pr = peaks(ref)
        nimp = sum(g['impacts'] for g in ref['gaps'])
        print(f"== {name}: impacts {nimp}, peak F {max(g['peak_force_N'] for g in ref['gaps']):.4g}")
        for dt in DTS:
            s, err = run(m, dt, f'{key}_{dt}_{label}', extra_ti=extra_ti, extra_contact=extra_contact)
            if s is None:
                print(f'  dt {dt}: FAILED {err}'); continue
            e = errors(peaks(s), pr)
            worst = max(e, key=e.get)
            nw = s['newton']
            def wk(sub):
                ks = [k for k in e if sub in k]
                kk = max(ks, key=e.get)
                return f"{e[kk]*100:.3f}%"
            print(f"  dt {dt:g}: cuts {nw['step_cuts']} maxit {nw['max_iterations_per_step']} "
                  f"ev {nw['event_refinements']} cref {nw['contact_refinements']} sub {nw['steps_including_substeps']} "
                  f"| drift {wk('drift')} acc {wk('acc')} F {wk('.F')} worst {worst} {e[worst]*100:.3f}% wall {s['analysis']['wall_time_s']:.2f}s")
