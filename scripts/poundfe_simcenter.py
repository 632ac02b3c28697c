#!/usr/bin/env python3
"""poundfe as a SimCenter simulation application (EE-UQ, R2D: the
performSIMULATION step of SimCenterBackendApplications' workflow, in place of
OpenSeesSimulation or customPySimulation).

Command-line contract of SimCenter's simulation applications:
  poundfe_simcenter.py --filenameAIM AIM.json --filenameSAM SAM.json
      --filenameEVENT EVENT.json --filenameEDP EDP.json --filenameSIM SIM.json [--getRV]
(the options in any order).

--getRV: writes SIM.json ({}: poundfe draws no random variable of its own)
  and gives EDP.json the pounding demands of the model's gaps (types
  impact_count, max_impact_force, max_impact_velocity with "floor" and "gap",
  appended to the responses the EDP application wrote, total_number_edp
  updated); without an EDP.json it writes one with the standard earthquake
  EDPs of the building (those of createEDP/standardEarthquakeEDP:
  max_abs_acceleration at floors 0..n, max_rel_disp and max_drift at 1..n,
  max_roof_drift) plus residual_drift and the pounding ones.
Otherwise: runs the model on the event and fills every response's
  scalar_data in EDP.json (one number per dof, "NaN" for a demand the model
  has not got), and writes the same numbers, space-separated, to results.out.

SAM.json names the model: "mainScript" (a poundfe .prm) looked for in the
working directory, then in SAM's "modelPath", then in AIM's "commonFileDir"
(as customPySimulation does); "building" (optional) names the building whose
demands fill EDP.json (default: the first), "cline" = a building's name picks
another one for a response.

EVENT.json: Events[0]: "timeSeries" [{"type": "Value", "name", "dT", "data",
"factor"}], "pattern" [{"type": "UniformAcceleration", "timeSeries", "dof"}],
"factor", "units" {"length", "time"}: the acceleration is data x series factor
x event factor in length/time^2, in g when "units" is absent (as
OpenSeesPreprocessor assumes). dof 1 drives x; dof 2 y (Model/Dimension = 3).

The run is `poundfe run` with Output/Demand tables = true
(demands_<building>.csv, output/demand_table.h: pelicun's names), read back:
max_abs_acceleration = PFA, max_rel_disp = PFD (in the SAM's, else AIM
GeneralInformation's, length and time units: m and s by default), max_drift = PID, max_roof_drift = PRD, residual_drift = RID,
residual_disp = RFD, impact_count = NIMP, max_impact_force = PIMF (N),
max_impact_velocity = PIMV (m/s).

The poundfe binary: $POUNDFE, else build/poundfe next to this script's
folder, else `poundfe` on the PATH. Exit status: poundfe's (1: bad input, with
one message naming the file and the entry; nothing written).
"""

import json
import os
import shutil
import subprocess
import sys

G = 9.80665
LENGTH = {"m": 1.0, "meter": 1.0, "cm": 0.01, "centimeter": 0.01, "mm": 0.001,
          "millimeter": 0.001, "in": 0.0254, "inch": 0.0254, "ft": 0.3048, "foot": 0.3048}
TIME = {"sec": 1.0, "s": 1.0, "second": 1.0, "ms": 1e-3, "min": 60.0, "minute": 60.0}
# SimCenter's EDP types and the pelicun demand types of demands_<building>.csv
PELICUN = {"max_abs_acceleration": "PFA", "max_rel_disp": "PFD", "max_drift": "PID",
           "max_roof_drift": "PRD", "residual_drift": "RID", "residual_disp": "RFD",
           "impact_count": "NIMP", "max_impact_force": "PIMF", "max_impact_velocity": "PIMV"}
POUNDING = {"NIMP": "impact_count", "PIMF": "max_impact_force", "PIMV": "max_impact_velocity"}


class InputFault(Exception):
    """Bad input: (file, entry, problem)."""


def fail(path, entry, problem):
    raise InputFault(f"{path}: parameter '{entry}': {problem}")


