#!/usr/bin/env python3
"""Writes a city-block parameter file: a row of reinforced-concrete frames
side by side, alternating between two designs (a stiffer, heavier one and a
more flexible one, so that neighbours vibrate out of phase and pound), with
Bouc-Wen hinges at the column bases and beam ends, Hertz-damp gaps at every
common floor, and Rayleigh damping from given coefficients (no modal
analysis: `Number of modes = 0`, because the modal analysis is dense, n x n).

input/city-block.prm (issue 12 item 5, ~110k equations) and the small
variant of the distributed-solver test (tests/cli/city-block-small.prm) are
both written by this script:

  python3 scripts/city_block.py > input/city-block.prm
  python3 scripts/city_block.py --small > tests/cli/city-block-small.prm
"""
import argparse

HEADER = """# {title}
# Written by scripts/city_block.py{options}; edit that script, not this file.
# {n} reinforced-concrete frames in a row, {storeys} storeys, {bays} bays of {bay} m,
# {elements} frame elements per member, alternating between a stiffer, heavier
# design (odd buildings) and a more flexible one (even buildings), {gap} m apart;
# Bouc-Wen hinges at the column bases and the beam ends of every building and
# Hertz-damp gap elements at every floor of every neighbouring pair. Rayleigh
# damping from given coefficients (5 % at about 0.5 and 5 Hz), so no modal
# analysis is needed (Output/Number of modes = 0: the modal analysis is dense).
# {purpose}
"""

BUILDING = """
subsection Building {number}
  set Name                = {name}
  set Type                = frame
  set Number of storeys   = {storeys}
  set Number of bays      = {bays}
  set Storey heights      = 3.2
  set Bay widths          = {bay}
  set Elements per member = {elements}
  set Column E            = 3.0e10
  set Column A            = {column_area}
  set Column I            = {column_i}
  set Beam E              = 3.0e10
  set Beam A              = 0.18
  set Beam I              = 5.4e-3
  set Floor masses        = {floor_mass}
  subsection Hinges
    set Locations    = column bases, beam ends
    set Yield moment = {yield_moment}
  end
  subsection Bouc-Wen
    set alpha = 0.005
  end
  subsection Damping
    set Type = coefficients
    set a0   = 0.2856
    set a1   = 0.002894
  end
end
"""

FOOTER = """
subsection Ground motion
  set Type = kanai-tajimi
  subsection Stochastic
    set Soil        = medium
    set Target PGA  = {pga}
    set Peak factor = 3.0
    set Duration    = {duration}
    set Envelope    = jennings
    set Rise end    = 0.5
    set Plateau end = {plateau}
    set Decay rate  = 0.3
    set Seed        = 2026
  end
end

subsection Contact
  set Law                        = hertz-damp
  set Stiffness                  = 2.75e9
  set Damping from               = calibrated
  set Coefficient of restitution = 0.65
end

subsection Time integration
  set Time step     = {dt}
  set End time      = {end}
  set Linear solver = petsc-mumps
  # Bouc-Wen's local tolerance is absolute on z: at the default 1e-12, while
  # z is still ~1e-9 (the first steps), thousands of hinges leave a residual
  # that stalls Newton at ~1e-6 of the first and cuts steps.
  set Law tolerance = 1e-15
end

subsection Output
  set Directory       = results/{directory}
  set Output interval = {interval}
  set VTU interval    = 0
  set Number of modes = 0
end
"""

DESIGNS = [  # odd buildings, even buildings
    dict(column_area=0.64, column_i=3.41e-2, floor_mass=90000, yield_moment=1.2e6),
    dict(column_area=0.36, column_i=1.08e-2, floor_mass=60000, yield_moment=5.0e5),
]


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("--small", action="store_true",
                        help="the small variant of the distributed-solver test")
    parser.add_argument("--buildings", type=int, help="override the number of buildings")
    parser.add_argument("--storeys", type=int, help="override the number of storeys")
    parser.add_argument("--end", type=float, help="override the end time, s")
    args = parser.parse_args()
    if args.small:
        size = dict(n=3, storeys=4, bays=2, elements=2, bay=6.0, gap=0.002)
        run = dict(pga=0.5, duration=3, plateau=2, dt=0.005, end=1.5, interval=0.005,
                   directory="city-block-small")
        title = ("A small city block (3 frames of 4 storeys): serial against\n# "
                 "mpirun -np 2 with petsc-mumps (tests/cli/distributed.sh).")
        purpose = "About 300 equations; 1.5 s of motion, a few seconds to run."
    else:
        size = dict(n=12, storeys=40, bays=10, elements=4, bay=6.0, gap=0.007)
        run = dict(pga=0.5, duration=20, plateau=10, dt=0.005, end=1.0, interval=0.01,
                   directory="city-block")
        title = ("City block (issue 12 item 5): one large model for a distributed solve,\n# "
                 "mpirun -np P poundfe run input/city-block.prm. Partitioned by building\n# "
                 "(issue 23, theory 3.5d): replace 'Linear solver = petsc-mumps' below with\n# "
                 "'Linear solver = eigen-ldlt', add 'set Partition = buildings' and\n# "
                 "'set Nonlinear solver = krylov-newton' to Time integration, and run it\n# "
                 "with mpirun -np 2 (at most 12 ranks: one per building).")
        purpose = ("116 292 equations, 10 172 nonlinear elements (9 732 hinges, 440 gaps).\n"
                   "# Only the first {end} s of the motion (End time), so that the example runs "
                   "in\n# minutes; see doc/benchmarks.md. Not run by "
                   "cli/regression\n# (too long for CI): "
                   "tests/cli/city-block-small.prm is its small variant. Over a\n# "
                   "whole record, hinges.csv of every hinge grows by 63 MB a second of motion:\n# "
                   "'set Record = hinge states of B05' (in Output/Recorders) records those "
                   "of one\n# building only.").format(end=run["end"])
    for key, value in (("n", args.buildings), ("storeys", args.storeys)):
        if value is not None:
            size[key] = value
    if args.end is not None:
        run["end"] = args.end
    options = " --small" if args.small else ""
    print(HEADER.format(title=title, options=options, purpose=purpose, **size), end="")
    print("""
subsection Model
  set Number of buildings = {n}
  set Mass matrix         = lumped
  set Separations         = {gap}
end""".format(**size))
    for b in range(size["n"]):
        print(BUILDING.format(number=b + 1, name="B%02d" % (b + 1), **size, **DESIGNS[b % 2]),
              end="")
    print(FOOTER.format(**run), end="")


if __name__ == "__main__":
    main()
