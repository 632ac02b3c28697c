#!/usr/bin/env python3
"""The VTU output of `run` and `modal` (theory §10), read with Python's own XML
parser, base64 and zlib, and checked against the run's other outputs and against beam theory:

  usage: vtu.py POUNDFE FILE.prm [FILE.prm ...]

(gaps and hinges are checked when the run has them; points inside elements
where neither end is hinged, which needs a model with such elements)

- structure: every DataArray holds points x components or cells x components
  values, offsets and connectivity agree, no two points coincide, the .pvd
  lists exactly the .vtu files written, with the frames' times;
- member end forces: each element is in equilibrium (no loads between its
  ends: N1 + N2 = 0, V1 + V2 = 0, M1 + M2 + V2 L = 0), to 1e-6 of the largest;
- points inside an element: the cubic Hermite interpolation of its end
  displacements, computed here independently (elements whose ends are not
  hinged, where the point's rotation is the element end's), to 1e-9 m;
- gaps: the contact force equals contact_force.csv's at the frame's time
  (the same doubles: exact) and `contact` is 1 exactly where it is > 0;
- hinges: the moment and z equal hinges.csv's (exact);
- modes: each file's frequency is summary.json's, and the largest
  translation is 5 % of the model's largest dimension (1e-12).
"""
import base64
import csv
import json
import math
import os
import struct
import subprocess
import sys
import tempfile
import xml.etree.ElementTree as ET
import zlib

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


COMPRESSED = [False]  # the file being read declares vtkZLibDataCompressor


def arrays(section):
    out = {}
    if section is None:
        return out
    for a in section.findall("DataArray"):
        out[a.get("Name")] = (int(a.get("NumberOfComponents", "1")), decode(a))
    return out


FORMATS = {"Float64": "d", "Int64": "q", "Int32": "i", "UInt8": "B"}


def decode(array):
    """A DataArray's values: ascii, or VTK's compressed binary (base64 of the
    UInt64 header {blocks, block size, last block size, compressed sizes...}
    then base64 of the zlib blocks)."""
    kind, text = array.get("type"), (array.text or "").strip()
    if array.get("format") == "ascii":
        return [int(v) if kind.startswith(("Int", "UInt")) else float(v) for v in text.split()]
    check(COMPRESSED[0], f"array {array.get('Name')}: binary, but the file declares no compressor")
    n_blocks = struct.unpack("<Q", base64.b64decode(text[:12])[:8])[0]
    header_chars = 4 * math.ceil(8 * (3 + n_blocks) / 3)
    header = struct.unpack(f"<{3 + n_blocks}Q", base64.b64decode(text[:header_chars]))
    raw = zlib.decompress(base64.b64decode(text[header_chars:]))
    check(len(raw) == header[1] * (n_blocks - 1) + (header[2] or header[1]),
          f"array {array.get('Name')}: {len(raw)} bytes against its header {header}")
    code = FORMATS[kind]
    return list(struct.unpack(f"<{len(raw) // struct.calcsize(code)}{code}", raw))


def read_vtu(path):
    root = ET.parse(path).getroot()
    check(root.get("header_type") == "UInt64" and root.get("byte_order") == "LittleEndian",
          f"{path}: header type or byte order")
    COMPRESSED[0] = root.get("compressor") == "vtkZLibDataCompressor"
    grid = root.find("UnstructuredGrid")
    piece = grid.find("Piece")
    n_points, n_cells = int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))
    fields = {k: v[1][0] for k, v in arrays(grid.find("FieldData")).items()}
    points = arrays(piece.find("Points"))["Points"][1]
    cells = arrays(piece.find("Cells"))
    point_data = arrays(piece.find("PointData"))
    cell_data = arrays(piece.find("CellData"))
    for name, (nc, values) in point_data.items():
        check(len(values) == nc * n_points, f"{path}: point data {name} has {len(values)} values")
    for name, (nc, values) in cell_data.items():
        check(len(values) == nc * n_cells, f"{path}: cell data {name} has {len(values)} values")
    check(len(points) == 3 * n_points, f"{path}: {len(points)} point coordinates")
    offsets, connectivity = cells["offsets"][1], cells["connectivity"][1]
    check(len(offsets) == n_cells and offsets[-1] == len(connectivity), f"{path}: offsets")
    check(all(0 <= c < n_points for c in connectivity), f"{path}: connectivity out of range")
    xyz = [tuple(points[3 * i:3 * i + 3]) for i in range(n_points)]
    check(len(set(xyz)) == n_points, f"{path}: {n_points - len(set(xyz))} duplicated points")
    cell_points = [connectivity[(offsets[c - 1] if c else 0):offsets[c]] for c in range(n_cells)]
    return dict(fields=fields, xyz=xyz, cells=cell_points,
                point={k: v[1] for k, v in point_data.items()},
                cell={k: v[1] for k, v in cell_data.items()})


