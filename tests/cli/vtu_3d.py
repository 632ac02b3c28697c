#!/usr/bin/env python3
"""The VTU output of 3D models (doc/theory.md §10, "3D models"), read with
Python's XML parser, base64 and zlib (the readers of tests/cli/vtu.py), and
checked against the run's CSV histories at the frame's time:

  usage: vtu_3d.py POUNDFE INPUT_DIR

- input/3d-torsional-pair.prm (3D frames, rigid diaphragms, hinges, pounding),
  cut to 4 s, a frame every 0.01 s (every tenth read, and all within 0.05 s of
  a contact), all equations recorded (phase portrait):
  * structure: arrays sized by points x components or cells x components,
    offsets and connectivity agree, the .pvd lists the files with their times,
    one line per member (storeys x (columns + beams along x and y) in closed
    form from the grid), one slab and one mass centre per floor;
  * a mass centre's ux is floor_displacement.csv's, its uy and rz the master
    node's u in phase_portrait.csv (the same doubles: exact);
  * every slab corner and every joint above the ground moves with its floor as
    a rigid body, u = u_C + θ e_z × (X - C), rz = θ (1e-12 of the largest
    translation: one product and sum in each program);
  * a joint's uz, rx, ry are its node's three DOFs in phase_portrait.csv
    (exact); the joints on the ground do not move (exact);
  * each member is in equilibrium: its end forces sum to zero and so do their
    moments about its first end (1e-9 of its largest end force times its
    length: the rows of K_e balance to round-off);
  * a gap's force is contact_force.csv's (exact) and contact is 1 exactly
    where it is > 0, in contact in some frame;
  * each gap's contact point (one vertex per gap) carries the same force and
    flag; its arrow point, joined to it by a stem (a line of kind 8 with the
    same force and flag), stands straight above it (2 % of the model's size,
    so that a Glyph's arrow there is not hidden in the slabs' plane) and
    moves with it; the contact point carries no contact_force, the arrow
    point in contact the force on the gap's first
    building: of magnitude the gap force (1e-12: |n| = 1 to round-off), in
    plan, pushing the first floor away from the second (positive along the
    line from the second's mass centre to the first's), and its displaced
    position is a corner of one of the two slabs moved as a rigid body with
    the finite rotation R(θ), as the contact element does (1e-9 m); zero
    force and no displacement check while open;
- input/3d-torsional-shear-pair.prm cut to 1 s: the mass centres, slabs and
  one storey line per storey, as above;
  and Δmax/Δavg at the instant of each storey's largest corner drift
  (summary.json), recomputed from every step's floor motions and the plan
  at rest (1e-12 relative: the same doubles in another order);
- `modal` of the frames: each mode's frequency is summary.json's and its
  largest translation 5 % of the model's largest extent (1e-12).
"""
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu  # noqa: E402  (the readers; its own checks run only as a script)

failures = vtu.failures
check = vtu.check
MEMBER, STOREY, GAP, SLAB, CENTRE, CONTACT, ARROW = 0, 1, 2, 4, 5, 6, 8


def read(path):
    """Points, cells, point and cell data of a VTU file (duplicated points
    allowed: a mass centre may stand on a joint)."""
    root = ET.parse(path).getroot()
    vtu.COMPRESSED[0] = root.get("compressor") == "vtkZLibDataCompressor"
    grid = root.find("UnstructuredGrid")
    piece = grid.find("Piece")
    n_points, n_cells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))
    fields = {k: v[1][0] for k, v in vtu.arrays(grid.find("FieldData")).items()}
    points = vtu.arrays(piece.find("Points"))["Points"][1]
    cells = vtu.arrays(piece.find("Cells"))
    data = {}
    for section, n in (("PointData", n_points), ("CellData", n_cells)):
        for name, (nc, values) in vtu.arrays(piece.find(section)).items():
            check(len(values) == nc * n, f"{path}: {name} has {len(values)} values for {n} x {nc}")
            data[name] = [values[nc * i:nc * i + nc] if nc > 1 else values[i] for i in range(n)]
    check(len(points) == 3 * n_points, f"{path}: {len(points)} point coordinates")
    offsets, connectivity = cells["offsets"][1], cells["connectivity"][1]
    check(len(offsets) == n_cells and offsets[-1] == len(connectivity), f"{path}: offsets")
    check(all(0 <= c < n_points for c in connectivity), f"{path}: connectivity out of range")
    return dict(fields=fields, xyz=[points[3 * i:3 * i + 3] for i in range(n_points)],
                cells=[connectivity[(offsets[c - 1] if c else 0):offsets[c]] for c in range(n_cells)],
                types=cells["types"][1], data=data)


