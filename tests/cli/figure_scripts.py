#!/usr/bin/env python3
"""The gnuplot scripts kept by tests/cli/figure_scripts.sh, one per command
(SCRIPTS/<command>.gp), checked figure by figure (see that file).

  usage: figure_scripts.py SCRIPTS WORK   (WORK/out-<command>: the results)
"""
import csv
import os
import re
import sys

failures = []


def check(condition, message):
    if not condition:
        failures.append(message)


def panels_of(path):
    """{png: [panel, ...]}: each panel its lines from the reset before it to
    its plot command, with its title, labels, ranges, series and data blocks."""
    figures, png, lines = {}, None, []
    for line in open(path).read().split("\n"):
        m = re.match(r"set output '(.*)\.tmp'", line)
        if m:
            png = m.group(1)
            figures[png] = []
            lines = []
            continue
        lines.append(line)
        if line.startswith("plot ") and png:
            figures[png].append(panel(lines))
            lines = []
    return figures


def panel(lines):
    text = "\n".join(lines)
    get = lambda what: (re.findall(r"^set " + what + r" '((?:[^']|'')*)'", text, re.M) or [None])[-1]
    series = re.findall(r"(\S+) using (.+?) with (.+?) title '((?:[^']|'')*)' noenhanced",
                        lines[-1][5:])
    blocks = dict(re.findall(r"^(\$\w+) << EOD\n(.*?)\nEOD", text, re.M | re.S))
    return dict(lines=lines, text=text, title=get("title"), x=get("xlabel"), y=get("ylabel"),
                y2=get("y2label"), yrange=(re.findall(r"^set yrange \[(.*?)\]", text, re.M) or [None])[-1],
                series=series, blocks=blocks)


def holds_probability(p, name):
    """P = 0 and 1 inside the y range, with room for a marker."""
    low, high = (float(x) for x in p["yrange"].split(":")) if p["yrange"] else (None, None)
    check(low is not None and low < 0 and high > 1, f"{name}: y range [{p['yrange']}] clips P = 0 or 1")


def first(figures, png, command):
    check(png in figures and figures[png], f"{command}: no {png}")
    return figures.get(png, [None])[0] if figures.get(png) else None


scripts, work = sys.argv[1], sys.argv[2]
every = {}
for command in ("run", "montecarlo", "fragility", "subset", "separation", "mitigation",
                "site-hazard", "msa", "ida"):
    path = os.path.join(scripts, command + ".gp")
    check(os.path.exists(path), f"{command}: no gnuplot script")
    every[command] = panels_of(path) if os.path.exists(path) else {}
    for png, panels in every[command].items():
        for i, p in enumerate(panels):
            name = f"{command} {png} panel {i + 1}"
            # the reset first, then the panel's own settings
            for reset in ("set autoscale", "set xtics norotate autofreq", "set boxwidth",
                          "set offsets 0, 0, 0, 0"):
                check(reset in p["lines"], f"{name}: no '{reset}' before it")
            lines = p["lines"]
            own = [k for k, line in enumerate(lines) if line.startswith("set title")]
            check(all(r in lines and lines.index(r) < own[0] for r in ("set autoscale", "set boxwidth")
                      if own), f"{name}: the reset after the panel's own settings")
            if i == 0:
                check(bool(p["title"]), f"{name}: no title")

# run: the whole model's figures name the buildings; the roof in mm
run = every["run"]
for png in ("drift_profile.png", "acceleration_profile.png", "roof_displacement.png",
            "base_shear.png", "energy.png", "contact_force.png"):
    p = first(run, png, "run") if png != "base_shear.png" or png in run else None
    if p:
        check(re.match(r"(Building \S+|Buildings .+ and \S+|\d+ buildings): ", p["title"]) is not None,
              f"run {png}: the title does not name the buildings: {p['title']}")
roof = first(run, "roof_displacement.png", "run")
if roof:
    check(roof["y"] == "displacement (mm)", f"roof_displacement.png: y label {roof['y']}")
    check(roof["series"] and all(s[1].endswith("/0.001)") for s in roof["series"]),
          f"roof_displacement.png: not in mm: {[s[1] for s in roof['series']]}")

