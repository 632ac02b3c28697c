#!/usr/bin/env python3
"""The HDF5 + XDMF field output (Output/Field format = xdmf) against the VTU
output of the same input (the default format), a 2D and a 3D model:

  usage: xdmf.py POUNDFE INPUT_DIR
         xdmf.py --compare DIR NAME   (DIR/xdmf/NAME.xdmf + .h5 against DIR/vtu/NAME.pvd)
         xdmf.py --complete DIR       (DIR/solution.xdmf names every frame of solution.h5)

The last two serve other tests (cli/partitioned-run: the ranks' HDF5 file
written together against rank 0's VTU frames of the same run).

The .h5 file is read back by a second method, independent of the writer:
the HDF5 C library called from Python (ctypes; the datasets found by walking
the groups, read with H5Dread converting to double, which is exact for the
int32/int64 arrays), and the VTU files by tests/cli/vtu.py's XML, base64 and
zlib readers.

- every array of every VTU frame (field, point and cell data, the points,
  connectivity, offsets and types) equals the .h5's (1e-12 of the array's
  largest magnitude: both are the same doubles, so in fact exact), and the
  .h5 holds no array the VTU has not; integers are stored as integers;
- the XDMF file is well-formed XML (Python's parser): Xdmf Version 3.0, one
  temporal collection of uniform grids, one per PVD entry, whose Time values
  equal the PVD timesteps (exact: both the shortest round-trip text); every
  DataItem is Format HDF, names a dataset of the .h5 whose dimensions and
  number type it gives; Node attributes have a row per point, Cell attributes
  a row per cell; the Mixed topology decoded (XDMF 3: type, number of points,
  indices) gives the VTU cells, with Polyvertex for a vertex, Polyline for a
  line or poly-line and Polygon for a polygon, and NumberOfElements cells;
- modal (2D): modes.xdmf/modes.h5 against modes.pvd the same way;
- a command that writes no fields (spectrum) refuses xdmf: exit 1, the
  message names Output/Field format, nothing written;
- no temporary (*.tmp) is left, and the manifest lists solution.h5 and
  solution.xdmf;
- a long 2D run stopped by SIGINT after half a second exits 130 with summary.json
  "interrupted", solution.h5 and solution.xdmf in place, as many grids as
  frame groups, the last frame's time not after the summary's end time.
"""
import ctypes
import ctypes.util
import json
import os
import signal
import subprocess
import sys
import tempfile
import time
import xml.etree.ElementTree as ET

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import vtu  # noqa: E402  (the readers; its own checks run only as a script)

failures = vtu.failures
check = vtu.check
TOLERANCE = 1e-12


# -- HDF5 through its C library ------------------------------------------------
def load_hdf5():
    for name in ("hdf5_openmpi", "hdf5_serial", "hdf5"):
        path = ctypes.util.find_library(name)
        if path:
            return ctypes.CDLL(path)
    for path in ("/usr/lib/x86_64-linux-gnu/hdf5/openmpi/libhdf5.so",
                 "/usr/lib/x86_64-linux-gnu/hdf5/serial/libhdf5.so"):
        if os.path.exists(path):
            return ctypes.CDLL(path)
    sys.exit("xdmf.py: no HDF5 C library found")


H5 = load_hdf5()
hid_t, herr_t, hsize_t = ctypes.c_int64, ctypes.c_int, ctypes.c_ulonglong
H5.H5open()
H5.H5Eset_auto2.argtypes = [ctypes.c_int64, ctypes.c_void_p, ctypes.c_void_p]
H5.H5Eset_auto2(0, None, None)  # H5E_DEFAULT: a failed open (a group) prints nothing
for function, restype in (("H5Fopen", hid_t), ("H5Gopen2", hid_t), ("H5Dopen2", hid_t),
                          ("H5Dget_space", hid_t), ("H5Dget_type", hid_t),
                          ("H5Lget_name_by_idx", ctypes.c_ssize_t)):
    getattr(H5, function).restype = restype
