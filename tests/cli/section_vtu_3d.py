#!/usr/bin/env python3
"""The fibre members of a 3D frame in the VTU output of `run`, read back and
checked against the run's recorders and against the members' equilibrium:

  usage: section_vtu_3d.py POUNDFE FIBRE3D.prm

The run is input/fibre-frame-3d.prm (gravity first, then the horizontal pair),
shortened to 2 s, frames every 0.25 s, recording the section states and the
end forces of every member. Checked:
- one vertex cell (kind 7) per integration point of every fibre member, on its
  member's line at the Gauss-Lobatto place (0, (1 - 1/sqrt 5)/2, ..., 1 for
  four points) to 1e-12 m, the end points the member's own (shared; no other
  point where an integration point stands), `integration_point` 1-based along the member and the
  member's `member` and `building` ids;
- at every frame, section_N, section_Mz, axial_strain, curvature_z, the three
  extreme fibre strains, section_My and curvature_y of each point are
  sections.csv's values at the frame's time, exactly (both outputs take them
  from one function; the CSV's shortest form reads back exactly); every other
  cell holds 0;
- at every frame, end_forces_start and end_forces_end (N, Vy, Vz, T, My, Mz)
  of each member's line are member_forces.csv's at that time, exactly;
- the limit states about both axes (summary.json's section_limit_states):
  each point's peak kappa_y either way bounds sections.csv's largest and
  smallest curvature_y (a row per step) and exceeds it by at most 1e-3 of
  kappa_y (the summary's peaks also see the steps' substeps); its ductility
  about y is max(kappa_y,max / kappa_y+, -kappa_y,min / kappa_y-) and about z
  the same (1e-12, one division), the curvature ductility the larger of the
  two, and within 1e-3 above the one sections.csv's curvatures give; each member's damage state the worst limit its points' extreme strains
  in sections.csv reach (bar yield |eps_s| >= eps_y, spalling eps_c <= eps_sp,
  fracture eps_s >= eps_f; crushing, whose core strain sections.csv does not
  hold, must not be reached) and drift_profile.csv's damage state of each storey the
  worst of its members' (the columns below a floor and that floor's beams);
- equilibrium, a reference independent of the element's forces: a
  force-based member's end sections carry its end forces, section N at
  either end = N_end = -N_start, section Mz = -Mz_start at the first point
  and Mz_end at the last, My likewise, to 1e-6 of the largest |force| of the
  member's kind over the run (the element's iteration stops when
  compatibility holds to 1e-20 of its energy; the section laws' forces then
  differ from b(x) q by the last residual). The elastic K u of a cracked
  member fails this by the loss of stiffness, which is why the run must
  crack: a bar strain beyond 1e-3 (seven times the concrete's cracking
  strain) at some point.
"""
import csv
import json
import math
import os
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu  # noqa: E402  (read_vtu: Python's XML parser, base64 and zlib)

SECTION_ARRAYS = ["section_N", "section_Mz", "axial_strain", "curvature_z", "concrete_strain",
                  "steel_strain_max", "steel_strain_min", "section_My", "curvature_y"]
SECTION_COLUMNS = ["_N_N", "_Mz_N_m", "_eps0", "_kappa_z_1_m", "_concrete_strain",
                   "_steel_strain_max", "_steel_strain_min", "_My_N_m", "_kappa_y_1_m"]
FORCE_COLUMNS = [f"_{q}{end}{unit}" for end in "12" for q, unit in
                 (("N", "_N"), ("Vy", "_N"), ("Vz", "_N"), ("T", "_N_m"), ("My", "_N_m"),
                  ("Mz", "_N_m"))]
LOBATTO4 = [0.0, (1 - 1 / math.sqrt(5)) / 2, (1 + 1 / math.sqrt(5)) / 2, 1.0]
EQUILIBRIUM = 1e-6
SUBSTEP = 1e-3  # of kappa_y (and of a ductility): what a substep may add to a recorded peak


def member_labels():
    """The members of input/fibre-frame-3d.prm: A (3 storeys, 2 x 1 bays) and
    B (2 storeys, 1 x 1 bay), labelled as the 3D frame builder labels them."""
    labels = []
    for name, storeys, nx, ny in (("A", 3, 3, 2), ("B", 2, 2, 2)):
        for s in range(1, storeys + 1):
            for jx in range(1, nx + 1):
                for jy in range(1, ny + 1):
                    labels.append(f"{name}_C{s}.{jx}.{jy}")
                    if jx < nx:
                        labels.append(f"{name}_BX{s}.{jx}.{jy}")
                    if jy < ny:
                        labels.append(f"{name}_BY{s}.{jx}.{jy}")
    return labels


