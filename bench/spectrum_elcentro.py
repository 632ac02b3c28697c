#!/usr/bin/env python3
"""El Centro 1940 NS: `poundfe spectrum` against an independent computation.

  bench/spectrum_elcentro.py POUNDFE [RECORD]

RECORD defaults to /work/shared/records/elCentro_verification.at2 (the
"Peknold version", 1559 points at 0.02 s, in g). The record is not part of
the project: this script is a verification bench, not a ctest.

poundfe computes the 5 %-damped spectrum by the Nigam-Jennings exact
recursion (excitation/response_spectrum.h). The independent method here is
classical fourth-order Runge-Kutta on u'' + 2 zeta w u' + w^2 u = -a(t),
a(t) linear between the record's samples, with 20 sub-steps per sample
(h = 1 ms: the RK4 error is O((w h)^4), below 1e-8 at T = 0.5 s), the
peak taken at every sub-step, and the record followed by free vibration
for one period (poundfe's convention). PGA, PGV, Arias intensity and D5-95
are integrated here from the same samples (trapezoidal rule on a fine
linear interpolation). Pure Python: no NumPy needed.
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile

# the independent reference: RK4 and the intensity integrals, shared with tests/cli/spectrum.sh
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "tests", "cli"))
from spectrum_reference import G, intensity, rk4_peak  # noqa: E402

PERIODS = [0.5, 1.0, 2.0]
ZETA = 0.05


def read_at2(path):
    """Values in g after the 'NPTS=..., DT=...' line (or a '*** Begin data' header)."""
    values, dt, started = [], None, False
    with open(path) as f:
        for line in f:
            m = re.search(r"NPTS\s*=\s*(\d+)\s*,\s*DT\s*=\s*([0-9.Ee+-]+)", line)
            if m:
                dt, started = float(m.group(2)), True
                continue
            if started:
                if line.strip().startswith("***"):
                    break
                values += [float(x) for x in line.split()]
    return dt, [v * G for v in values]


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    poundfe = os.path.abspath(sys.argv[1])
    record = sys.argv[2] if len(sys.argv) > 2 else "/work/shared/records/elCentro_verification.at2"
    dt, a = read_at2(record)
    with tempfile.TemporaryDirectory() as work:
        prm = os.path.join(work, "elcentro.prm")
        with open(prm, "w") as f:
            f.write(f"""subsection Building 1
  set Type = shear
  set Number of storeys = 1
  set Storey heights = 3
  set Floor masses = 1000
  set Storey stiffnesses = 1e6
end
subsection Ground motion
  set Type = record
  subsection Record
    set File = {os.path.abspath(record)}
  end
end
subsection Time integration
  set Time step = {dt}
end
subsection Spectrum
  set Minimum period = {PERIODS[0]}
  set Maximum period = {PERIODS[-1]}
  set Number of periods = {len(PERIODS)}
  set Spacing = logarithmic
  set Damping ratios = {ZETA}
end
subsection Output
  set Plots = false
end
""")
        out = os.path.join(work, "out")
        subprocess.run([poundfe, "spectrum", prm, "--output", out], check=True,
                       stdout=subprocess.DEVNULL)
        with open(os.path.join(out, "spectrum.csv")) as f:
            header = f.readline().strip().split(",")
            rows = [[float(x) for x in line.split(",")] for line in f]
        with open(os.path.join(out, "summary.json")) as f:
            summary = json.load(f)
    column = header.index("psa_g_5pct")
    print(f"El Centro 1940 NS ({len(a)} points, dt = {dt} s), 5 % damping")
    print(f"{'T (s)':>6} {'PSA poundfe (g)':>16} {'PSA RK4 (g)':>12} {'rel. diff':>10}")
    worst = 0.0
    for row, period in zip(rows, PERIODS):
        assert abs(row[0] - period) < 1e-12 * period
        reference = (2 * math.pi / period) ** 2 * rk4_peak(a, dt, period, ZETA) / G
        diff = row[column] / reference - 1
        worst = max(worst, abs(diff))
        print(f"{period:6.2f} {row[column]:16.5f} {reference:12.5f} {diff:10.2e}")
    ours = summary["intensity"]
    theirs = intensity(a, dt)
    for key, value in theirs.items():
        print(f"{key:30s} poundfe {ours[key]:.6g}   independent {value:.6g}   "
              f"rel. diff {ours[key] / value - 1:.2e}")
    print(f"largest spectral difference {worst:.2e}")


if __name__ == "__main__":
    main()