H5.H5Fopen.argtypes = [ctypes.c_char_p, ctypes.c_uint, hid_t]
H5.H5Gopen2.argtypes = H5.H5Dopen2.argtypes = [hid_t, ctypes.c_char_p, hid_t]
for function in ("H5Fclose", "H5Gclose", "H5Dclose", "H5Sclose", "H5Tclose", "H5Dget_space",
                 "H5Dget_type", "H5Tget_class", "H5Tget_size", "H5Sget_simple_extent_ndims"):
    getattr(H5, function).argtypes = [hid_t]
H5.H5Sget_simple_extent_dims.argtypes = [hid_t, ctypes.POINTER(hsize_t), ctypes.c_void_p]
H5.H5Dread.argtypes = [hid_t, hid_t, hid_t, hid_t, hid_t, ctypes.c_void_p]
H5.H5Lget_name_by_idx.argtypes = [hid_t, ctypes.c_char_p, ctypes.c_int, ctypes.c_int, hsize_t,
                                  ctypes.c_char_p, ctypes.c_size_t, hid_t]
NATIVE_DOUBLE = hid_t.in_dll(H5, "H5T_NATIVE_DOUBLE_g").value
H5T_INTEGER, H5T_FLOAT = 0, 1


class GroupInfo(ctypes.Structure):
    _fields_ = [("storage_type", ctypes.c_int), ("nlinks", hsize_t),
                ("max_corder", ctypes.c_int64), ("mounted", ctypes.c_bool)]


H5.H5Gget_info.argtypes = [hid_t, ctypes.POINTER(GroupInfo)]


def read_h5(path):
    """{dataset path: (dimensions, 'int' or 'float', element size, flat values)}
    of every dataset, found by walking the groups from the root."""
    out = {}
    f = H5.H5Fopen(path.encode(), 0, 0)  # H5F_ACC_RDONLY, H5P_DEFAULT
    check(f >= 0, f"{path}: HDF5 cannot open it")
    if f < 0:
        return out

    def walk(group_path):
        group = H5.H5Gopen2(f, group_path.encode(), 0)
        info = GroupInfo()
        H5.H5Gget_info(group, ctypes.byref(info))
        names = []
        for i in range(info.nlinks):
            buffer = ctypes.create_string_buffer(256)
            H5.H5Lget_name_by_idx(group, b".", 0, 0, i, buffer, 256, 0)
            names.append(buffer.value.decode())
        H5.H5Gclose(group)
        for name in names:
            child = group_path.rstrip("/") + "/" + name
            dataset = H5.H5Dopen2(f, child.encode(), 0)
            if dataset < 0:  # a group
                walk(child)
                continue
            space, kind = H5.H5Dget_space(dataset), H5.H5Dget_type(dataset)
            rank = H5.H5Sget_simple_extent_ndims(space)
            dims = (hsize_t * max(rank, 1))()
            H5.H5Sget_simple_extent_dims(space, dims, None)
            shape = tuple(dims[i] for i in range(rank))
            n = 1
            for d in shape:
                n *= d
            values = (ctypes.c_double * max(n, 1))()
            status = H5.H5Dread(dataset, NATIVE_DOUBLE, 0, 0, 0, values)  # H5S_ALL, H5P_DEFAULT
            check(status >= 0, f"{path}:{child}: H5Dread failed")
            type_class = H5.H5Tget_class(kind)
            out[child] = (shape, "int" if type_class == H5T_INTEGER else "float",
                          H5.H5Tget_size(kind), list(values)[:n])
            for close, handle in ((H5.H5Tclose, kind), (H5.H5Sclose, space),
                                  (H5.H5Dclose, dataset)):
                close(handle)

    walk("/")
    H5.H5Fclose(f)
    return out