def parse_arguments(argv):
    names = {"--filenameAIM": "aim", "--filenameSAM": "sam", "--filenameEVENT": "event",
             "--filenameEDP": "edp", "--filenameSIM": "sim"}
    files, get_rv, i = {}, False, 0
    while i < len(argv):
        if argv[i] == "--getRV":
            get_rv = True
        elif argv[i] in names and i + 1 < len(argv):
            files[names[argv[i]]] = argv[i + 1]
            i += 1
        else:
            raise InputFault(f"poundfe_simcenter.py: unknown argument '{argv[i]}' (expected "
                             "--filenameAIM, --filenameSAM, --filenameEVENT, --filenameEDP, "
                             "--filenameSIM and --getRV)")
        i += 1
    for key, option in (("aim", "--filenameAIM"), ("sam", "--filenameSAM"), ("edp", "--filenameEDP")):
        if key not in files:
            raise InputFault(f"poundfe_simcenter.py: {option} is missing")
    return files, get_rv


def read_json(path):
    try:
        with open(path, encoding="utf-8") as f:
            return json.load(f)
    except OSError as e:
        raise InputFault(f"{path}: cannot be read ({e.strerror})")
    except json.JSONDecodeError as e:
        raise InputFault(f"{path}:{e.lineno}: not JSON ({e.msg})")


def poundfe_binary():
    if os.environ.get("POUNDFE"):
        return os.environ["POUNDFE"]
    built = os.path.join(os.path.dirname(os.path.dirname(os.path.abspath(__file__))), "build", "poundfe")
    return built if os.path.exists(built) else (shutil.which("poundfe") or "poundfe")


def model_file(sam, sam_path, aim):
    script = sam.get("mainScript")
    if not isinstance(script, str) or not script:
        fail(sam_path, "mainScript", "names no poundfe parameter file (.prm)")
    for folder in (".", sam.get("modelPath"), aim.get("commonFileDir")):
        if isinstance(folder, str) and os.path.isfile(os.path.join(folder, script)):
            return os.path.abspath(os.path.join(folder, script))
    fail(sam_path, "mainScript", f"'{script}' is not in the working directory, modelPath or "
         "commonFileDir")


def event_series(event_path):
    """[(dof, dT, accelerations in m/s^2)] of EVENT.json's first event."""
    events = read_json(event_path).get("Events")
    if not isinstance(events, list) or not events:
        fail(event_path, "Events", "expected a list of one event or more")
    event = events[0]
    units = event.get("units")
    if units is None:
        to_si = G  # OpenSeesPreprocessor: no units, the data are in g
    else:
        length, time = units.get("length", "m"), units.get("time", "sec")
        if length not in LENGTH:
            fail(event_path, "Events[0].units.length", f"unknown length unit '{length}'")
        if time not in TIME:
            fail(event_path, "Events[0].units.time", f"unknown time unit '{time}'")
        to_si = LENGTH[length] / TIME[time] ** 2
    factor = float(event.get("factor", 1.0))
    series = {s.get("name"): s for s in event.get("timeSeries", [])}
    motions = []
    for k, pattern in enumerate(event.get("pattern", [])):
        where = f"Events[0].pattern[{k}]"
        if pattern.get("type") != "UniformAcceleration":
            fail(event_path, where + ".type", f"'{pattern.get('type')}': poundfe takes "
                 "UniformAcceleration patterns")
        dof = pattern.get("dof")
        if dof not in (1, 2):
            fail(event_path, where + ".dof", f"{dof}: poundfe takes the horizontal dofs 1 and 2")
        s = series.get(pattern.get("timeSeries"))
        if s is None or s.get("type", "Value") != "Value" or not s.get("data"):
            fail(event_path, where + ".timeSeries", f"'{pattern.get('timeSeries')}' names no "
                 "Value time series with data")
        dt = float(s.get("dT", 0))
        if not dt > 0:
            fail(event_path, "Events[0].timeSeries.dT", f"must be positive, got {dt}")
        scale = float(s.get("factor", 1.0)) * factor * to_si
        motions.append((dof, dt * TIME[units.get("time", "sec")] if units else dt,
                        [float(a) * scale for a in s["data"]]))
    if not any(dof == 1 for dof, _, _ in motions):
        fail(event_path, "Events[0].pattern", "no UniformAcceleration pattern on dof 1 (x)")
    return event.get("name", "event"), motions