def columns(path):
    header, rows = vtu.read_csv(path)
    return {name: i for i, name in enumerate(header[1:])}, rows


def run(poundfe, prm, work, name, edits, command="run"):
    with open(prm) as f:
        text = f.read()
    for old, new in edits:
        check(old in text, f"{prm}: no '{old}' to change")
        text = text.replace(old, new)
    path = os.path.join(work, name + ".prm")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(work, name)
    subprocess.run([poundfe, command, path, "--output", out], check=True, stdout=subprocess.DEVNULL)
    return out


def building_names(prm):
    with open(prm) as f:
        return re.findall(r"set Name\s*=\s*(\S+)", f.read())


def unit(component):
    """The unit of a DOF's column of phase_portrait.csv: rad for a rotation."""
    return "rad" if component.startswith("r") else "m"


def check_frames(out, names, expected_members, frames_in_contact):
    disp_col, disp = columns(os.path.join(out, "floor_displacement.csv"))
    dof_col, dofs = columns(os.path.join(out, "phase_portrait.csv"))
    gap_col, gaps = columns(os.path.join(out, "contact_force.csv"))
    gap_names = [c[:-len("_force_N")] for c in gap_col if c.endswith("_force_N")]
    frames = vtu.read_pvd(out + "/solution.pvd")
    check(len(frames) > 1, "no frames")
    # every tenth frame, and every frame while a gap is closed (reading is the slow part)
    closed = [t for t, row in gaps.items() if any(row[gap_col[g + "_force_N"]] > 0 for g in gap_names)]
    frames = [f for i, f in enumerate(frames)
              if i % 10 == 0 or any(abs(f[0] - t) < 0.05 for t in closed)]
    n_joints = n_corners = n_contact = 0
    for time, name in frames:
        v = read(os.path.join(out, name))
        check(abs(v["fields"]["TIME"] - time) <= 1e-12 * max(1, time), f"{name}: TIME")
        kind, building, member = v["data"]["kind"], v["data"]["building"], v["data"]["member"]
        d, r, node = v["data"]["displacement"], v["data"]["rotation"], v["data"]["node"]
        if time == frames[0][0]:
            check(kind.count(MEMBER) == expected_members,
                  f"{kind.count(MEMBER)} member lines, {expected_members} expected")
            check(kind.count(CONTACT) == len(gap_names),
                  f"{kind.count(CONTACT)} contact points, {len(gap_names)} gaps")
        u = dofs[min(dofs, key=lambda t: abs(t - time))]
        largest = max(1e-300, max(math.hypot(*p) for p in d))
        centres = {}  # (building, z) -> point of the mass centre
        for c, points in enumerate(v["cells"]):
            if kind[c] != CENTRE:
                continue
            p = points[0]
            b = names[building[c] - 1]
            master = v["data"]["node"][p]
            centres[(building[c], round(v["xyz"][p][2], 6))] = p
            want_ux = disp[time][disp_col[f"{b}_floor{member[c]}_disp_x_m"]]
            check(d[p][0] == want_ux, f"{name}: {b} floor {member[c]} ux {d[p][0]} against {want_ux}")
            for got, comp in ((d[p][1], "uy"), (r[p][2], "rz")):
                want = u[dof_col[f"{b}_node{master}_{comp}_{unit(comp)}"]]
                check(got == want, f"{name}: {b} floor {member[c]} {comp} {got} against {want}")

        def rigid(p, b):
            """The motion of point p by its floor's mass centre; None on the ground."""
            c = centres.get((b, round(v["xyz"][p][2], 6)))
            if c is None:
                return None
            dx, dy = v["xyz"][p][0] - v["xyz"][c][0], v["xyz"][p][1] - v["xyz"][c][1]
            theta = r[c][2]
            return d[c][0] - theta * dy, d[c][1] + theta * dx, theta

        for c, points in enumerate(v["cells"]):
            if kind[c] == SLAB:
                for p in points:
                    want = rigid(p, building[c])
                    n_corners += 1
                    check(max(abs(d[p][0] - want[0]), abs(d[p][1] - want[1]), abs(r[p][2] - want[2]))
                          <= 1e-12 * largest, f"{name}: slab corner {p} {d[p]} against {want}")
            elif kind[c] == MEMBER:
                for p in points:
                    want = rigid(p, building[c])
                    b = names[building[c] - 1]
                    if want is None:  # on the ground
                        check(d[p] == [0, 0, 0] and r[p] == [0, 0, 0], f"{name}: ground joint {p} moves")
                        continue
                    n_joints += 1
                    check(max(abs(d[p][0] - want[0]), abs(d[p][1] - want[1]), abs(r[p][2] - want[2]))
                          <= 1e-12 * largest, f"{name}: joint {p} {d[p]} against its floor's {want}")
                    # the joint's vertical part: phase_portrait.csv names its DOFs uz, rx, ry
                    own = [u[dof_col[f"{b}_node{node[p]}_{comp}_{unit(comp)}"]] for comp in ("uz", "rx", "ry")]
                    check([d[p][2], r[p][0], r[p][1]] == own,
                          f"{name}: joint {p} (uz, rx, ry) against node {node[p]}'s {own}")
                f1, f2 = v["data"]["end_forces_start"][c], v["data"]["end_forces_end"][c]
                a, b2 = v["xyz"][points[0]], v["xyz"][points[1]]
                L = math.dist(a, b2)
                scale = max(1.0, max(abs(x) for x in f1 + f2 if True)) * max(1.0, L)
                residuals = [f1[k] + f2[k] for k in range(4)] + [
                    f1[4] + f2[4] - L * f2[2], f1[5] + f2[5] + L * f2[1]]
                check(max(abs(x) for x in residuals) <= 1e-9 * scale,
                      f"{name}: member {c} not in equilibrium {residuals}")
            elif kind[c] == GAP:
                force = v["data"]["force"][c]
                want = gaps[time][gap_col[gap_names[member[c] - 1] + "_force_N"]]
                check(force == want, f"{name}: gap {member[c]} force {force} against {want}")
                check(v["data"]["contact"][c] == (force > 0), f"{name}: gap {member[c]} contact flag")
                n_contact += force > 0
            elif kind[c] == CONTACT:
                check_contact_point(v, name, c, gaps[time][gap_col[gap_names[member[c] - 1] + "_force_N"]],
                                    centres)
    check(n_contact >= frames_in_contact, f"{n_contact} gap-frames in contact")
    return len(frames), n_joints, n_corners, n_contact


