#!/usr/bin/env bash
# Hostile and malformed input (issue 14 items 1-6, 8, 10): each case is
# written here, run through the real binary, and must give its exit status
# and its message, in one line, with nothing written on exit 1.
#   long lines and a 6,000-value list, deep JSON, unbounded step counts,
#   AT2 headers (Fortran D exponents read right, malformed numbers refused),
#   empty/null/CR-only input, a backslash in a comment, trailing text after
#   numbers, command-line options, record values made non-finite by units or
#   scaling, messages that blame the right file and print numbers exactly.
set -u
poundfe=$1
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$here/expect.sh"

# 1. long lines: a list of 6,000 values, a 30,000-character subsection name
heights=$(python3 -c 'print(", ".join(["3.0"] * 6000))')
shear "  set Storey heights = $heights" > long-list.prm
expect 1 "long-list.prm:6: parameter 'Building 1/Storey heights': needs 1 value or 3" modal long-list.prm --output out
python3 -c 'print("subsection " + "x" * 30000 + "\nend")' > long-subsection.prm
shear >> long-subsection.prm
expect 1 "long-subsection.prm:1: There is no such subsection" modal long-subsection.prm --output out
printf 'subsection Model\n  set Number of buildings = 1\nend\nsubsection Building 1\n  set Type = shear\n  set Number of storeys = 6000\n  set Storey heights = %s\n  set Floor masses = 1000\n  set Storey stiffnesses = 5e6\nend\nsubsection Output\n  set Plots = false\n  set Number of modes = 1\nend\n' "$heights" > tall.prm
expect 0 "mode  frequency (Hz)" modal tall.prm --output out

# 1. deep JSON
python3 -c 'print("{\"Model\": " + "[" * 30000 + "]" * 30000 + "}")' > deep.json
expect 1 "deep.json:1: nested more than 64 levels deep" modal deep.json --output out

# 2. unbounded step counts
shear > endless.prm
printf 'subsection Time integration\n  set End time = 1e308\nend\n' >> endless.prm
expect 1 "parameter 'Time integration/End time': needs unboundedly many steps" run endless.prm --output out
sed -i 's/1e308/1e5/' endless.prm
expect 1 "needs 100000000 steps of 0.001 s to reach 1e+05 s, more than Time integration/Maximum number of steps = 10000000" run endless.prm --output out
printf 'NPTS=  3, DT= 1e5 SEC\n 0.1 0.2 0.3\n' > slow.at2
shear > slow.prm
printf 'subsection Ground motion\n  set Type = record\n  subsection Record\n    set File = slow.at2\n  end\nend\n' >> slow.prm
expect 1 "parameter 'Ground motion/Record/File': needs 200000000 steps" run slow.prm --output out

shear > long-noise.prm
printf 'subsection Ground motion\n  set Type = kanai-tajimi\n  subsection Stochastic\n    set Duration = 1e308\n  end\nend\n' >> long-noise.prm
expect 1 "long-noise.prm:15: parameter 'Ground motion/Stochastic/Duration': needs unboundedly many samples of 0.001 s" run long-noise.prm --output out

