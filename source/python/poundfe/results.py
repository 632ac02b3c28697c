"""A run's results as NumPy arrays: the command line's own observers fill
them in memory (the recorders' tables as doubles, summary.json and the other
tables as the texts their files would hold), or they are read from the files
those observers wrote with output=: what Python gets is what `poundfe run`
writes, to the last digit."""

import csv
import io
import json
import os

import numpy as np


def _pandas():
    try:
        import pandas
    except ImportError as error:
        raise ImportError("to_dataframe needs pandas (apt-get install python3-pandas, or "
                          "pip install pandas); the arrays are in .tables without it") from error
    return pandas


def dataframe_of(table):
    """A Table or a structured array as a pandas DataFrame (its column names)."""
    pandas = _pandas()
    if isinstance(table, Table):
        return pandas.DataFrame(table.data, columns=table.names)
    frame = pandas.DataFrame({name: np.asarray(table[name]) for name in table.dtype.names})
    if isinstance(table, DemandTable):
        frame.attrs["units"] = dict(table.units)
    return frame


class Table:
    """A recorder's time series: `time` (s) and one column per name, e.g.
    drift["A3_storey1_drift_ratio"]; `values` is the 2-D array of every
    column but time (one row per recorded step)."""

    def __init__(self, names, data):
        self.names = list(names)          # the file's header, time_s first
        self.data = np.asarray(data, dtype=float).reshape(-1, len(self.names))

    @property
    def time(self):
        return self.data[:, 0]

    @property
    def columns(self):
        return self.names[1:]

    @property
    def values(self):
        return self.data[:, 1:]

    def __getitem__(self, name):
        try:
            return self.data[:, self.names.index(name)]
        except ValueError:
            raise KeyError(f"no column '{name}' (columns: {', '.join(self.columns)})") from None

    def __len__(self):
        return self.data.shape[0]

    def to_dataframe(self):
        """A pandas DataFrame, one column per name (ImportError without pandas)."""
        return dataframe_of(self)

    def __repr__(self):
        return f"<poundfe.Table {len(self)} rows x {len(self.columns)} columns>"


def _number_or_text(texts):
    """A column of a CSV table: float64 when every entry is a number or
    empty (an undefined value: NaN), text otherwise."""
    try:
        return np.array([float(t) if t != "" else np.nan for t in texts], dtype=float)
    except ValueError:
        return np.array(texts, dtype=str)


def structured(names, columns):
    """A structured array, one field per column (name, 1-D array)."""
    n = len(columns[0]) if columns else 0
    array = np.zeros(n, dtype=[(name, c.dtype) for name, c in zip(names, columns)])
    for name, column in zip(names, columns):
        array[name] = column
    return array


class DemandTable(np.ndarray):
    """A demand table in pelicun's demand-sample convention (demands_*.csv):
    a structured array, one float64 field per column ("index": the row
    number), and `units` {column: unit} from the file's units row, which is
    not a row of the array (to_dataframe keeps it as DataFrame.attrs["units"]).
    A column, table["1-PID-1-1"], is a plain float64 array: its reductions
    are NumPy float64 scalars (a Python float: json.dumps takes them)."""

    def __array_finalize__(self, obj):
        self.units = getattr(obj, "units", {})

    def __getitem__(self, key):
        # a field or a field's element is no longer a table: without this
        # view, numpy keeps the subclass and max() of a column is a 0-d table
        item = super().__getitem__(key)
        if isinstance(item, np.ndarray) and item.dtype.names is None:
            return item.view(np.ndarray)
        return item


def read_csv_text(text):
    """A CSV table's text with a header: a Table when its first column is
    time_s and every entry a number, otherwise a structured array (one field
    per column, numbers as float64, the rest as text). Blank lines (between
    the blocks of a gnuplot surface) and comment lines ('#', a resumable
    table's record of its inputs) are left out; a column without a name (a
    demand table's row number) is named "index", and a demand table's units
    row (its first row, "Units" under that column) becomes the DemandTable's
    units."""
    rows = [row for row in csv.reader(io.StringIO(text)) if row and not row[0].startswith("#")]
    # a pelicun demand table's first column, the row number, has no name
    names, rows = [name or "index" for name in rows[0]], rows[1:]
    if names[0] == "index" and rows and rows[0][0] == "Units":
        table = structured(names, [_number_or_text([row[i] for row in rows[1:]])
                                   for i in range(len(names))]).view(DemandTable)
        table.units = dict(zip(names[1:], rows[0][1:]))
        return table
    if names[0] == "time_s":
        try:
            return Table(names, [[float(x) for x in row] for row in rows])
        except ValueError:  # a column of text (a switching event's name)
            pass
    return structured(names, [_number_or_text([row[i] for row in rows])
                              for i in range(len(names))])