def section_points(header):
    """(member label, point number, first column) of each point of sections.csv."""
    points = []
    for k in range(1, len(header), len(SECTION_COLUMNS)):
        label, number = header[k][:-len(SECTION_COLUMNS[0])].rsplit("_ip", 1)
        points.append((label, int(number), k - 1))
        for j, column in enumerate(SECTION_COLUMNS):
            if header[k + j] != f"{label}_ip{number}{column}":
                vtu.failures.append(f"sections.csv: column {header[k + j]}")
    return points


def member_cells(v):
    """Each member line's cell by (building, member id), and the section cells."""
    kind = v["cell"]["kind"]
    lines = {(v["cell"]["building"][c], v["cell"]["member"][c]): c
             for c in range(len(kind)) if kind[c] == 0}
    return lines, [c for c in range(len(kind)) if kind[c] == 7]


def check_no_shared_section_point(name, v, failures):
    """vtu.py's check of duplicated points, left to this one: a gap's contact
    point stands at rest on a slab corner (a joint), so a 3D drawing with
    contact in plan repeats those points; an integration point must be no
    other point than its member's own end."""
    vtu.failures[:] = [f for f in vtu.failures if "duplicated points" not in f]
    kind = v["cell"]["kind"]
    at = {}
    for c in range(len(kind)):
        if kind[c] not in (6, 8):  # the contact points at rest, and their stems
            for p in v["cells"][c]:
                at.setdefault(v["xyz"][p], set()).add(p)
    for c in range(len(kind)):
        if kind[c] == 7 and len(at[v["xyz"][v["cells"][c][0]]]) > 1:
            failures.append(f"{name}: section cell {c}'s point is repeated")


def check_places(v, points, failures):
    """Each section cell on its member's line at the rule's place."""
    lines, sections = member_cells(v)
    for (label, number, _), c in zip(points, sections):
        line = v["cells"][lines[(v["cell"]["building"][c], v["cell"]["member"][c])]]
        a, b, p = (v["xyz"][i] for i in (line[0], line[1], v["cells"][c][0]))
        xi = LOBATTO4[number - 1]
        if max(abs(p[k] - a[k] - xi * (b[k] - a[k])) for k in range(3)) > 1e-12:
            failures.append(f"{label} point {number}: at {p}, not at xi = {xi} of {a}-{b}")
        if v["cell"]["integration_point"][c] != number:
            failures.append(f"{label}: cell {c} is point {v['cell']['integration_point'][c]}")
        end = {1: line[0], 4: line[1]}.get(number)
        if end is not None and v["cells"][c][0] != end:
            failures.append(f"{label} point {number}: not its member's end point")


def check_sections(name, v, points, row, failures):
    """The section arrays against sections.csv's row, exactly; 0 elsewhere."""
    _, sections = member_cells(v)
    if len(sections) != len(points):
        failures.append(f"{name}: {len(sections)} section cells, {len(points)} in sections.csv")
        return
    for (label, number, first), c in zip(points, sections):
        for k, array in enumerate(SECTION_ARRAYS):
            if v["cell"][array][c] != row[first + k]:
                failures.append(f"{name}: {array} of {label} point {number} "
                                f"{v['cell'][array][c]} against sections.csv's {row[first + k]}")
    kind = v["cell"]["kind"]
    for array in SECTION_ARRAYS:
        off = [c for c in range(len(kind)) if kind[c] != 7 and v["cell"][array][c] != 0]
        if off:
            failures.append(f"{name}: {array} nonzero on cells {off[:5]}")


