#!/usr/bin/env python3
"""The thesis's printed Tables 2.2, 2.3, 3.1 and eq. 2.36's frequencies
against poundfe's outputs.

The printed values are typed in below from the thesis (§2.3.1 Table 2.2 and
Table 2.3; §3.3.2 Table 3.1). Every row of one table has the same
tolerance rule:
  - Tables 2.2 and 2.3 and eq. 2.36 (§2.3): half a unit of the last digit
    the thesis prints (the table is rounded, so a value within that is the
    same printed number; eq. 2.36's frequencies are printed to the nearest
    hertz: half a hertz);
  - Table 3.1: two units of the last printed digit, 2e-4 in s, m and m/s
    (every value is printed to four decimals): half a unit of rounding, and
    the event times of Newmark with event refinement at dt = 1e-4 s against
    the thesis's ode45 with event location (about one step, 1e-4 s, and the
    state at the event with it).
Table 2.2's magnitudes are inputs (the catalogue holds the printed ones):
they are shown, marked as inputs, and not compared.

  thesis_tables.py check DIR22 DIR22_UNROUNDED DIR23 DIR31 DIR236
      exit 1 (with every failure listed) unless every value agrees
  thesis_tables.py markdown DIR22 DIR22_UNROUNDED DIR23 DIR31 DIR236
      the tables side by side, in Markdown, on standard output
DIR22: `site-hazard input/thesis/table-2.2.prm` (intensity rounded to one
decimal); DIR22_UNROUNDED: the same with `Intensity decimals = -1`; DIR23:
`site-hazard input/thesis/table-2.3.prm`; DIR31: `run input/thesis/table-3.1.prm`;
DIR236: `modal input/thesis/eq-2.36.prm`.
"""
import csv
import json
import sys

# Table 2.2 (§2.3.1): date, M, r (km), I, A_h (cm/s^2), and whether the
# thesis rounded I to one decimal before A_h on that row (24.8 and 3.1 are
# 10^(0.014 + 0.3 I) of the rounded I; 13.0 of the unrounded one).
TABLE_2_2 = [
    ("1903-06-10", 4.4, 79.4, 3.7, 13.0, False),
    ("1911-03-26", 5.7, 119.3, 4.6, 24.8, True),
    ("1913-10-09", 5.1, 280.0, 1.6, 3.1, True),
]

# Table 2.3 (§2.3.1): (method, return period, acceleration in gal printed,
# half a unit of its last printed digit); then k per return period, the
# OBE's return period for 50 % in 100 years, OBE and MCE (g).
TABLE_2_3_ROWS = [
    ("ISC", 100, 5.8, 0.05),
    ("JMA", 100, 2.5, 0.05),
    ("ISC", 250, 16.4, 0.05),
    ("JMA", 250, 14.0, 0.5),
    ("M.R.", 250, 32.7, 0.05),
]
TABLE_2_3_K = [(100, 0.01), (250, 0.03)]
TABLE_2_3_OBE_PERIOD = 144   # years (printed as an integer)
TABLE_2_3_OBE_G = 0.03
TABLE_2_3_MCE_G = 0.06

# Table 3.1 (§3.3.2): time (s), displacement (m), region (1: g1 crossed,
# 2: g2, the velocity's zero), velocity (m/s).
TABLE_3_1 = [
    (0.4006, 0.0050, 1, 0.1664), (0.4071, 0.0055, 2, 0.0000), (0.4172, 0.0050, 1, -0.0658),
    (0.8384, 0.0050, 1, 0.2095), (0.8446, 0.0055, 2, 0.0000), (0.8543, 0.0050, 1, -0.0820),
    (1.2818, 0.0050, 1, 0.2079), (1.2880, 0.0055, 2, -0.0000), (1.2977, 0.0050, 1, -0.0811),
    (1.7307, 0.0050, 1, 0.2048), (1.7368, 0.0055, 2, 0.0000), (1.7467, 0.0050, 1, -0.0799),
    (2.1798, 0.0050, 1, 0.2047), (2.1860, 0.0055, 2, 0.0000), (2.1958, 0.0050, 1, -0.0799),
    (2.6286, 0.0050, 1, 0.2049), (2.6348, 0.0055, 2, 0.0000), (2.6446, 0.0050, 1, -0.0799),
]
# eq. 2.36 (§2.3): m = 1000 kg, k = 5e6 N/m; the roots "rounded to the
# nearest integer, are 20, 14, and 5 Hz" (printed highest first).
EQ_2_36_HZ = [5, 14, 20]
EQ_2_36_TOLERANCE = 0.5     # Hz: half a unit of the printed integer

