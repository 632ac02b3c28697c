#!/usr/bin/env python3
"""Absurd-value scan of the examples' numeric entries.

Sets each numeric entry of input/*.prm (every number of a list) to each of
1e200, -1e200, 0, nan, inf and 1e-300, runs the command of the entry's
section on that example, and prints one JSON line per run: the exit status,
the wall time, whether anything was written and the last line of standard
error. The rule it checks: bad input exits 1 with one message and writes
nothing; nothing exits 0 with an absurd answer, crashes or hangs.

usage: absurd-input-scan.py ROOT BINARY [TIMEOUT_S] [VALUE ...]
"""
import glob, json, os, re, shutil, subprocess, sys, tempfile, time

COMMAND = {"IDA": "ida", "MSA": "msa", "Monte Carlo": "montecarlo", "Separation": "separation",
           "Site hazard": "site-hazard", "Subset simulation": "subset", "Mitigation": "mitigation",
           "Bifurcation": "bifurcation", "Moment curvature": "moment-curvature",
           "Sections": "moment-curvature", "Reliability": "reliability",
           "Random parameters": "dynamic-form", "Spectrum": "spectrum", "Pushover": "pushover",
           "Fragility": "fragility", "Stationary PDF": "stationary-pdf",
           "Selection": "select-records", "Drift limits": "montecarlo"}
NUMBER = re.compile(r"[-+]?(?:\d+\.?\d*|\.\d+)(?:[eE][-+]?\d+)?")


def numeric_entries(root):
    """One (file, path, template, top section) per entry, Building i merged."""
    entries = {}
    files = sorted(glob.glob(os.path.join(root, "input", "*.prm")), key=os.path.getsize)
    for f in files:
        if "city-block" in f:
            continue
        stack = []
        for line in open(f):
            s = line.split("#")[0].strip()
            if s.startswith("subsection "):
                stack.append(s[11:].strip())
            elif s == "end" and stack:
                stack.pop()
            elif s.startswith("set ") and "=" in s:
                key, value = s[4:].split("=", 1)
                value = value.strip()
                if not NUMBER.findall(value) or NUMBER.sub("", value).replace(",", "").strip():
                    continue
                path = "/".join(stack + [key.strip()])
                generic = re.sub(r"Building \d+", "Building N", path)
                entries.setdefault(generic, (f, path, value, stack[0] if stack else ""))
    return entries


def run(binary, command, f, path, value, timeout):
    out = tempfile.mkdtemp(prefix="absurd-scan-")
    shutil.rmtree(out)
    start = time.monotonic()
    try:
        p = subprocess.run(["nice", "-n", "19", binary, command, f, "--output", out,
                            "--set", f"{path}={value}", "--set", "Output/Plots=false"],
                           capture_output=True, text=True, timeout=timeout)
        rc, err = p.returncode, (p.stderr.strip().splitlines() or [""])[-1][:240]
    except subprocess.TimeoutExpired:
        rc, err = "timeout", ""
    wall = time.monotonic() - start
    written = os.path.isdir(out) and bool(os.listdir(out))
    shutil.rmtree(out, ignore_errors=True)
    return rc, round(wall, 2), written, err


def main():
    root, binary = sys.argv[1], sys.argv[2]
    timeout = float(sys.argv[3]) if len(sys.argv) > 3 else 20
    values = sys.argv[4:] or ["1e200", "-1e200", "0", "nan", "inf", "1e-300"]
    entries = numeric_entries(root)
    print(len(entries), "entries", file=sys.stderr)
    for generic, (f, path, template, top) in entries.items():
        command = COMMAND.get(top, "run")
        for v in values:
            value = NUMBER.sub(v, template)
            rc, wall, written, err = run(binary, command, f, path, value, timeout)
            print(json.dumps({"rc": rc, "wall": wall, "cmd": command, "file": os.path.basename(f),
                              "path": path, "value": v, "written": written, "err": err}), flush=True)


if __name__ == "__main__":
    main()
