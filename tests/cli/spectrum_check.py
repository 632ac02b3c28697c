#!/usr/bin/env python3
"""Checks of tests/cli/spectrum.sh (pure Python).

  spectrum_check.py floors RUN_DIR     floor spectra of a run against RK4 on
                                       the run's own floor_acceleration.csv
  spectrum_check.py single DIR         spectrum.csv, summary.json of `spectrum`
  spectrum_check.py matched DIR        after re-running with the matched S0:
                                       mean PSA at the matching period = target
  spectrum_check.py s0 DIR             print the matched S0 and the period
"""
import csv
import json
import math
import os
import sys

from spectrum_reference import intensity, rk4_peak


def read_csv(path):
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    return rows[0], [[float(x) for x in row] for row in rows[1:]]


def fail(message):
    print("FAIL " + message)
    sys.exit(1)


def floors(directory):
    # Every step is in floor_acceleration.csv (Output interval = 0) and the
    # single building has no contact: the steps are uniform. RK4 with 10
    # sub-steps samples the peak >= 400 times per period; poundfe samples it
    # >= 200 times (1.2e-4 low at most) and ends with the run. Tolerance 1e-3:
    # RK4's own error is O((w h)^4) ~ 1e-8; the rest is the peaks' sampling.
    header, rows = read_csv(os.path.join(directory, "floor_acceleration.csv"))
    times = [r[0] for r in rows]
    dt = times[1] - times[0]
    s_header, s_rows = read_csv(os.path.join(directory, "floor_spectra.csv"))
    with open(os.path.join(directory, "summary.json")) as f:
        files = json.load(f)["output"]["files"]
    if "floor_spectra.csv" not in files:
        fail("floor_spectra.csv not listed in summary.json")
    zeta = 0.05
    checked, worst = 0, 0.0
    for name in header[1:]:
        floor = name[: -len("_acc_m_s2")]
        column = s_header.index(floor + "_psa_m_s2_5pct")
        a = [r[header.index(name)] for r in rows]
        for row in s_rows[:: max(1, len(s_rows) // 4)]:
            period = row[0]
            reference = (2 * math.pi / period) ** 2 * rk4_peak(a, dt, period, zeta, 10, False)
            if abs(row[column] / reference - 1) > 1e-3:
                fail(f"{floor} T = {period}: poundfe {row[column]}, RK4 {reference}")
            checked += 1
            worst = max(worst, abs(row[column] / reference - 1))
    print(f"ok   floor spectra: {checked} ordinates within 0.1 % of RK4 (largest {worst:.1e})")


def single(directory):
    header, rows = read_csv(os.path.join(directory, "spectrum.csv"))
    with open(os.path.join(directory, "summary.json")) as f:
        summary = json.load(f)
    for key in ("pga_m_s2", "pgv_m_s", "pgd_m", "arias_intensity_m_s",
                "significant_duration_5_95_s"):
        if key not in summary["intensity"]:
            fail("summary.json lacks intensity." + key)
    psa = header.index("psa_m_s2_5pct")
    sd = header.index("sd_m_5pct")
    for row in rows:
        w = 2 * math.pi / row[0]
        if abs(row[psa] - w * w * row[sd]) > 1e-12 * row[psa]:
            fail("PSA != w^2 Sd")
    print(f"ok   spectrum.csv: {len(rows)} periods, PSA = w^2 Sd")


def matched(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        m = json.load(f)["matching"]
    if abs(m["mean_psa_m_s2"] / m["target_psa_m_s2"] - 1) > 1e-9 or abs(m["s0_factor"] - 1) > 2e-9:
        fail(f"matched S0: mean PSA {m['mean_psa_m_s2']} against target {m['target_psa_m_s2']}")
    print(f"ok   matched S0: mean PSA {m['mean_psa_m_s2']:.6f} = target "
          f"{m['target_psa_m_s2']:.6f} m/s^2 at T = {m['period_s']:.4f} s")


def s0(directory):
    with open(os.path.join(directory, "summary.json")) as f:
        m = json.load(f)["matching"]
    print(repr(m["matched_s0_m2_s3"]), repr(m["period_s"]))


if __name__ == "__main__":
    {"floors": floors, "single": single, "matched": matched, "s0": s0}[sys.argv[1]](sys.argv[2])
