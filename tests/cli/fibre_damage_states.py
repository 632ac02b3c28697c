#!/usr/bin/env python3
"""The damage states of fibre members per storey in `montecarlo` (the
realizations' <building>_storey<i>_damage_state columns and summary.json's
storey_damage_states), checked in closed form and against the section states
recorder of the same realizations run one by one:

  usage: fibre_damage_states.py POUNDFE FIBRE.prm

- at a PGA of 0.005 g no bar yields and no concrete spalls (the gravity
  state's strains are far below both): every column 0, every probability 0;
- at 1.2 g every realization yields the bars of each building's first storey:
  P(yield) of those storeys 1;
- at 1.2 g, each realization r run again by `run` with Ground motion/
  Stochastic/Realization = r (the same standard normals) and its sections.csv
  recorded at every step: each storey's worst state from those strains (bar
  yield |eps_s| >= eps_y, spalling eps_c <= -0.004, crushing, fracture
  eps_s >= 0.05, the limits of the run's summary.json) is the realization's
  column, and each probability of summary.json is the count of realizations
  at that state or worse over the realizations. Crushing is read from the
  most compressed concrete fibre, which bounds the core's: the test stops if
  that bound cannot decide;
- `fragility` at PGA levels 0.005 g and 1.2 g, 3 realizations per level: at
  each level summary.json's damage_states_per_level (the level's PGA, each
  storey's probability of each state or worse, its failures and
  realizations) is the count over that level's pga_*/realizations.csv
  damage state columns, read independently; at 0.005 g every probability is
  0, at 1.2 g P(yield) of each building's first storey is 1.
"""
import csv
import json
import os
import subprocess
import sys
import tempfile

STATES = ["yield", "spalling", "crushing", "fracture"]
COMMON = ["--set", "Output/Plots=false", "--set", "Ground motion/Stochastic/Duration=2",
          "--set", "Section limits/Bar fracture strain=0.05"]


def montecarlo(poundfe, prm, pga, out):
    subprocess.run([poundfe, "montecarlo", prm, "--output", out, "--set",
                    "Monte Carlo/Realizations=3", "--set",
                    f"Ground motion/Stochastic/Target PGA={pga}"] + COMMON,
                   check=True, stdout=subprocess.DEVNULL)
    rows = list(csv.DictReader(open(os.path.join(out, "realizations.csv"))))
    summary = json.load(open(os.path.join(out, "summary.json")))
    return rows, summary["probabilities"].get("storey_damage_states", [])


def storey_of(label):
    """A_C2.1 (a column of storey 2), A_B2.1 (a beam of floor 2): ('A', 2)."""
    building, member = label.split("_", 1)
    return building, int(member[1:].split(".")[0])


def states_from_sections(out):
    """Each storey's worst state number (0 none ... 4 fracture) from sections.csv."""
    summary = json.load(open(os.path.join(out, "summary.json")))
    limits = {m["member"]: {k: v["strain"] for k, v in m["limits"].items()}
              for m in summary["section_limit_states"]}
    header = open(os.path.join(out, "sections.csv")).readline().strip().split(",")
    peaks = {}  # (member, quantity) -> extreme over the rows
    with open(os.path.join(out, "sections.csv")) as f:
        reader = csv.reader(f)
        next(reader)
        for row in reader:
            for name, value in zip(header[1:], row[1:]):
                member = name.split("_ip", 1)[0]
                value = float(value)
                for q, sign in (("concrete_strain", -1), ("steel_strain_max", 1),
                                ("steel_strain_min", -1)):
                    if name.endswith(q):
                        key = (member, q)
                        peaks[key] = max(peaks.get(key, 0.0) * sign, value * sign) * sign
    worst = {}
    for member, l in limits.items():
        concrete = peaks[(member, "concrete_strain")]
        bar = max(peaks[(member, "steel_strain_max")], -peaks[(member, "steel_strain_min")])
        if l["crushing"] is not None and concrete <= l["crushing"]:
            sys.exit(f"FAIL {member}: the cover reached the crushing strain; the core "
                     "cannot be read from sections.csv: lower the level")
        state = 0
        if bar >= l["bar_yield"]:
            state = 1
        if concrete <= l["spalling"]:
            state = 2
        if peaks[(member, "steel_strain_max")] >= l["bar_fracture"]:
            state = 4
        key = storey_of(member)
        worst[key] = max(worst.get(key, 0), state)
    return worst