def run_poundfe(prm, motions, directory):
    """`poundfe run` of the model on the motions; its demand tables' folder."""
    sets = {"Ground motion/Type": "record", "Ground motion/Scale factor": "1",
            "Ground motion/Components": str(len(motions)), "Output/Demand tables": "true",
            "Output/Plots": "false", "Output/VTU interval": "0"}
    for dof, dt, a in motions:
        path = os.path.abspath(f"poundfe_event_dof{dof}.txt")
        with open(path, "w") as f:
            f.write("".join(f"{x!r}\n" for x in a))
        if dof == 1:
            sets.update({"Ground motion/Record/File": path, "Ground motion/Record/Format": "text",
                         "Ground motion/Record/Units": "m/s^2",
                         "Ground motion/Record/Time step": repr(dt),
                         "Ground motion/Record/Target PGA": "0"})
        else:
            sets["Ground motion/Record/Second file"] = path
    command = [poundfe_binary(), "run", prm, "--output", directory]
    for key, value in sets.items():
        command += ["--set", f"{key}={value}"]
    done = subprocess.run(command, capture_output=True, text=True)
    if done.returncode != 0:  # nothing of this run stays
        sys.stderr.write(done.stderr)
        for dof, _, _ in motions:
            os.remove(f"poundfe_event_dof{dof}.txt")
        shutil.rmtree(directory, ignore_errors=True)
        raise SystemExit(done.returncode)
    return directory


def demand_tables(directory):
    """{building: {pelicun column name: (value, unit)}} of a run's tables."""
    tables = {}
    for name in sorted(os.listdir(directory)):
        if name.startswith("demands_") and name.endswith(".csv"):
            with open(os.path.join(directory, name)) as f:
                header, units, row = (line.rstrip("\n").split(",") for line in f.readlines()[:3])
            tables[name[len("demands_"):-len(".csv")]] = {
                h: (float(v), u) for h, u, v in zip(header[1:], units[1:], row[1:])}
    return tables


def building_of(sam, sam_path, directory):
    with open(os.path.join(directory, "summary.json")) as f:
        files = json.load(f)["output"]["files"]
    order = [f[len("demands_"):-len(".csv")] for f in files if f.startswith("demands_")]
    name = sam.get("building", order[0])
    if name not in order:
        fail(sam_path, "building", f"'{name}' is not a building of the model ({', '.join(order)})")
    return name


def unit_factors(sam, aim):
    """{pelicun type: factor} from the table's units (g, m) to the SAM's (else AIM
    GeneralInformation's) length and time units; m and s by default."""
    units = sam.get("units") or aim.get("GeneralInformation", {}).get("units") or {}
    length = LENGTH.get(units.get("length", "m"), 1.0)
    time = TIME.get(units.get("time", "sec"), 1.0)
    return {"PFA": G * time ** 2 / length, "PFD": 1 / length, "RFD": 1 / length}


def response_values(response, table, factors):
    """One number per dof of a response, from the building's table."""
    kind = PELICUN.get(response.get("type"))
    dofs = response.get("dofs") or [1]
    if kind is None:
        return ["NaN"] * len(dofs)
    if kind in ("PID", "PRD"):
        location = response.get("floor2", response.get("floor"))
    else:
        location = response.get("floor")
    values = []
    for dof in dofs:
        if kind in POUNDING:
            gaps = [response["gap"]] if "gap" in response else \
                [h.split("-")[3] for h in table if h.startswith(f"1-{kind}-{location}-")]
            found = [table[f"1-{kind}-{location}-{g}"][0] for g in gaps
                     if f"1-{kind}-{location}-{g}" in table]
            values.append(max(found) if found and dof == 1 else "NaN")
            continue
        entry = table.get(f"1-{kind}-{location}-{dof}")
        values.append("NaN" if entry is None else entry[0] * factors.get(kind, 1.0))
    return values