# -- VTU, raw ------------------------------------------------------------------
def read_vtu_raw(path):
    """Every array of a VTU file: {(section, name): (components, values)}."""
    root = ET.parse(path).getroot()
    vtu.COMPRESSED[0] = root.get("compressor") == "vtkZLibDataCompressor"
    grid = root.find("UnstructuredGrid")
    piece = grid.find("Piece")
    out = {}
    for section, element in (("Grid", grid.find("FieldData")), ("Points", piece.find("Points")),
                             ("Cells", piece.find("Cells")), ("Node", piece.find("PointData")),
                             ("Cell", piece.find("CellData"))):
        for name, value in vtu.arrays(element).items():
            out[(section, name)] = value
    return out, int(piece.get("NumberOfPoints")), int(piece.get("NumberOfCells"))


def same(a, b):
    scale = max([abs(x) for x in a] + [1e-300])
    return len(a) == len(b) and all(abs(x - y) <= TOLERANCE * scale for x, y in zip(a, b))


VTK_OF_XDMF = {1: {1}, 2: {3, 4}, 3: {7}}  # Polyvertex, Polyline, Polygon
INTEGER_ARRAYS = {"kind", "building", "member", "node", "contact"}


def decode_mixed(topology, n_cells):
    cells, types, i = [], [], 0
    while i < len(topology):
        kind, n = int(topology[i]), int(topology[i + 1])
        types.append(kind)
        cells.append([int(c) for c in topology[i + 2:i + 2 + n]])
        i += 2 + n
    check(len(cells) == n_cells, f"Mixed topology: {len(cells)} cells, NumberOfElements {n_cells}")
    return cells, types


def check_series(directory, name):
    """<name>.xdmf and <name>.h5 against <name>.pvd's VTU files in directory/vtu."""
    frames = vtu.read_pvd(os.path.join(directory, "vtu", name + ".pvd"))
    xdmf_dir = os.path.join(directory, "xdmf")
    h5 = read_h5(os.path.join(xdmf_dir, name + ".h5"))
    root = ET.parse(os.path.join(xdmf_dir, name + ".xdmf")).getroot()  # well-formed XML
    check(root.tag == "Xdmf" and root.get("Version") == "3.0", "Xdmf root or version")
    collection = root.find("Domain").find("Grid")
    check(collection.get("GridType") == "Collection" and
          collection.get("CollectionType") == "Temporal", "not a temporal collection")
    grids = collection.findall("Grid")
    check(len(grids) == len(frames), f"{len(grids)} XDMF grids, {len(frames)} PVD entries")
    used = set()
    n_arrays = 0
    for (time, file), grid in zip(frames, grids):
        check(grid.get("GridType") == "Uniform", f"{grid.get('Name')}: not uniform")
        check(float(grid.find("Time").get("Value")) == time,
              f"{grid.get('Name')}: Time {grid.find('Time').get('Value')}, PVD {time}")
        v, n_points, n_cells = read_vtu_raw(os.path.join(directory, "vtu", file))

        def item(element, rows):
            d = element.find("DataItem")
            check(d.get("Format") == "HDF", f"{file}: DataItem format {d.get('Format')}")
            h5_file, path = d.text.strip().split(":")
            check(h5_file == name + ".h5", f"{file}: DataItem names {h5_file}")
            check(path in h5, f"{file}: {path} is not in the .h5")
            if path not in h5:
                return path, (), []
            shape, kind, size, values = h5[path]
            dims = tuple(int(x) for x in d.get("Dimensions").split())
            check(dims == shape, f"{path}: XDMF dimensions {dims}, HDF5 {shape}")
            check(rows is None or shape[0] == rows, f"{path}: {shape[0]} rows, {rows} expected")
            check(d.get("NumberType") == ("Int" if kind == "int" else "Float") and
                  int(d.get("Precision")) == size, f"{path}: number type or precision")
            used.add(path)
            return path, shape, values

        _, _, xyz = item(grid.find("Geometry"), n_points)
        check(grid.find("Geometry").get("GeometryType") == "XYZ", "geometry type")
        check(same(v[("Points", "Points")][1], xyz), f"{file}: points")
        topology = grid.find("Topology")
        check(topology.get("TopologyType") == "Mixed" and
              int(topology.get("NumberOfElements")) == n_cells, f"{file}: topology")
        _, _, mixed = item(topology, None)
        cells, types = decode_mixed(mixed, n_cells)
        offsets, connectivity = v[("Cells", "offsets")][1], v[("Cells", "connectivity")][1]
        vtk_cells = [connectivity[(offsets[c - 1] if c else 0):offsets[c]] for c in range(n_cells)]
        check(cells == vtk_cells, f"{file}: the Mixed cells are not the VTU cells")
        check(all(t in VTK_OF_XDMF.get(x, ()) for x, t in zip(types, v[("Cells", "types")][1])),
              f"{file}: XDMF cell types against VTK types")
        for array in ("connectivity", "offsets", "types"):
            check(same(v[("Cells", array)][1], h5["/mesh/" + array][3]), f"{file}: /mesh/{array}")
            used.add("/mesh/" + array)
        seen = set()
        for attribute in grid.findall("Attribute"):
            key = (attribute.get("Center"), attribute.get("Name"))
            seen.add(key)
            check(key in v, f"{file}: XDMF attribute {key} is not in the VTU")
            if key not in v:
                continue
            n_components, values = v[key]
            rows = {"Node": n_points, "Cell": n_cells, "Grid": 1}[key[0]]
            path, shape, stored = item(attribute, rows)
            check(len(stored) == rows * n_components, f"{path}: {len(stored)} values")
            check(same(values, stored), f"{file}: {key} differs from {path}")
            check((h5[path][1] == "int") == (key[1] in INTEGER_ARRAYS) if path in h5 else True,
                  f"{path}: stored as {h5[path][1] if path in h5 else '?'}")
            n_arrays += 1
        missing = {k for k in v if k[0] in ("Grid", "Node", "Cell")} - seen
        check(not missing, f"{file}: VTU arrays without an XDMF attribute: {sorted(missing)}")
    check(set(h5) == used, f"{name}.h5: datasets no grid names: {sorted(set(h5) - used)}")
    return len(frames), n_arrays