def check_forces(name, v, points, forces, failures):
    """End forces against member_forces.csv; the member's ends by equilibrium
    with its end sections. Returns {label: (end forces, end sections)}."""
    header, row = forces
    lines, sections = member_cells(v)
    seen = {}
    for (label, number, _), c in zip(points, sections):
        cell = lines[(v["cell"]["building"][c], v["cell"]["member"][c])]
        f = v["cell"]["end_forces_start"][6 * cell:6 * cell + 6] + \
            v["cell"]["end_forces_end"][6 * cell:6 * cell + 6]
        if label not in seen:
            expected = [row[header.index(label + col) - 1] for col in FORCE_COLUMNS]
            if f != expected:
                failures.append(f"{name}: end forces of {label} {f} against member_forces.csv's "
                                f"{expected}")
            seen[label] = (f, {})
        if number in (1, 4):
            seen[label][1][number] = [v["cell"][a][c] for a in ("section_N", "section_Mz",
                                                                "section_My")]
    return seen


def equilibrium_gaps(members):
    """Per member kind (column, beam): the largest |force| and the largest
    difference between an end force and its end section's."""
    gaps = {}
    for label, (f, ends) in members.items():
        kind = "column" if "_C" in label else "beam"
        n1, mz1, my1 = ends[1]
        n4, mz4, my4 = ends[4]
        pairs = [(n1, -f[0]), (n4, f[6]), (mz1, -f[5]), (mz4, f[11]), (my1, -f[4]), (my4, f[10])]
        scale, gap = gaps.get(kind, (0.0, 0.0))
        for a, b in pairs:
            scale, gap = max(scale, abs(a), abs(b)), max(gap, abs(a - b))
        gaps[kind] = (scale, gap)
    return gaps


STATES = ["none", "yield", "spalling", "crushing", "fracture"]


def ductility(high, low, up, down):
    return max(high / up, -low / down)


def check_limits(out, header, rows, points, failures):
    """summary.json's limit states about both axes against sections.csv."""
    members = {m["member"]: m for m in json.load(open(os.path.join(out, "summary.json")))
               ["section_limit_states"]}
    worst, largest_mu = {}, 0.0
    for label, number, first in points:
        m, k = members.get(label), number - 1
        if m is None or "curvature_ductility_y" not in m:
            failures.append(f"summary.json: no limit states about y of {label}")
            continue
        series = {name: [r[first + j] for r in rows.values()]
                  for j, name in enumerate(SECTION_COLUMNS)}
        ky, kz = series["_kappa_y_1_m"], series["_kappa_z_1_m"]
        up, down = m["yield_curvature_y_positive_1_m"][k], m["yield_curvature_y_negative_1_m"][k]
        high, low = m["peak_curvature_y_positive_1_m"][k], m["peak_curvature_y_negative_1_m"][k]
        # the summary's peaks also see the substeps, which sections.csv has no row of
        if not (low <= min(ky + [0.0]) and max(ky + [0.0]) <= high and
                high - max(ky) <= SUBSTEP * up and min(ky) - low <= SUBSTEP * down):
            failures.append(f"{label} point {number}: peak kappa_y {low}, {high} against "
                            f"sections.csv's {min(ky)}, {max(ky)}")
        mu_y = ductility(high, low, up, down)
        mu_z = ductility(m["peak_curvature_positive_1_m"][k], m["peak_curvature_negative_1_m"][k],
                         m["yield_curvature_positive_1_m"][k], m["yield_curvature_negative_1_m"][k])
        for name, expected in (("curvature_ductility_y", mu_y), ("curvature_ductility_z", mu_z),
                               ("curvature_ductility", max(mu_y, mu_z))):
            if abs(m[name][k] - expected) > 1e-12 * expected:
                failures.append(f"{label} point {number}: {name} {m[name][k]} against {expected}")
        mu_recorded = max(ductility(max(ky + [0.0]), min(ky + [0.0]), up, down),
                          ductility(max(kz + [0.0]), min(kz + [0.0]),
                                    m["yield_curvature_positive_1_m"][k],
                                    m["yield_curvature_negative_1_m"][k]))
        if not mu_recorded <= m["curvature_ductility"][k] <= mu_recorded + SUBSTEP:
            failures.append(f"{label} point {number}: curvature ductility "
                            f"{m['curvature_ductility'][k]}, sections.csv's {mu_recorded}")
        largest_mu = max(largest_mu, m["curvature_ductility_y"][k])
        limits = {name: m["limits"][name]["strain"] for name in m["limits"]}
        steel = max(max(series["_steel_strain_max"]), -min(series["_steel_strain_min"]))
        reached = [limits["bar_yield"] is not None and steel >= limits["bar_yield"],
                   min(series["_concrete_strain"]) <= limits["spalling"], False,
                   limits["bar_fracture"] is not None and
                   max(series["_steel_strain_max"]) >= limits["bar_fracture"]]
        state = max([l + 1 for l in range(4) if reached[l]] + [0])
        worst[label] = max(worst.get(label, 0), state)
        if (m["limits"]["crushing"]["ratio"] or 0) >= 1:
            failures.append(f"{label}: the core crushed; sections.csv cannot check it")
    for label, state in worst.items():
        if members.get(label, {}).get("damage_state") != STATES[state]:
            failures.append(f"{label}: damage state {members.get(label, {}).get('damage_state')} "
                            f"against sections.csv's {STATES[state]}")
    storeys = {}
    for label, state in worst.items():
        building, place = label.split("_", 1)
        key = (building, int(place.lstrip("CBXY").split(".")[0]))
        storeys[key] = max(storeys.get(key, 0), state)
    with open(os.path.join(out, "drift_profile.csv")) as f:
        drift = {(r["building"], int(r["storey"])): r.get("damage_state")
                 for r in csv.DictReader(f)}
    for key, state in storeys.items():
        if drift.get(key) != STATES[state]:
            failures.append(f"drift_profile.csv: storey {key} {drift.get(key)} against {STATES[state]}")
    return sorted(set(worst.values())), largest_mu