def read_pvd(path):
    root = ET.parse(path).getroot()
    return [(float(d.get("timestep")), d.get("file")) for d in root.iter("DataSet")]


def read_csv(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], {float(r[0]): [float(x) for x in r[1:]] for r in rows[1:]}


def hermite(xyz0, xyz1, d0, d1, xi):
    """Global (ux, uy) at xi from end displacements (ux, uy, rz): axial linear,
    transverse cubic Hermite in the element's axes."""
    dx, dy = xyz1[0] - xyz0[0], xyz1[1] - xyz0[1]
    L = math.hypot(dx, dy)
    c, s = dx / L, dy / L
    u1, v1 = c * d0[0] + s * d0[1], -s * d0[0] + c * d0[1]
    u2, v2 = c * d1[0] + s * d1[1], -s * d1[0] + c * d1[1]
    u = (1 - xi) * u1 + xi * u2
    v = ((1 - 3 * xi**2 + 2 * xi**3) * v1 + (xi - 2 * xi**2 + xi**3) * L * d0[2]
         + (3 * xi**2 - 2 * xi**3) * v2 + (xi**3 - xi**2) * L * d1[2])
    return c * u - s * v, s * u + c * v


def check_file(poundfe, prm, work):
    out = os.path.join(work, "run")
    subprocess.run([poundfe, "run", prm, "--output", out], check=True, stdout=subprocess.DEVNULL)
    subprocess.run([poundfe, "modal", prm, "--output", os.path.join(work, "modal")], check=True,
                   stdout=subprocess.DEVNULL)

    # -- the time history --------------------------------------------------------
    frames = read_pvd(os.path.join(out, "solution.pvd"))
    written = sorted(os.listdir(os.path.join(out, "solution")))
    check(sorted(os.path.basename(f) for _, f in frames) == written,
          "solution.pvd does not list exactly the files in solution/")
    def read_if_there(name):
            path = os.path.join(out, name)
            return read_csv(path)[1] if os.path.exists(path) else None


    gap_rows, hinge_rows = read_if_there("contact_force.csv"), read_if_there("hinges.csv")
    n_interior_checked = n_contact_frames = n_elements = 0
    for time, name in frames:
        v = read_vtu(os.path.join(out, name))
        check(v["fields"]["TIME"] == time, f"{name}: TIME {v['fields']['TIME']} against the .pvd's {time}")
        kind, cell = v["cell"]["kind"], v["cell"]
        hinged_points = {v["cells"][c][0] for c in range(len(kind)) if kind[c] == 3}
        largest = max([abs(x) for k in ("N_start", "V_start", "M_start") for x in cell[k]] + [1.0])
        disp, rot = v["point"]["displacement"], v["point"]["rotation"]
        for c in (c for c in range(len(kind)) if kind[c] == 0):
            n_elements += 1
            pts = v["cells"][c]
            p0, p1 = v["xyz"][pts[0]], v["xyz"][pts[-1]]
            L = math.hypot(p1[0] - p0[0], p1[1] - p0[1])
            n1, v1, m1 = cell["N_start"][c], cell["V_start"][c], cell["M_start"][c]
            n2, v2, m2 = cell["N_end"][c], cell["V_end"][c], cell["M_end"][c]
            for residual in (n1 + n2, v1 + v2, m1 + m2 + v2 * L):
                check(abs(residual) <= 1e-6 * largest, f"{name}: element cell {c} not in equilibrium ({residual})")
            if pts[0] in hinged_points or pts[-1] in hinged_points:
                continue
            d0 = disp[3 * pts[0]:3 * pts[0] + 2] + [rot[pts[0]]]
            d1 = disp[3 * pts[-1]:3 * pts[-1] + 2] + [rot[pts[-1]]]
            for k, p in enumerate(pts[1:-1], start=1):
                xi = k / (len(pts) - 1)
                ux, uy = hermite(p0, p1, d0, d1, xi)
                check(abs(ux - disp[3 * p]) < 1e-9 and abs(uy - disp[3 * p + 1]) < 1e-9,
                      f"{name}: interior point {p} ({disp[3 * p]}, {disp[3 * p + 1]}) against Hermite ({ux}, {uy})")
                n_interior_checked += 1
        gaps = [c for c in range(len(kind)) if kind[c] == 2]
        forces = gap_rows[time][0::2] if gap_rows else []
        check(len(gaps) == len(forces), f"{name}: {len(gaps)} gap cells, {len(forces)} in contact_force.csv")
        for g, f in zip(gaps, forces):
            check(cell["force"][g] == f, f"{name}: gap force {cell['force'][g]} against contact_force.csv's {f}")
            check(cell["contact"][g] == (1 if f > 0 else 0), f"{name}: contact flag {cell['contact'][g]} with force {f}")
            n_contact_frames += cell["contact"][g]
        hinges = [c for c in range(len(kind)) if kind[c] == 3]
        row = hinge_rows[time] if hinge_rows else []
        check(3 * len(hinges) == len(row), f"{name}: {len(hinges)} hinge cells, {len(row) // 3} in hinges.csv")
        for h, c in enumerate(hinges):
            check(cell["force"][c] == row[3 * h] and cell["z"][c] == row[3 * h + 2],
                  f"{name}: hinge {h} moment/z {cell['force'][c]}/{cell['z'][c]} against hinges.csv {row[3 * h]}/{row[3 * h + 2]}")
    check(n_interior_checked > 0 or hinge_rows or n_elements == 0, "no interior point checked")

    # -- the modes ---------------------------------------------------------------
    modal = os.path.join(work, "modal")
    with open(os.path.join(modal, "summary.json")) as f:
        frequencies = json.load(f)["modes"]["frequencies_hz"]
    modes = read_pvd(os.path.join(modal, "modes.pvd"))
    check(len(modes) == len(frequencies), f"{len(modes)} mode files for {len(frequencies)} modes")
    for (number, name), frequency in zip(modes, frequencies):
        v = read_vtu(os.path.join(modal, name))
        check(v["fields"]["mode"] == number, f"{name}: mode {v['fields']['mode']}")
        check(abs(v["fields"]["frequency_Hz"] - frequency) <= 1e-12 * frequency,
              f"{name}: frequency {v['fields']['frequency_Hz']} against summary.json's {frequency}")
        xs, ys = [p[0] for p in v["xyz"]], [p[1] for p in v["xyz"]]
        size = max(max(xs) - min(xs), max(ys) - min(ys))
        d = v["point"]["displacement"]
        largest = max(math.hypot(d[3 * i], d[3 * i + 1]) for i in range(len(xs)))
        check(abs(largest - 0.05 * size) <= 1e-12 * size, f"{name}: largest translation {largest}, size {size}")
    print(f"{os.path.basename(prm)}: {len(frames)} frames, {n_interior_checked} interior points, "
          f"{n_contact_frames} gap-frames in contact, {len(modes)} modes")


if __name__ == "__main__":  # tests/cli/vtu_3d.py imports the readers
    poundfe = sys.argv[1]
    for prm in sys.argv[2:]:
        with tempfile.TemporaryDirectory() as work:
            check_file(poundfe, prm, work)
    for f in failures[:20]:
        print("FAIL", f)
    print(f"{len(failures)} failures")
    sys.exit(1 if failures else 0)