def standard_responses(table, building):
    """StandardEarthquakeEDP's responses of one building (dof 1) and residual drifts."""
    floors = sorted({int(h.split("-")[2]) for h in table if h.startswith("1-PFA-")})
    responses = []
    for f in floors:
        responses.append({"type": "max_abs_acceleration", "cline": building, "floor": str(f), "dofs": [1]})
        if f > 0:
            responses.append({"type": "max_rel_disp", "cline": building, "floor": str(f), "dofs": [1]})
            responses.append({"type": "max_drift", "cline": building, "floor1": str(f - 1),
                              "floor2": str(f), "dofs": [1]})
    responses.append({"type": "max_roof_drift", "cline": building, "floor1": "0",
                      "floor2": str(floors[-1]), "dofs": [1]})
    for f in floors[1:]:
        responses.append({"type": "residual_drift", "cline": building, "floor": str(f), "dofs": [1]})
    return responses


def pounding_responses(table, building):
    responses = []
    for h in table:
        _, kind, floor, gap = h.split("-")
        if kind in POUNDING:
            responses.append({"type": POUNDING[kind], "cline": building, "floor": floor,
                              "gap": gap, "dofs": [1]})
    return responses


def get_rv(files, prm, sam, aim):
    """SIM.json, and EDP.json's pounding (or every) response."""
    zero = run_poundfe(prm, [(1, 0.01, [0.0, 0.0, 0.0])], "poundfe_getrv")
    building = building_of(sam, files["sam"], zero)
    table = demand_tables(zero)[building]
    if os.path.exists(files["edp"]):
        edp = read_json(files["edp"])
        events = edp.get("EngineeringDemandParameters") or [{"name": "event", "responses": []}]
        events[0].setdefault("responses", []).extend(pounding_responses(table, building))
    else:
        events = [{"name": "event", "responses": standard_responses(table, building) +
                   pounding_responses(table, building)}]
        edp = {"RandomVariables": []}
    for response in events[0]["responses"]:
        response.setdefault("scalar_data", [])
    edp["EngineeringDemandParameters"] = events
    edp["total_number_edp"] = sum(len(r.get("dofs") or [1]) for e in events for r in e["responses"])
    shutil.rmtree(zero, ignore_errors=True)
    with open(files.get("sim", "SIM.json"), "w", encoding="utf-8") as f:
        json.dump({}, f, indent=2)
    with open(files["edp"], "w", encoding="utf-8") as f:
        json.dump(edp, f, indent=2)


def simulate(files, prm, sam, aim):
    if "event" not in files:
        raise InputFault("poundfe_simcenter.py: --filenameEVENT is missing")
    name, motions = event_series(files["event"])
    edp = read_json(files["edp"])
    events = edp.get("EngineeringDemandParameters")
    if not isinstance(events, list) or not events:
        fail(files["edp"], "EngineeringDemandParameters", "no event's responses to fill")
    directory = run_poundfe(prm, motions, "poundfe_run")
    tables = demand_tables(directory)
    default = building_of(sam, files["sam"], directory)
    factors = unit_factors(sam, aim)
    results = []
    for response in events[0].get("responses", []):
        table = tables.get(response.get("cline"), tables[default])
        response["scalar_data"] = response_values(response, table, factors)
        results += response["scalar_data"]
    with open(files["edp"], "w", encoding="utf-8") as f:
        json.dump(edp, f, indent=2)
    with open("results.out", "w", encoding="utf-8") as f:
        f.write(" ".join(str(x) for x in results))


def main(argv):
    try:
        files, rv = parse_arguments(argv)
        aim, sam = read_json(files["aim"]), read_json(files["sam"])
        prm = model_file(sam, files["sam"], aim)
        (get_rv if rv else simulate)(files, prm, sam, aim)
    except InputFault as e:
        sys.stderr.write(f"poundfe_simcenter.py: error: {e}\n")
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