def main():
    poundfe, prm = sys.argv[1], sys.argv[2]
    failures = vtu.failures
    labels = member_labels()
    with tempfile.TemporaryDirectory() as work:
        short = os.path.join(work, "short.prm")
        with open(prm) as f:
            open(short, "w").write(f.read().replace("set Duration   = 6", "set Duration   = 2"))
        out = os.path.join(work, "run")
        subprocess.run([poundfe, "run", short, "--output", out, "--set", "Output/Plots=false",
                        "--set", "Output/VTU interval=0.25", "--set", "Output/Output interval=0",
                        "--set", "Output/Recorders/Record=section states; member end forces of "
                        + ", ".join(labels)], check=True, stdout=subprocess.DEVNULL)
        header = open(os.path.join(out, "sections.csv")).readline().strip().split(",")
        _, rows = vtu.read_csv(os.path.join(out, "sections.csv"))
        forces_header, forces = vtu.read_csv(os.path.join(out, "member_forces.csv"))
        points = section_points(header)
        frames = vtu.read_pvd(os.path.join(out, "solution.pvd"))
        gaps, cracked, n_members = {}, 0.0, 0
        for time, name in frames:
            v = vtu.read_vtu(os.path.join(out, name))
            check_no_shared_section_point(name, v, failures)
            if time not in rows or time not in forces:
                failures.append(f"{name}: no row of sections.csv or member_forces.csv at t = {time}")
                continue
            check_sections(name, v, points, rows[time], failures)
            members = check_forces(name, v, points, (forces_header, forces[time]), failures)
            n_members = len(members)
            for kind, (scale, gap) in equilibrium_gaps(members).items():
                s0, g0 = gaps.get(kind, (0.0, 0.0))
                gaps[kind] = (max(s0, scale), max(g0, gap))
            cracked = max([cracked] + [v["cell"]["steel_strain_max"][c]
                                       for c in member_cells(v)[1]])
        check_places(v, points, failures)
        states, largest_mu_y = check_limits(out, header, rows, points, failures)
    for kind, (scale, gap) in gaps.items():
        if not gap <= EQUILIBRIUM * scale:
            failures.append(f"{kind}s: end forces and end sections differ by {gap:.3g} N (m), "
                            f"{gap / scale:.3g} of the largest {scale:.4g}")
    if len(frames) < 8 or cracked <= 1e-3 or n_members != len(labels):
        failures.append(f"{len(frames)} frames, largest bar strain {cracked}, {n_members} of "
                        f"{len(labels)} members: no cracked frame checked")
    for f in failures[:20]:
        print("FAIL", f)
    print(f"{len(frames)} frames, {len(points)} integration points, {n_members} members, "
          f"largest bar strain {cracked:.3g}; equilibrium of the end sections: "
          + ", ".join(f"{k}s {g / s:.3g} of {s:.4g}" for k, (s, g) in sorted(gaps.items()))
          + f"; damage states {[STATES[k] for k in states]}, largest curvature ductility "
          f"about y {largest_mu_y:.3g}; {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