def read_csv(path):
    """A CSV file (see read_csv_text)."""
    with open(path, newline="") as f:
        return read_csv_text(f.read())


def memory_table(names, array):
    """A table kept in memory (rows x columns of float64) as read_csv_text
    would give its CSV: a Table when its first column is time_s, otherwise
    a structured array."""
    if names[0] == "time_s":
        return Table(names, array)
    return structured(names, [array[:, i] for i in range(len(names))])


def read_npy(path):
    """A recorder's NumPy table and its names (<stem>.columns.txt)."""
    with open(path[:-4] + ".columns.txt") as f:
        names = f.read().split("\n")
    return Table([n for n in names if n], np.load(path))


def _optional_array(raw, key):
    """raw[key] as an array, None when absent (a 2D model's y and θz)."""
    return np.array(raw[key]) if key in raw else None


class Modes:
    """Undamped modes (poundfe.modal, Results.modes): omega (rad/s),
    frequencies (Hz), periods (s), participating_mass_ratio (x), and for a
    3D model participating_mass_ratio_y and participating_mass_ratio_rz
    (None in 2D), shapes (mass-normalised, one column per mode, one row per
    equation named in `equations`: <building>_node<n>_ux, _uy, _rz, and in
    3D _uz, _rx, _ry of a joint, _hinge_ry, _hinge_rz of a hinge); `buildings`
    holds each building's own modes (with name, rayleigh_a0, rayleigh_a1)."""

    def __init__(self, raw):
        self.omega = np.array(raw["omega_rad_s"])
        self.frequencies = np.array(raw["frequencies_hz"])
        self.periods = np.array(raw["periods_s"])
        self.participating_mass_ratio = np.array(raw["participating_mass_ratio_x"])
        self.participating_mass_ratio_y = _optional_array(raw, "participating_mass_ratio_y")
        self.participating_mass_ratio_rz = _optional_array(raw, "participating_mass_ratio_rz")
        self.shapes = np.array(raw["shapes"])
        self.equations = raw.get("equations")
        self.name = raw.get("name")
        self.rayleigh = (raw["rayleigh_a0"], raw["rayleigh_a1"]) if "rayleigh_a0" in raw else None
        self.buildings = [Modes(b) for b in raw.get("buildings", [])]

    @classmethod
    def of_command(cls, result):
        """The Modes of `poundfe modal`'s CommandResult: summary.json's
        frequencies, periods and participations, mode_shapes.csv's omega and
        shapes (mode_shapes_<building>.csv each building's), so the same
        doubles as its files; the result's summary, status, report, files,
        tables and output kept as attributes."""
        summary = result.summary

        def raw(modes, table):
            names = list(table.dtype.names)[2:]  # after mode, omega_rad_s
            return dict(modes, omega_rad_s=table["omega_rad_s"], equations=names,
                        shapes=np.array([table[n] for n in names]).reshape(len(names), len(table)))

        whole = raw(summary["modes"], result.tables["mode_shapes"])
        whole["buildings"] = [
            dict(raw(b["modes"], result.tables["mode_shapes_" + b["name"]]), name=b["name"],
                 rayleigh_a0=b["rayleigh_a0"], rayleigh_a1=b["rayleigh_a1"])
            for b in summary["buildings"]]
        modes = cls(whole)
        for name in ("summary", "status", "report", "files", "tables", "output"):
            setattr(modes, name, getattr(result, name, None))
        return modes

    def to_dataframe(self):
        """One row per mode: frequency, period, participating mass ratio
        (ImportError without pandas)."""
        columns = {"frequency_hz": self.frequencies, "period_s": self.periods,
                   "participating_mass_ratio_x": self.participating_mass_ratio}
        if self.participating_mass_ratio_y is not None:
            columns["participating_mass_ratio_y"] = self.participating_mass_ratio_y
            columns["participating_mass_ratio_rz"] = self.participating_mass_ratio_rz
        return _pandas().DataFrame(columns)

    def __repr__(self):
        hz = ", ".join(f"{f:.4g}" for f in self.frequencies)
        return f"<poundfe.Modes {self.name or 'model'}: {hz} Hz>"