def check_contact_point(v, name, c, want, centres):
    """A gap's contact point (the vertex cell c) against the gap's force
    `want` and the floors' motions (the mass centres `centres`)."""
    p, g = v["cells"][c][0], v["data"]["member"][c]
    stems = [s for s, points in enumerate(v["cells"])
             if v["data"]["kind"][s] == ARROW and v["data"]["member"][s] == g]
    check(len(stems) == 1, f"{name}: contact point {g}: {len(stems)} arrow stems")
    if len(stems) != 1:
        return
    bottom, a = v["cells"][stems[0]]
    check(bottom == p, f"{name}: contact point {g}: the stem starts at point {bottom}")
    lift = v["xyz"][a][2] - v["xyz"][p][2]
    size = model_size(v)
    check(v["xyz"][a][:2] == v["xyz"][p][:2] and abs(lift - 0.02 * size) <= 1e-9 * size and lift > 0,
          f"{name}: contact point {g}: arrow point {v['xyz'][a]} not {0.02 * size} m above {v['xyz'][p]}")
    check(v["data"]["displacement"][a] == v["data"]["displacement"][p],
          f"{name}: contact point {g}: the arrow point does not move with it")
    check(v["data"]["contact_force"][p] == [0, 0, 0], f"{name}: contact point {g} carries a force")
    check(v["data"]["force"][stems[0]] == want and v["data"]["contact"][stems[0]] == (want > 0),
          f"{name}: contact point {g}: the stem's force")
    force, f = v["data"]["force"][c], v["data"]["contact_force"][a]
    check(force == want and v["data"]["contact"][c] == (force > 0), f"{name}: contact point {g} force")
    if force <= 0:
        check(f == [0, 0, 0], f"{name}: contact point {g}: force {f} while open")
        return
    check(abs(math.hypot(f[0], f[1]) - force) <= 1e-12 * force and f[2] == 0,
          f"{name}: contact point {g}: |{f}| against {force}")
    z = round(v["xyz"][p][2], 6)
    first = v["data"]["building"][c]
    floors = {b: q for (b, level), q in centres.items() if level == z}
    check(len(floors) == 2 and first in floors, f"{name}: contact point {g}: floors {floors}")
    second = next(b for b in floors if b != first)
    where = {b: [v["xyz"][q][k] + v["data"]["displacement"][q][k] for k in range(2)]
             for b, q in floors.items()}
    check(f[0] * (where[first][0] - where[second][0]) + f[1] * (where[first][1] - where[second][1]) > 0,
          f"{name}: contact point {g}: force {f} pushes the first floor towards the second")
    x = [v["xyz"][p][k] + v["data"]["displacement"][p][k] for k in range(2)]
    corners = []
    for s, points in enumerate(v["cells"]):
        if v["data"]["kind"][s] == SLAB and round(v["xyz"][points[0]][2], 6) == z:
            q = floors[v["data"]["building"][s]]
            C, u, theta = v["xyz"][q], v["data"]["displacement"][q], v["data"]["rotation"][q][2]
            for k in points:
                X = [v["xyz"][k][0] - C[0], v["xyz"][k][1] - C[1]]
                corners.append((C[0] + u[0] + math.cos(theta) * X[0] - math.sin(theta) * X[1],
                                C[1] + u[1] + math.sin(theta) * X[0] + math.cos(theta) * X[1]))
    nearest = min(math.dist(x, corner) for corner in corners)
    check(nearest <= 1e-9, f"{name}: contact point {g} at {x}, {nearest} m from a slab corner")