# Table 3.1: two units of the fourth decimal, in every column
TIME_TOLERANCE = 2e-4       # s
VELOCITY_TOLERANCE = 2e-4   # m/s
DISPLACEMENT_TOLERANCE = 2e-4  # m
BARRIER = 0.005             # m: the gap, where g1 = 0


class Comparison:
    def __init__(self):
        self.rows = {}        # table -> [(quantity, printed, poundfe, difference, tolerance)]
        self.failures = []

    def add(self, table, quantity, printed, got, tolerance, role="compared"):
        """role: "compared", "shown" (another rule, not compared) or "input"
        (poundfe was given the printed value: not compared)."""
        difference = got - printed
        self.rows.setdefault(table, []).append((quantity, printed, got, difference, tolerance, role))
        if role == "compared" and not abs(difference) <= tolerance:
            self.failures.append(f"{table} {quantity}: poundfe {got!r}, thesis {printed!r}, "
                                 f"difference {difference:.3g} > {tolerance:g}")


def events(directory):
    return {r["date"]: r for r in csv.DictReader(open(f"{directory}/hazard.csv"))}


def compare_table_2_2(c, rounded_dir, unrounded_dir):
    rounded, unrounded = events(rounded_dir), events(unrounded_dir)
    for date, M, r, I, A, thesis_rounds in TABLE_2_2:
        for name, rows in (("I rounded", rounded), ("I unrounded", unrounded)):
            if date not in rows:
                c.failures.append(f"Table 2.2: no event of {date} in {name} hazard.csv")
                return
        row = rounded[date] if thesis_rounds else unrounded[date]
        other = unrounded[date] if thesis_rounds else rounded[date]
        c.add("2.2", f"{date} M (input)", M, float(row["magnitude"]), 0.05, role="input")
        c.add("2.2", f"{date} r (km)", r, float(row["distance_km"]), 0.05)
        c.add("2.2", f"{date} I", I, float(unrounded[date]["intensity"]), 0.05)
        mode = "I rounded to 0.1" if thesis_rounds else "I not rounded"
        c.add("2.2", f"{date} A_h (cm/s^2), {mode}", A, float(row["pga_cm_s2"]), 0.05)
        other_mode = "I not rounded" if thesis_rounds else "I rounded to 0.1"
        c.add("2.2", f"{date} A_h (cm/s^2), {other_mode} (not the thesis's rule for this row)",
              A, float(other["pga_cm_s2"]), 0.05, role="shown")


def compare_table_2_3(c, directory):
    study = json.load(open(f"{directory}/summary.json"))["site_study"]
    for method, T, A, half in TABLE_2_3_ROWS:
        found = [r for r in study["rows"]
                 if r["method"] == method and r["return_period_years"] == T]
        if len(found) != 1:
            c.failures.append(f"Table 2.3: no single row {method} at {T} years")
            continue
        c.add("2.3", f"{method} {T} years: A (gal)", A, found[0]["acceleration_gal"], half)
    for T, k in TABLE_2_3_K:
        found = [d for d in study["design_coefficients"] if d["return_period_years"] == T]
        if len(found) != 1:
            c.failures.append(f"Table 2.3: no design k at {T} years")
            continue
        c.add("2.3", f"k at {T} years (largest A/980 {found[0]['largest_k']:.4f}, rounded)",
              k, found[0]["k"], 0.005)
    design = study["design_earthquakes"]
    c.add("2.3", "return period of 50 % in 100 years", TABLE_2_3_OBE_PERIOD,
          design["service_life_return_period_years"], 0.5)
    c.add("2.3", "OBE (g)", TABLE_2_3_OBE_G, design["obe_g"], 0.005)
    c.add("2.3", "MCE (g)", TABLE_2_3_MCE_G, design["mce_g"], 0.005)