def check_fragility(poundfe, prm, out, failures):
    """fragility's damage states per level against its realizations' columns."""
    subprocess.run([poundfe, "fragility", prm, "--output", out, "--set",
                    "Fragility/PGA levels=0.005, 1.2", "--set",
                    "Fragility/Realizations per level=3"] + COMMON,
                   check=True, stdout=subprocess.DEVNULL)
    levels = json.load(open(os.path.join(out, "summary.json")))["damage_states_per_level"]
    if [level["pga_g"] for level in levels] != [0.005, 1.2]:
        failures.append(f"fragility: levels {[level['pga_g'] for level in levels]}")
        return 0
    n_rows = 0
    for level in levels:
        name = "pga_" + ("%g" % level["pga_g"]) + "g"
        rows = list(csv.DictReader(open(os.path.join(out, name, "realizations.csv"))))
        rows = [r for r in rows if r["completed"] == "1"]
        n_rows += len(rows)
        storeys = level["storey_damage_states"]
        if len(storeys) != 7:
            failures.append(f"fragility {name}: {len(storeys)} storeys, 7 expected")
        for s in storeys:
            states = [float(r[s["column"]]) for r in rows]
            for l, state in enumerate(STATES):
                count = sum(x >= l + 1 for x in states)
                p = s[state]
                if (p["failures"], p["realizations"], p["probability"]) != \
                        (count, len(rows), count / len(rows)):
                    failures.append(f"fragility {name}: P({state}) of {s['column']} "
                                    f"{p['probability']} ({p['failures']} of "
                                    f"{p['realizations']}), its realizations {count} of "
                                    f"{len(rows)}")
                if level["pga_g"] == 0.005 and p["probability"] != 0:
                    failures.append(f"fragility {name}: {s['column']} P({state}) nonzero")
                if level["pga_g"] == 1.2 and state == "yield" and \
                        s["column"].endswith("_storey1_damage_state") and p["probability"] != 1:
                    failures.append(f"fragility {name}: P(yield) of {s['column']} not 1")
    return n_rows


def main():
    poundfe, prm = sys.argv[1], sys.argv[2]
    failures = []
    with tempfile.TemporaryDirectory() as work:
        rows, storeys = montecarlo(poundfe, prm, 0.005, os.path.join(work, "low"))
        columns = [c for c in rows[0] if c.endswith("_damage_state")]
        if len(columns) != 7 or len(storeys) != 7:
            failures.append(f"{len(columns)} damage state columns, {len(storeys)} storeys in "
                            "summary.json: 7 (4 + 3 storeys) expected")
        for r in rows:
            if any(float(r[c]) != 0 for c in columns):
                failures.append(f"0.005 g, realization {r['realization']}: a damage state")
        for s in storeys:
            if any(s[state]["probability"] != 0 for state in STATES):
                failures.append(f"0.005 g: {s['column']} has a nonzero probability")

        rows, storeys = montecarlo(poundfe, prm, 1.2, os.path.join(work, "high"))
        by_column = {s["column"]: s for s in storeys}
        for b in ("A", "B"):
            p = by_column[f"{b}_storey1_damage_state"]["yield"]["probability"]
            if p != 1:
                failures.append(f"1.2 g: P(yield) of {b}'s first storey {p}, 1 expected")
        counts = {c: [0] * 4 for c in columns}
        for r in rows:
            out = os.path.join(work, "run" + r["realization"])
            subprocess.run([poundfe, "run", prm, "--output", out, "--set",
                            f"Ground motion/Stochastic/Realization={r['realization']}",
                            "--set", "Ground motion/Stochastic/Target PGA=1.2",
                            "--set", "Output/Recorders/Record=section states every 0"] + COMMON,
                           check=True, stdout=subprocess.DEVNULL)
            worst = states_from_sections(out)
            for (building, storey), state in worst.items():
                column = f"{building}_storey{storey}_damage_state"
                if float(r[column]) != state:
                    failures.append(f"realization {r['realization']}: {column} {r[column]}, "
                                    f"sections.csv gives {state}")
                for l in range(4):
                    counts[column][l] += state >= l + 1
        for c in columns:
            for l, state in enumerate(STATES):
                p = by_column[c][state]
                if p["failures"] != counts[c][l] or p["probability"] != counts[c][l] / len(rows):
                    failures.append(f"1.2 g: P({state}) of {c} {p['probability']} "
                                    f"({p['failures']}), sections.csv counts {counts[c][l]}")
        seen = {state: sum(counts[c][l] for c in columns) for l, state in enumerate(STATES)}
        n_fragility = check_fragility(poundfe, prm, os.path.join(work, "fragility"), failures)
    for f in failures[:20]:
        print("FAIL", f)
    print(f"{len(columns)} storeys, {len(rows)} realizations at 1.2 g; storeys x realizations "
          f"at each state or worse: {seen}; fragility: {n_fragility} realizations over 2 "
          f"levels; {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