# montecarlo: a histogram's range above its tallest bar; a CDF holds 0 and 1
for png, panels in every["montecarlo"].items():
    p = panels[0]
    top = float(p["yrange"].split(":")[1]) if p["yrange"] and p["yrange"].split(":")[1] != "*" else None
    if png.startswith("pdf_"):
        data, using = p["series"][0][0], p["series"][0][1]
        if data == "$counts":
            tallest = max(float(r.split(",")[1]) for r in p["blocks"]["$counts"].split("\n")[1:])
        else:
            rows = list(csv.reader(open(os.path.join(work, "out-montecarlo", data.strip("'")))))[1:]
            m = re.search(r"\(\$5\*([0-9.e+-]+)\)", using)
            tallest = max(float(r[4]) for r in rows) * (float(m.group(1)) if m else 1.0)
        check(top is not None and top > tallest, f"{png}: y range [{p['yrange']}], tallest bar {tallest}")
    else:
        check(top is not None and top > 1 and p["yrange"].startswith("0:"), f"{png}: y range {p['yrange']}")

p = first(every["fragility"], "fragility.png", "fragility")
if p:
    holds_probability(p, "fragility.png")
    check(p["x"] == "PGA (g)" and "PGA" in p["title"], f"fragility.png: {p['title']} / {p['x']}")

p = first(every["subset"], "subset_levels.png", "subset")
if p:
    check(re.search(r"of building \S+", p["title"]) is not None, f"subset_levels.png: {p['title']}")

p = first(every["separation"], "separation.png", "separation")
if p:
    check(p["x"] == "separation (mm)" and "S1-S2" in p["title"], f"separation.png: {p['title']} / {p['x']}")
    gap = [s for s in p["series"] if s[3] == "existing gap"]
    check(len(gap) == 1 and gap[0][0] in p["blocks"], "separation.png: the existing gap not a data block")
    if gap and gap[0][0] in p["blocks"]:
        rows = [r.split(",") for r in p["blocks"][gap[0][0]].split("\n")[1:]]
        check(len(rows) == 2 and rows[0][0] == rows[1][0] and float(rows[0][1]) == 0 <
              float(rows[1][1]), f"separation.png: the existing gap drawn as {rows}")
    for s in p["series"]:
        colour = re.search(r"lc rgb '([^']*)'", s[2])
        check(colour is not None and colour.group(1).lower() not in ("yellow", "#f0e442", "gold"),
              f"separation.png: {s[3]} in {colour.group(1) if colour else 'the default colour'}")
p = first(every["separation"], "pounding_probability.png", "separation")
if p:
    holds_probability(p, "pounding_probability.png")
    check("(mm)" in p["x"] and "S1-S2" in p["title"], f"pounding_probability.png: {p['title']}")

panels = every["mitigation"].get("mitigation.png", [])
check(len(panels) == 3, f"mitigation.png: {len(panels)} panels")
if len(panels) == 3:
    check("pounding of" in panels[0]["title"], f"mitigation.png: {panels[0]['title']}")
    holds_probability(panels[1], "mitigation.png P(pounding)")
    check(panels[1]["y2"] == "impact force (kN)" and panels[2]["y"] == "required gap (mm)" and
          panels[2]["y2"] == "floor acceleration (g)",
          f"mitigation.png: units {panels[1]['y2']}, {panels[2]['y']}, {panels[2]['y2']}")

p = first(every["site-hazard"], "hazard.png", "site-hazard")
if p:
    check(re.match(r"Site hazard at [0-9.]+ [NS], [0-9.]+ [EW]: ", p["title"]) is not None,
          f"hazard.png: {p['title']}")
    check("set logscale y" in p["lines"] and p["y"] == "annual rate of exceedance (1/year)",
          f"hazard.png: {p['y']}")

p = first(every["msa"], "msa.png", "msa")
if p:
    holds_probability(p, "msa.png")
    check(p["title"].endswith("(g)") and p["x"].endswith("(g)"), f"msa.png: {p['title']} / {p['x']}")
    titles = [s[3] for s in p["series"]]
    fits = [t[:-len(" (fit)")] for t in titles if t.endswith(" (fit)")]
    check(fits and all(f + " (observed fraction)" in titles for f in fits),
          f"msa.png: the observed fractions not in the key: {titles}")
    check("collapse (observed fraction)" in titles, f"msa.png: no collapse fractions: {titles}")
    check("set offsets 0, graph 0.04, 0, 0" in p["lines"], "msa.png: the last stripe on the frame")

p = first(every["ida"], "ida.png", "ida")
if p:
    check("largest peak drift ratio of all buildings" in p["title"] and p["y"].endswith("(g)"),
          f"ida.png: {p['title']} / {p['y']}")
    check(p["yrange"] == "0:*" and "set xrange [0:*]" in p["lines"], f"ida.png: ranges")

n = sum(len(panels) for figures in every.values() for panels in figures.values())
for f in failures:
    print("FAIL", f)
print(f"{'ok  ' if not failures else 'FAIL'} {sum(len(f) for f in every.values())} figures, "
      f"{n} panels of {len(every)} commands")
sys.exit(1 if failures else 0)