def check_shear(out, names, n_storeys):
    frames = vtu.read_pvd(out + "/solution.pvd")
    v = read(os.path.join(out, frames[-1][1]))
    kind = v["data"]["kind"]
    check(kind.count(STOREY) == n_storeys, f"{kind.count(STOREY)} storey lines, {n_storeys} expected")
    check(kind.count(SLAB) == n_storeys and kind.count(CENTRE) == n_storeys, "slabs or mass centres")
    return check_frames(out, names, 0, 0)


def check_irregularity(out, names):
    """Δmax/Δavg at the instant of each storey's largest corner drift, from
    every step's floor motions (phase_portrait.csv) and the plan at rest (the
    first VTU frame: mass centres and slab corners), against summary.json."""
    v = read(os.path.join(out, vtu.read_pvd(out + "/solution.pvd")[0][1]))
    kind, building, member = v["data"]["kind"], v["data"]["building"], v["data"]["member"]
    centre, corners = {}, {}
    for c, points in enumerate(v["cells"]):
        if kind[c] == CENTRE:
            centre[(building[c], member[c])] = points[0]
        elif kind[c] == SLAB:
            corners[(building[c], member[c])] = points
    dof_col, dofs = columns(os.path.join(out, "phase_portrait.csv"))
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)["buildings"]
    n_checked = 0
    for b, name in enumerate(names, start=1):
        floors = sorted(f for (bb, f) in centre if bb == b)
        for d, axis in enumerate("xy"):
            reported = summary[b - 1]["plan"][f"torsional_irregularity_at_peak_{axis}"]
            for i in floors:
                def motion(floor, row, X):  # u of floor `floor` at the plan point X, along `axis`
                    if floor == 0:
                        return 0.0
                    p = centre[(b, floor)]
                    node = v["data"]["node"][p]
                    ux, uy, th = (row[dof_col[f"{name}_node{node}_{c}_{unit(c)}"]] for c in ("ux", "uy", "rz"))
                    C = v["xyz"][p]
                    return ux - th * (X[1] - C[1]) if d == 0 else uy + th * (X[0] - C[0])
                peak, ratio = 0.0, 1.0
                for t in sorted(dofs):
                    drifts = [motion(i, dofs[t], v["xyz"][k]) - motion(i - 1, dofs[t], v["xyz"][k])
                              for k in corners[(b, i)]]
                    hi, lo = max(drifts), min(drifts)
                    largest = max(abs(hi), abs(lo))
                    if largest > peak:
                        peak = largest
                        average = 0.5 * (hi + lo) if abs(hi) >= abs(lo) else -0.5 * (hi + lo)
                        if average > 0:
                            ratio = largest / average
                got = reported[i - 1]
                check(abs(got - ratio) <= 1e-12 * ratio,
                      f"{name} storey {i} {axis}: ratio at the peak {got} against {ratio}")
                n_checked += 1
    return n_checked


