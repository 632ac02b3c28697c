# pelicun 3's DEMAND sample schema (pelicun/file_io.py load_data,
# model/demand_model.py load_sample), shared by the CLI tests of the demand
# tables: an index column with an empty header; column names
# "<event>-<type>-<location>-<direction>" (split at '-', 4 parts); a second
# row whose index is "Units" with a unit of pelicun's
# settings/default_units.json; then one row per realization, numbers only.
import csv
import math
import re

UNITS = {"rad", "unitless", "g", "mps2", "inps2", "m", "in", "mps", "inps", "N", "kN", "ea"}


def check_schema(path):
    """The column names (after the index) and the data rows of a table."""
    rows = list(csv.reader(open(path)))
    head, units, data = rows[0], rows[1], rows[2:]
    assert head[0] == "" and units[0] == "Units", path
    for h, u in zip(head[1:], units[1:]):
        assert re.fullmatch(r"1-[A-Z][A-Z0-9_.]*-[0-9]+-[0-9]+", h), h
        assert u in UNITS, u
    for i, row in enumerate(data):
        assert row[0] == str(i) and len(row) == len(head)
        assert all(math.isfinite(float(x)) for x in row[1:])
    return head[1:], data
