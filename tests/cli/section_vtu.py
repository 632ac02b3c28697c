#!/usr/bin/env python3
"""The fibre members' section states in the VTU output of `run`, read back and
checked against the section states recorder (sections.csv) of the same run:

  usage: section_vtu.py POUNDFE FIBRE.prm

- one vertex cell (kind 7) per integration point of every fibre member, its
  point on its member's line at the rule's place (Gauss-Lobatto ends on the
  member's end points, shared: no duplicated point), `integration_point`
  1-based along the member;
- at every frame, section_N, section_M, axial_strain, curvature,
  concrete_strain, steel_strain_max and steel_strain_min of each point are
  sections.csv's values at the frame's time, exactly (the same doubles: both
  outputs take them from one function, and the CSV's shortest form reads
  back exactly); every other cell holds 0;
- at every frame, the end forces of each fibre member's cell (N_start ...
  M_end) are member_forces.csv's at that time, exactly: both are the
  member's element's own resisting forces in its local axes, not the
  elastic K u; the run cracks its members (a bar strain beyond 1e-3, eight
  times the concrete's cracking strain), where the two differ;
- when ParaView's pvpython is installed, the last frame is opened by
  ParaView's own reader (XMLUnstructuredGridReader) and the arrays it sees
  compared with this reader's (exact).
"""
import os
import shutil
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu  # noqa: E402  (read_vtu: Python's XML parser, base64 and zlib)

NAMES = ["section_N", "section_M", "axial_strain", "curvature", "concrete_strain",
         "steel_strain_max", "steel_strain_min"]
COLUMNS = ["_N_N", "_M_N_m", "_eps0", "_kappa_1_m", "_concrete_strain", "_steel_strain_max",
           "_steel_strain_min"]
PARAVIEW = """
import sys
from paraview.simple import XMLUnstructuredGridReader
from paraview import servermanager
from vtk.numpy_interface import dataset_adapter as dsa
reader = XMLUnstructuredGridReader(FileName=[sys.argv[1]])
reader.UpdatePipeline()
data = dsa.WrapDataObject(servermanager.Fetch(reader))
for name in sys.argv[2:]:
    print(name, " ".join(repr(float(x)) for x in data.CellData[name]))
"""


def check_frame(name, v, header, row, failures):
    kind = v["cell"]["kind"]
    sections = [c for c in range(len(kind)) if kind[c] == 7]
    if 7 * len(sections) != len(row):
        failures.append(f"{name}: {len(sections)} section cells, {len(row) // 7} in sections.csv")
        return sections
    for p, c in enumerate(sections):
        label = header[1 + 7 * p]
        number = int(label[:-len(COLUMNS[0])].rsplit("_ip", 1)[1])
        if v["cell"]["integration_point"][c] != number:
            failures.append(f"{name}: cell {c} is point {v['cell']['integration_point'][c]}, "
                            f"sections.csv's column {label}")
        for k, array in enumerate(NAMES):
            if header[1 + 7 * p + k] != label[:-len(COLUMNS[0])] + COLUMNS[k]:
                failures.append(f"sections.csv: column {header[1 + 7 * p + k]}")
            if v["cell"][array][c] != row[7 * p + k]:
                failures.append(f"{name}: {array} of cell {c} ({label[:-len(COLUMNS[0])]}) "
                                f"{v['cell'][array][c]} against sections.csv's {row[7 * p + k]}")
    for array in NAMES:
        off = [c for c in range(len(kind)) if kind[c] != 7 and v["cell"][array][c] != 0]
        if off:
            failures.append(f"{name}: {array} nonzero on cells {off[:5]}")
    return sections


END_FORCES = ["N_start", "V_start", "M_start", "N_end", "V_end", "M_end"]
FORCE_COLUMNS = ["_N1_N", "_V1_N", "_M1_N_m", "_N2_N", "_V2_N", "_M2_N_m"]


def member_labels():
    """The members of input/fibre-frame-pounding.prm: two one-bay frames,
    A of four storeys and B of three."""
    return [f"{b}_{kind}{s}.{line}" for b, storeys in (("A", 4), ("B", 3))
            for s in range(1, storeys + 1) for kind, line in (("C", 1), ("C", 2), ("B", 1))]


def check_end_forces(name, v, header, sections, forces, failures):
    """The end forces of each fibre member's cell against member_forces.csv."""
    header_forces, row = forces
    kind, members, buildings = v["cell"]["kind"], v["cell"]["member"], v["cell"]["building"]
    checked = set()
    for p, c in enumerate(sections):
        label = header[1 + 7 * p][:-len(COLUMNS[0])].rsplit("_ip", 1)[0]
        if label in checked:
            continue
        checked.add(label)
        cells = [e for e in range(len(kind)) if kind[e] == 0 and members[e] == members[c]
                 and buildings[e] == buildings[c]]
        if len(cells) != 1 or label + FORCE_COLUMNS[0] not in header_forces:
            failures.append(f"{name}: member {label}: cells {cells}, or not in member_forces.csv")
            continue
        for k, array in enumerate(END_FORCES):
            expected = row[header_forces.index(label + FORCE_COLUMNS[k]) - 1]
            if v["cell"][array][cells[0]] != expected:
                failures.append(f"{name}: {array} of {label} {v['cell'][array][cells[0]]} "
                                f"against member_forces.csv's {expected}")
    return len(checked)