class Results:
    """A time history's results.

    status ("completed", "failed", "interrupted"), message, steps, end_time;
    series: {stem: Table} of every recorder (floor_displacement, drift,
    floor_acceleration, contact_force, hinges, energy, ground_motion, ... as
    the input's Output/Recorders ask), also as attributes (results.drift);
    impacts: the impact log, a structured array (gap, start_time_s, ...,
    peak_force_N, impulse_N_s: impacts.csv's columns);
    peaks: {building: {drift_ratio, floor_acceleration, floor_displacement,
    residual_drift_ratio (arrays per storey, along x), roof_displacement};
    a 3D model's also drift_ratio_y, floor_acceleration_y, floor_displacement_y,
    residual_drift_ratio_y, time_of_peak_drift_y, floor_rotation (rad) and
    floor_angular_acceleration (rad/s^2)};
    gaps: {label: summary.json's entry (impacts, peak_force_N, ...)};
    summary: summary.json as a dict; modes: Modes; tables: the other tables
    (drift_profile, acceleration_profile, residual_drift, ...).

    Made from a run in memory (raw["tables"], raw["texts"]) or from the
    files of `directory`."""

    def __init__(self, raw, directory=None):
        self.status = raw["status"]
        self.message = raw["message"]
        self.steps = raw["steps"]
        self.end_time = raw["end_time"]
        self.wall_time = raw["wall_time"]
        self.warnings = list(raw["warnings"])
        self.modes = Modes(raw["modes"])
        if directory is None:
            self.summary, found = self._in_memory(raw)
        else:
            self.summary, found = self._in_files(directory)
        self.series, self.tables = {}, {}
        for name in self.summary["output"]["files"]:
            stem = os.path.splitext(name)[0]
            table = found(name, stem)
            if table is not None:
                (self.series if isinstance(table, Table) else self.tables)[stem] = table
        self.impacts = self.tables.pop("impacts", None)
        self.peaks = {b["name"]: self._peaks_of(b) for b in self.summary["buildings"]}
        self.gaps = {g["label"]: g for g in self.summary.get("gaps", [])}

    @staticmethod
    def _in_memory(raw):
        """summary.json and a function giving a listed file's table."""
        tables = {stem: memory_table(names, array) for stem, names, array in raw["tables"]}
        texts = raw["texts"]

        def found(name, stem):
            if stem in tables:
                return tables[stem]
            if name.endswith(".csv") and name in texts:
                return read_csv_text(texts[name])
            return None

        return json.loads(texts["summary.json"]), found

    @staticmethod
    def _in_files(directory):
        with open(os.path.join(directory, "summary.json")) as f:
            summary = json.load(f)

        def found(name, stem):
            path = os.path.join(directory, name)
            if name.endswith(".npy"):
                return read_npy(path)
            if name.endswith(".csv"):
                return read_csv(path)
            return None

        return summary, found

    @staticmethod
    def _peaks_of(building):
        storeys = building["storeys"]

        def column(key):
            return np.array([s[key] for s in storeys], dtype=float)

        peaks = {"drift_ratio": column("peak_drift_ratio"),
                 "time_of_peak_drift": column("time_of_peak_drift_s"),
                 "residual_drift_ratio": column("residual_drift_ratio"),
                 "floor_acceleration": column("peak_absolute_floor_acceleration_m_s2"),
                 "floor_displacement": column("peak_floor_displacement_m"),
                 "roof_displacement": building["peak_roof_displacement_m"]}
        if storeys and "peak_drift_ratio_y" in storeys[0]:  # a 3D model: along y and about z
            peaks.update({"drift_ratio_y": column("peak_drift_ratio_y"),
                          "time_of_peak_drift_y": column("time_of_peak_drift_y_s"),
                          "residual_drift_ratio_y": column("residual_drift_ratio_y"),
                          "floor_acceleration_y": column("peak_absolute_floor_acceleration_y_m_s2"),
                          "floor_displacement_y": column("peak_floor_displacement_y_m"),
                          "floor_rotation": column("peak_floor_rotation_rad"),
                          "floor_angular_acceleration":
                              column("peak_floor_angular_acceleration_rad_s2")})
        return peaks

    def to_dataframe(self, name):
        """Series or table `name` as a pandas DataFrame (ImportError without
        pandas)."""
        _pandas()
        if name == "impacts" and self.impacts is not None:
            return dataframe_of(self.impacts)
        table = self.series.get(name, self.tables.get(name))
        if table is None:
            raise KeyError(f"no series or table '{name}' "
                           f"(series: {', '.join(self.series)}; tables: {', '.join(self.tables)})")
        return dataframe_of(table)

    @property
    def time(self):
        """The times of the default rows (Output/Output interval), s."""
        for table in self.series.values():
            return table.time
        return np.zeros(0)

    def __getattr__(self, name):
        series = self.__dict__.get("series", {})
        if name in series:
            return series[name]
        raise AttributeError(f"no attribute or recorded series '{name}' "
                             f"(series: {', '.join(series)})")

    def __repr__(self):
        return (f"<poundfe.Results {self.status}, {self.steps} steps to t = {self.end_time} s, "
                f"{0 if self.impacts is None else len(self.impacts)} impacts>")