shear | sed 's/^\(subsection Output\)$/\1\n  set VTU interval = 0.001\n  set Maximum VTU frames = 10/' > frames.prm # one Output section (issue 28)
printf 'subsection Time integration\n  set End time = 1\nend\nsubsection Ground motion\n  set Type = kanai-tajimi\n  subsection Stochastic\n    set Duration = 1\n  end\nend\n' >> frames.prm
expect 0 "Output/VTU interval = 0.001 s would write 1001 VTU frames, more than Output/Maximum VTU frames = 10: writing one every 0.112 s instead" run frames.prm --output out
frames=$(ls out/solution/*.vtu 2> /dev/null | wc -l)
[ "$frames" -ge 2 ] && [ "$frames" -le 10 ] || fail "frames.prm: $frames VTU frames, expected 2 to 10"

# 3. AT2 headers: Fortran D exponents, malformed numbers, absurd NPTS and DT
record() { # $1: header line; the record prm reads record.at2
  printf 'SYNTHETIC\nUNITS OF G\n%s\n 0.1 -0.2 0.3\n 0.1D-01 -0.2 0.3\n' "$1" > record.at2
}
printf 'subsection Ground motion\n  set Type = record\n  subsection Record\n    set File = record.at2\n  end\nend\nsubsection Output\n  set Plots = false\nend\n' > record.prm
record 'NPTS=    6, DT= 2.0D-02 SEC'
expect 0 "6 samples, dt = 0.02 s" ground-motion record.prm --output out
record 'NPTS=    6, DT= .2D-01 SEC'
expect 0 "dt = 0.02 s" ground-motion record.prm --output out
record '    6   .2D-01   NPTS, DT'
expect 0 "dt = 0.02 s" ground-motion record.prm --output out
record 'NPTS=    6, DT= 0.02.5 SEC'
expect 1 "record.at2:3: header field DT: expected a positive time step in s (e.g. 0.005 or .5D-02), got '0.02.5'" ground-motion record.prm --output out
record 'NPTS=    6, DT= 2e-2e SEC'
expect 1 "header field DT" ground-motion record.prm --output out
record 'NPTS=    6, DT= 1e999 SEC'
expect 1 "header field DT: expected a positive time step in s (e.g. 0.005 or .5D-02), got '1e999'" ground-motion record.prm --output out
record 'NPTS=   -5, DT= .01 SEC'
expect 1 "record.at2:3: header field NPTS: expected a whole number of points from 2 to 100000000, got '-5'" ground-motion record.prm --output out
record 'NPTS= 99999999999999999999, DT= .01 SEC'
expect 1 "header field NPTS" ground-motion record.prm --output out
record 'NPTS= 90000000, DT= .01 SEC'
expect 1 "promises NPTS = 90000000 values, found 6" ground-motion record.prm --output out
mkdir -p directory.at2
sed 's/record.at2/directory.at2/' record.prm > directory.prm
expect 1 "directory.at2: is a directory, not a record file" ground-motion directory.prm --output out

# 4. empty, null, CR-only, a backslash in a comment, --output ""
: > empty.prm
expect 1 "empty.prm: the file sets no parameter" modal empty.prm --output out
printf '# only a comment\n\n' > comments.prm
expect 1 "comments.prm: the file sets no parameter" modal comments.prm --output out
echo null > null.json
expect 1 "null.json:1: a JSON parameter file is an object" modal null.json --output out
echo '{ }' > nothing.json
expect 1 "nothing.json:1: the file sets no parameter" modal nothing.json --output out
{ echo '# CR line ends, a comment first'; shear '  set Storey heights = -3'; } | tr '\n' '\r' > cr.prm
expect 1 "cr.prm:7: parameter 'Building 1/Storey heights': must be positive and finite, got -3" modal cr.prm --output out
shear '  # the height of every storey \
  set Storey heights = -3' > backslash.prm
expect 1 "backslash.prm:7: parameter 'Building 1/Storey heights': must be positive" modal backslash.prm --output out
shear > fine.prm
expect 1 "--output needs a value" modal fine.prm --output ""

# 5. trailing text after numbers
barrier() {
  shear
  printf 'subsection Contact\n  set Law = hertz\n  set Barriers = %s\nend\n' "$1"
}
barrier '1 1 right 15mm' > barrier.prm
expect 1 "barrier.prm:14: parameter 'Contact/Barriers': '1 1 right 15mm': expected 'building floor left|right gap'" modal barrier.prm --output out
barrier '1 1 right 0.015 junk' > barrier.prm
expect 1 "expected 'building floor left|right gap'" modal barrier.prm --output out
barrier '1 1x right 0.015' > barrier.prm
expect 1 "expected 'building floor left|right gap'" modal barrier.prm --output out
shear '  set Storey heights = 3, 1e-2x' > list.prm
expect 1 "list.prm:6: parameter 'Building 1/Storey heights': The entry value 3, 1e-2x for the entry named Storey heights does not match the given pattern: a comma-separated list of numbers" modal list.prm --output out
shear > force.prm
printf 'subsection Time integration\n  set End time = 0.01\nend\n' >> force.prm
printf 'subsection Nodal forces\n  set Harmonic = 1 1 0 ux 100 6.28 0.5rad\nend\n' >> force.prm
expect 1 "force.prm:16: parameter 'Nodal forces/Harmonic': '1 1 0 ux 100 6.28 0.5rad': expected '... amplitude omega [phase]'" run force.prm --output out

# 6. command line
expect 1 "unknown option '--outptu'" run fine.prm --outptu x
expect 1 "'print-parameters' takes no argument, got 'fine.prm'" print-parameters fine.prm
expect 0 "usage: poundfe" --help
expect 0 "poundfe (git " --version

# 8. messages: numbers as written, the included file blamed
shear '  subsection Damping\n    set Damping ratio = -1e-300\n  end' | sed 's/\\n/\n/g' > ratio.prm
expect 1 "must lie in [0, 1), got -1e-300" modal ratio.prm --output out
shear '  set Storey heights = -1e308' > height.prm
expect 1 "must be positive and finite, got -1e+308" modal height.prm --output out
shear > restitution.prm
printf 'subsection Contact\n  set Law = hertz\n  set Coefficient of restitution = 1.00000000001\nend\n' >> restitution.prm
expect 1 "got 1.00000000001" modal restitution.prm --output out
printf 'subsection Time integration\n  set Time step = 0.01\n  set Tim step = 1\nend\n' > included.prm
shear > including.prm
echo "include included.prm" >> including.prm
expect 1 "included.prm:3: parameter 'Time integration/Tim step': No entry with name <Tim step> in 'Time integration' (did you mean 'Time step'?)" \
  modal including.prm --output out
shear > unclosed.prm
printf 'subsection Time integration\n  set Time step = 0.01\n' >> unclosed.prm
expect 1 "unclosed.prm:12: 'subsection Time integration' is never closed by 'end'" modal unclosed.prm --output out
shear > extra-end.prm
echo end >> extra-end.prm
expect 1 "extra-end.prm:12: 'end' without an open 'subsection'" modal extra-end.prm --output out

shear | sed 's/Floor masses = 1000/Floor masses = 4.9e-324/' > tiny-mass.prm
expect 1 "tiny-mass.prm:4: parameter 'Building 1/Floor masses': got 5e-324, below the smallest normal double" modal tiny-mass.prm --output out
shear > shinozuka.prm
printf 'subsection Ground motion\n  set Type = kanai-tajimi\n  subsection Stochastic\n    set Envelope = shinozuka-sato\n    set Shinozuka beta = 0.5\n    set Shinozuka alpha = 0.9\n  end\nend\n' >> shinozuka.prm
expect 1 "shinozuka.prm:17: parameter 'Ground motion/Stochastic/Shinozuka alpha': needs Shinozuka alpha < Shinozuka beta, got alpha = 0.9, beta = 0.5" modal shinozuka.prm --output out

# 10. record values that units or scaling make non-finite or denormal
printf 'NPTS=  3, DT= .01 SEC\n 0.1 1e308 0.3\n' > huge.at2
sed 's/record.at2/huge.at2/' record.prm > huge.prm
expect 1 "huge.at2: value 2 becomes inf m/s^2 in g (AT2): not a finite, normal number" ground-motion huge.prm --output out
printf 'NPTS=  3, DT= .01 SEC\n 1e-320 0 -1e-320\n' > tiny.at2
sed -e 's/record.at2/tiny.at2/' -e 's/  end/    set Target PGA = 0.3\n  end/' record.prm > tiny.prm
expect 1 "tiny.at2: value 1 becomes 9.8067e-320 m/s^2 in g (AT2): not a finite, normal number" ground-motion tiny.prm --output out
printf 'NPTS=  3, DT= .01 SEC\n 1e10 0 -1e10\n' > strong.at2
sed -e 's/record.at2/strong.at2/' -e 's/^  end/  end\n  set Scale factor = 1e300/' record.prm > strong.prm
expect 1 "strong.prm:6: parameter 'Ground motion/Scale factor': scales sample 1 of the ground motion to inf m/s^2" ground-motion strong.prm --output out

report hostile-input