def run(poundfe, prm, work, name, edits, command="run", fmt=None, expect=0):
    with open(prm) as f:
        text = f.read()
    for old, new in edits + ([("set VTU interval", f"set Field format = {fmt}\n  set VTU interval")]
                             if fmt else []):
        check(old in text, f"{prm}: no '{old}' to change")
        text = text.replace(old, new, 1)
    path = os.path.join(work, name + ".prm")
    with open(path, "w") as f:
        f.write(text)
    out = os.path.join(work, name)
    result = subprocess.run([poundfe, command, path, "--output", out], stdout=subprocess.DEVNULL,
                            stderr=subprocess.PIPE, text=True)
    check(result.returncode == expect, f"{command} {name}: exit {result.returncode}: {result.stderr}")
    return out, result.stderr


def both(poundfe, prm, work, name, edits, command="run"):
    base = os.path.join(work, name)
    os.makedirs(base)
    for fmt in ("vtu", "xdmf"):
        run(poundfe, prm, base, fmt, edits, command, fmt)
    return base


def no_temporaries(directory, files):
    left = [f for f in os.listdir(directory) if f.endswith(".tmp")]
    check(not left, f"{directory}: temporaries left: {left}")
    with open(os.path.join(directory, ".poundfe-files")) as f:
        listed = f.read().split()
    check(all(f in listed for f in files), f"{directory}: manifest lacks {files}")


def interrupted(poundfe, prm, work, edits):
    """A long run stopped by SIGINT half a second after it starts: exit 130, summary
    "interrupted", both files in place and consistent, the last frame's
    time at most the summary's end time."""
    out, path = os.path.join(work, "interrupted"), os.path.join(work, "interrupted.prm")
    with open(prm) as f:
        text = f.read()
    for old, new in edits:
        text = text.replace(old, new, 1)
    with open(path, "w") as f:
        f.write(text)
    job = subprocess.Popen([poundfe, "run", path, "--output", out], stdout=subprocess.DEVNULL,
                           stderr=subprocess.DEVNULL)
    for _ in range(1500):
        if os.path.isdir(out):
            break
        time.sleep(0.02)
    time.sleep(0.5)
    job.send_signal(signal.SIGINT)
    status = job.wait()
    check(status == 130, f"interrupted run: exit {status}")
    with open(os.path.join(out, "summary.json")) as f:
        summary = json.load(f)
    check(summary["status"] == "interrupted", f"interrupted run: status {summary['status']}")
    n_frames, last = complete(out)
    check(n_frames > 1, f"interrupted run: {n_frames} frames")
    end = summary["analysis"]["end_time_s"]
    check(last <= end < 2000, f"interrupted run: last frame {last}, end {end}")
    no_temporaries(out, ["solution.h5", "solution.xdmf"])
    return n_frames, last