def check_places(v, sections, failures):
    """Each section point lies on its member's line; end points are shared."""
    kind, members, buildings = v["cell"]["kind"], v["cell"]["member"], v["cell"]["building"]
    lines = {(buildings[c], members[c]): v["cells"][c] for c in range(len(kind)) if kind[c] == 0}
    for c in sections:
        line = lines[(buildings[c], members[c])]
        a, b, p = v["xyz"][line[0]], v["xyz"][line[-1]], v["xyz"][v["cells"][c][0]]
        cross = (b[0] - a[0]) * (p[1] - a[1]) - (b[1] - a[1]) * (p[0] - a[0])
        along = ((p[0] - a[0]) * (b[0] - a[0]) + (p[1] - a[1]) * (b[1] - a[1])) / \
            ((b[0] - a[0]) ** 2 + (b[1] - a[1]) ** 2)
        if abs(cross) > 1e-9 or not -1e-12 <= along <= 1 + 1e-12:
            failures.append(f"section cell {c}: point {p} off its member {a}-{b}")
        ends = {1: line[0], 4: line[-1]}  # Lobatto, 4 points: the first and last are the ends
        n = v["cell"]["integration_point"][c]
        if n in ends and v["cells"][c][0] != ends[n]:
            failures.append(f"section cell {c}: point {n} not the member's end point")


def check_paraview(path, v, failures):
    pvpython = shutil.which("pvpython")
    if pvpython is None:
        return "pvpython not installed: ParaView's reader not checked"
    command = [pvpython, "--force-offscreen-rendering", "-c", PARAVIEW, path] + NAMES
    if shutil.which("xvfb-run"):
        command = ["xvfb-run", "-a"] + command
    out = subprocess.run(command, capture_output=True, text=True)
    seen = {line.split()[0]: [float(x) for x in line.split()[1:]]
            for line in out.stdout.splitlines() if line.split() and line.split()[0] in NAMES}
    for array in NAMES:
        if seen.get(array) != v["cell"][array]:
            failures.append(f"ParaView's reader: {array} differs or missing ({out.stderr[-300:]})")
    return f"ParaView's reader: {len(seen)} section arrays of {len(v['cell']['kind'])} cells"


def main():
    poundfe, prm = sys.argv[1], sys.argv[2]
    failures = []
    with tempfile.TemporaryDirectory() as work:
        out = os.path.join(work, "run")
        subprocess.run([poundfe, "run", prm, "--output", out, "--set", "Output/Plots=false",
                        "--set", "Output/VTU interval=0.5", "--set", "Output/Output interval=0",
                        "--set", "Ground motion/Stochastic/Duration=3",
                        "--set", "Output/Recorders/Record=section states; member end forces of "
                        + ", ".join(member_labels())],
                       check=True, stdout=subprocess.DEVNULL)
        header, rows = vtu.read_csv(os.path.join(out, "sections.csv"))
        header = open(os.path.join(out, "sections.csv")).readline().strip().split(",")
        forces_header, forces = vtu.read_csv(os.path.join(out, "member_forces.csv"))
        frames = vtu.read_pvd(os.path.join(out, "solution.pvd"))
        bending, cracked, n_members = 0, 0, 0
        for time, name in frames:
            v = vtu.read_vtu(os.path.join(out, name))
            if time not in rows:
                failures.append(f"{name}: no row of sections.csv at t = {time}")
                continue
            sections = check_frame(name, v, header, rows[time], failures)
            bending = max([bending] + [abs(v["cell"]["curvature"][c]) for c in sections])
            cracked = max([cracked] + [v["cell"]["steel_strain_max"][c] for c in sections])
            if time not in forces:
                failures.append(f"{name}: no row of member_forces.csv at t = {time}")
                continue
            n_members = check_end_forces(name, v, header, sections,
                                         (forces_header, forces[time]), failures)
        check_places(v, sections, failures)
        failures += vtu.failures
        paraview = check_paraview(os.path.join(out, frames[-1][1]), v, failures)
    if len(frames) < 4 or bending == 0:
        failures.append(f"{len(frames)} frames, largest curvature {bending}: nothing checked")
    if cracked <= 1e-3 or n_members != len(member_labels()):
        failures.append(f"largest bar strain {cracked}, {n_members} members' end forces: "
                        "no cracked member checked")
    for f in failures[:20]:
        print("FAIL", f)
    print(f"{len(frames)} frames, {len(sections)} integration points each, largest curvature "
          f"{bending:.3g} 1/m, largest bar strain {cracked:.3g}, end forces of {n_members} "
          f"members; {paraview}; {len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