def compare_table_3_1(c, directory):
    impacts = list(csv.DictReader(open(f"{directory}/impacts.csv")))
    if 3 * len(impacts) != len(TABLE_3_1):
        c.failures.append(f"Table 3.1: {len(impacts)} impacts, {3 * len(impacts)} switching "
                          f"points; the thesis has {len(TABLE_3_1)}")
        return
    for k, impact in enumerate(impacts):
        enter, deepest, leave = TABLE_3_1[3 * k:3 * k + 3]
        n = k + 1
        c.add("3.1", f"impact {n}: enters (g1 = 0), t (s)", enter[0],
              float(impact["start_time_s"]), TIME_TOLERANCE)
        c.add("3.1", f"impact {n}: enters, velocity (m/s)", enter[3],
              float(impact["approach_velocity_m_s"]), VELOCITY_TOLERANCE)
        c.add("3.1", f"impact {n}: deepest (g2 = 0), t (s)", deepest[0],
              float(impact["max_penetration_time_s"]), TIME_TOLERANCE)
        c.add("3.1", f"impact {n}: deepest, displacement (m)", deepest[1],
              BARRIER + float(impact["max_penetration_m"]), DISPLACEMENT_TOLERANCE)
        c.add("3.1", f"impact {n}: leaves (g1 = 0), t (s)", leave[0],
              float(impact["end_time_s"]), TIME_TOLERANCE)
        c.add("3.1", f"impact {n}: leaves, velocity (m/s)", leave[3],
              -float(impact["separation_velocity_m_s"]), VELOCITY_TOLERANCE)


def compare_eq_2_36(c, directory):
    frequencies = json.load(open(f"{directory}/summary.json"))["modes"]["frequencies_hz"]
    for n, (printed, got) in enumerate(zip(EQ_2_36_HZ, frequencies), 1):
        c.add("2.36", f"mode {n}, frequency (Hz)", printed, got, EQ_2_36_TOLERANCE)
    if len(frequencies) < len(EQ_2_36_HZ):
        c.failures.append(f"eq. 2.36: {len(frequencies)} modes, the thesis has 3")


def compare(directories):
    c = Comparison()
    compare_table_2_2(c, directories[0], directories[1])
    compare_table_2_3(c, directories[2])
    compare_table_3_1(c, directories[3])
    compare_eq_2_36(c, directories[4])
    return c


def markdown(c):
    titles = {"2.2": "Table 2.2 (§2.3.1): historical earthquakes near the site",
              "2.3": "Table 2.3 (§2.3.1): earthquake coefficient",
              "3.1": "Table 3.1 (§3.3.2): the spillway's switching points",
              "2.36": "Eq. 2.36 (§2.3): natural frequencies of the three-storey building"}
    for table, rows in c.rows.items():
        print(f"#### {titles[table]}\n")
        print("| quantity | thesis | poundfe | difference | tolerance | agrees |")
        print("|---|---|---|---|---|---|")
        for quantity, printed, got, difference, tolerance, role in rows:
            agrees = {"compared": "yes" if abs(difference) <= tolerance else "**no**",
                      "shown": "(shown)", "input": "(input)"}[role]
            print(f"| {quantity} | {printed:g} | {got:.6g} | {difference:+.2g} | {tolerance:g} | {agrees} |")
        worst = max((abs(d) / t for _, _, _, d, t, role in rows if role == "compared"), default=0)
        print(f"\nLargest |difference| / tolerance over the compared rows: {worst:.2f}.\n")


def main():
    if len(sys.argv) != 7 or sys.argv[1] not in ("check", "markdown"):
        sys.exit(__doc__)
    c = compare(sys.argv[2:])
    if sys.argv[1] == "markdown":
        markdown(c)
    for f in c.failures:
        print("FAIL", f, file=sys.stderr)
    if sys.argv[1] == "check":
        n = sum(1 for rows in c.rows.values() for r in rows if r[5] == "compared")
        print(f"{n} printed values compared, {len(c.failures)} outside their tolerance")
    sys.exit(1 if c.failures else 0)


if __name__ == "__main__":
    main()