def complete(directory):
    """solution.xdmf names every frame group of solution.h5, in order, and no *.tmp is
    left: the number of frames and the last frame's time."""
    grids = ET.parse(os.path.join(directory, "solution.xdmf")).getroot().find("Domain").find("Grid")
    times = [float(g.find("Time").get("Value")) for g in grids.findall("Grid")]
    h5 = read_h5(os.path.join(directory, "solution.h5"))
    frames = sorted({p.split("/")[2] for p in h5 if p.startswith("/frames/")})
    check(frames == ["%05d" % f for f in range(len(times))],
          f"{directory}: {len(times)} grids, frame groups {frames[:3]}...")
    check(times == sorted(times), f"{directory}: grid times not increasing")
    left = [f for f in os.listdir(directory) if f.endswith(".tmp")]
    check(not left, f"{directory}: temporaries left: {left}")
    return len(times), times[-1] if times else None


def report(what):
    print(what)
    for f in failures[:20]:
        print("FAIL", f)
    sys.exit(1 if failures else 0)


def main():
    if sys.argv[1] == "--compare":
        report("%d frames, %d arrays equal" % check_series(sys.argv[2], sys.argv[3]))
    if sys.argv[1] == "--complete":
        report("%d frames to t = %s s" % complete(sys.argv[2]))
    poundfe, inputs = sys.argv[1], sys.argv[2]
    with tempfile.TemporaryDirectory() as work:
        # 2D: two frames with hinges and gaps, 0.4 s, a frame every 0.02 s
        prm = os.path.join(inputs, "two-buildings.prm")
        edits = [("set Duration    = 20", "set Duration    = 0.4"),
                 ("set VTU interval    = 0.05", "set VTU interval    = 0.02\n  set Plots = false")]
        out = both(poundfe, prm, work, "2d", edits)
        print("2D run: %d frames, %d arrays equal" % check_series(out, "solution"))
        no_temporaries(os.path.join(out, "xdmf"), ["solution.h5", "solution.xdmf"])
        out = both(poundfe, prm, work, "2d-modal", edits, "modal")
        print("2D modal: %d modes, %d arrays equal" % check_series(out, "modes"))
        edits = [("subsection Time integration", "subsection Time integration\n  set End time = 2000"),
                 ("set VTU interval    = 0.05",
                  "set VTU interval    = 0.5\n  set Plots = false\n  set Field format = xdmf")]
        print("2D run interrupted: %d frames to t = %g s, files complete" %
              interrupted(poundfe, prm, work, edits))
        # 3D: frames with rigid diaphragms, hinges and plan contact, 0.3 s
        prm = os.path.join(inputs, "3d-torsional-pair.prm")
        edits = [("set Duration         = 6", "set Duration         = 0.3"),
                 ("set VTU interval    = 0", "set VTU interval    = 0.02\n  set Plots = false")]
        out = both(poundfe, prm, work, "3d", edits)
        print("3D run: %d frames, %d arrays equal" % check_series(out, "solution"))
        # refused where no fields are written
        out, message = run(poundfe, prm, work, "refused", [], "spectrum", "xdmf", expect=1)
        check("Output/Field format" in message and not os.path.exists(out),
              f"spectrum with xdmf: '{message.strip()}', output {os.path.exists(out)}")
    for f in failures[:20]:
        print("FAIL", f)
    print(f"{len(failures)} failures")
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