def model_size(v):
    """The model's largest extent along x, y or z, without the contact
    arrows' points (lifted above the model by a fraction of that size)."""
    arrows = {points[1] for s, points in enumerate(v["cells"]) if v["data"]["kind"][s] == ARROW}
    xyz = [x for i, x in enumerate(v["xyz"]) if i not in arrows]
    return max(max(x[k] for x in xyz) - min(x[k] for x in xyz) for k in range(3))


def check_modes(out):
    with open(os.path.join(out, "summary.json")) as f:
        frequencies = json.load(f)["modes"]["frequencies_hz"]
    modes = vtu.read_pvd(os.path.join(out, "modes.pvd"))
    check(len(modes) == len(frequencies), f"{len(modes)} mode files for {len(frequencies)} modes")
    for (number, name), frequency in zip(modes, frequencies):
        v = read(os.path.join(out, name))
        check(abs(v["fields"]["frequency_Hz"] - frequency) <= 1e-12 * frequency, f"{name}: frequency")
        size = model_size(v)
        largest = max(math.hypot(*p) for p in v["data"]["displacement"])
        check(abs(largest - 0.05 * size) <= 1e-12 * size, f"{name}: largest translation {largest}")
    return len(modes)


poundfe, inputs = sys.argv[1], sys.argv[2]
record = ("  set Number of modes = 6\nend", "  set Number of modes = 6\n"
          "  subsection Recorders\n    set Record = phase portrait\n  end\nend")
with tempfile.TemporaryDirectory() as work:
    prm = os.path.join(inputs, "3d-torsional-pair.prm")
    out = run(poundfe, prm, work, "frames",
              [("set Duration         = 6", "set Duration         = 4"),
               ("set VTU interval    = 0", "set VTU interval    = 0.01\n  set Plots = false"),
               record])
    # per building: storeys x ((nx+1)(ny+1) columns + nx(ny+1) + ny(nx+1) beams), 5 storeys, 2 x 2 bays
    members = 2 * 5 * (3 * 3 + 2 * 3 + 2 * 3)
    n, joints, corners, contact = check_frames(out, building_names(prm), members, 1)
    print(f"frames: {n} frames, {joints} joint and {corners} slab-corner motions checked, "
          f"{contact} gap-frames in contact")
    print(f"frames: {check_modes(run(poundfe, prm, work, 'modal', [], 'modal'))} modes")
    prm = os.path.join(inputs, "3d-torsional-shear-pair.prm")
    out = run(poundfe, prm, work, "shear",
              [("set Duration         = 6", "set Duration         = 1"),
               ("set VTU interval    = 0", "set VTU interval    = 0.1\n  set Plots = false"),
               ("set Output interval = 0.01", "set Output interval = 0.005\n"
                "  subsection Recorders\n    set Record = phase portrait\n  end")])
    n, joints, corners, contact = check_shear(out, building_names(prm), 3 + 2)
    print(f"shear buildings: {n} frames, {corners} slab-corner motions checked")
    print(f"shear buildings: {check_irregularity(out, building_names(prm))} ratios "
          "Δmax/Δavg at the peak checked")
for f in failures[:20]:
    print("FAIL", f)
print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
