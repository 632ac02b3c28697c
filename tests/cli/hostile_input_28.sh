#!/usr/bin/env bash
# Hostile input, round two (issue 28), through the real binary: each case
# must give its exit status and its message (one line, nothing written on
# exit 1; tests/cli/expect.sh).
#   class 1: every reader bounded: JSON hazard/fragility files nested
#            100,000 deep, a FIFO, /dev/zero, a file over 1 GiB, a line over
#            1 MiB, for parameter files, records, catalogues, hazard and
#            fragility files, meshes;
#   class 2: a separation with a site hazard and one realization per PGA
#            level: the gap for the target is the closed form of a demand
#            without scatter, and a warning says why it is unconservative;
#   class 5: an AT2 with more values than NPTS is refused like one with fewer;
#   class 8: a parameter set twice, a section entered twice, a JSON key
#            twice, a command-line option twice, a level or ratio twice;
#   class 9: a binary parameter file, a byte-order mark on a catalogue, a
#            directory where a file is expected, a read-only output
#            directory, a `Building 2` section with one building.
#   hostile_input_28.sh POUNDFE INPUT_DIR SEPARATION_PAIR_PRM
set -u
poundfe=$(readlink -f "$1") inputs=$(readlink -f "$2") pair=$(readlink -f "$3")
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'chmod -R u+w "$work"; rm -rf "$work"' EXIT
cd "$work" || exit 1
. "$here/expect.sh"

cp "$inputs/site-hazard.prm" "$inputs/memvele-catalogue-illustrative.csv" .
sed -i 's/^\(subsection Output\)$/\1\n  set Plots = false/' site-hazard.prm
grep -q "set Plots = false" site-hazard.prm || { echo "FAIL site-hazard.prm has no Output section"; exit 1; }
# site-hazard.prm with its catalogue or its fragility from elsewhere
catalogue() { sed "s|= memvele-catalogue-illustrative.csv|= $1|" site-hazard.prm > "$2"; }
fragility() {
  sed -e "s|    set Median PGA = 0.25|    set File = $1|" -e '/    set Beta       = 0.5/d' site-hazard.prm > "$2"
}
# the separation pair with a site hazard from file $1, PGA levels $2
separation() {
  cat "$pair"
  printf 'subsection Separation\n  subsection Site hazard\n    set File = %s\n    set PGA levels = %s\n  end\nend\n' "$1" "${2:-0.02, 0.05, 0.1}"
}
record() { # $1: the record file; a run of it
  shear > "$2"
  printf 'subsection Ground motion\n  set Type = record\n  subsection Record\n    set File = %s\n  end\nend\n' "$1" >> "$2"
}

"$poundfe" site-hazard site-hazard.prm --output hazard > /dev/null 2>&1 || { echo "FAIL site-hazard"; exit 1; }

# --- class 1: every reader bounded
python3 -c 'print("[" * 100000 + "]" * 100000)' > deep.json
separation deep.json > deep-hazard.prm
expect 1 "deep.json:1: parameter 'Separation/Site hazard/File': nested more than 64 levels deep" separation deep-hazard.prm --output out
fragility deep.json deep-fragility.prm
expect 1 "deep.json:1: parameter 'Site hazard/Fragility/File': nested more than 64 levels deep" site-hazard deep-fragility.prm --output out
mkfifo fifo.prm fifo.csv fifo.at2 fifo.json fifo.msh
expect 1 "fifo.prm: is a named pipe (FIFO), not a regular file" modal fifo.prm --output out
record fifo.at2 fifo-record.prm
expect 1 "fifo.at2: is a named pipe (FIFO), not a regular file: the record file" run fifo-record.prm --output out
catalogue fifo.csv fifo-catalogue.prm
expect 1 "fifo.csv: parameter 'Site hazard/Catalogue file': is a named pipe (FIFO)" site-hazard fifo-catalogue.prm --output out
separation fifo.json > fifo-hazard.prm
expect 1 "fifo.json: parameter 'Separation/Site hazard/File': is a named pipe (FIFO)" separation fifo-hazard.prm --output out
fragility fifo.json fifo-fragility.prm
expect 1 "fifo.json: parameter 'Site hazard/Fragility/File': is a named pipe (FIFO)" site-hazard fifo-fragility.prm --output out
sed 's|= ../meshes/setback.msh|= fifo.msh|' "$inputs/setback-frame.prm" > fifo-mesh.prm
expect 1 "fifo.msh: is a named pipe (FIFO), not a regular file: the mesh file" modal fifo-mesh.prm --output out
ln -s /dev/zero zero.prm
expect 1 "zero.prm: is a device (like /dev/zero), not a regular file" modal zero.prm --output out
record /dev/zero zero-record.prm
expect 1 "/dev/zero: is a device (like /dev/zero), not a regular file: the record file" run zero-record.prm --output out
catalogue /dev/zero zero-catalogue.prm
expect 1 "/dev/zero: parameter 'Site hazard/Catalogue file': is a device (like /dev/zero)" site-hazard zero-catalogue.prm --output out
truncate -s 1100M big.at2 # sparse: no disk used
record big.at2 big-record.prm
expect 1 "big.at2: has 1153433600 bytes, more than the 1073741824 an input file may have" run big-record.prm --output out
{ head -1 memvele-catalogue-illustrative.csv; python3 -c 'print("1950," + "1" * 1100000 + ",10,5")'; } > long.csv
catalogue long.csv long-catalogue.prm
expect 1 "long.csv:2: parameter 'Site hazard/Catalogue file': a line of 1100010 characters, more than the 1048576 a line may have" site-hazard long-catalogue.prm --output out

# --- class 5: NPTS against the values, both ways
printf 'SYNTHETIC\nNPTS=  4, DT= .01 SEC\n 0.1 -0.2 0.3\n 0.1 -0.2 0.3\n' > more.at2
record more.at2 more.prm
expect 1 "more.at2:4: the header (line 2) promises NPTS = 4 values, found 6" run more.prm --output out
printf 'SYNTHETIC\nNPTS=  8, DT= .01 SEC\n 0.1 -0.2 0.3\n 0.1 -0.2 0.3\n' > fewer.at2
record fewer.at2 fewer.prm
expect 1 "fewer.at2:4: the header (line 2) promises NPTS = 8 values, found 6" run fewer.prm --output out
printf 'SYNTHETIC\nNPTS=  6, DT= .01 SEC\n 0.1 -0.2 0.3\n 0.1 -0.2 0.3\n*** End Data ***\n' > trailer.at2
record trailer.at2 trailer.prm
expect 0 "6 samples" ground-motion trailer.prm --output out

# --- class 8: duplicates are errors
shear '  set Floor masses = 2000' > twice.prm
expect 1 "twice.prm:6: parameter 'Building 1/Floor masses': is set a second time; the first is at line 4" modal twice.prm --output out
{ shear; printf 'subsection Output\n  set Number of modes = 2\nend\n'; } > section-twice.prm
expect 1 "section-twice.prm:12: 'subsection Output' (Output) is entered a second time; the first is at line 8" modal section-twice.prm --output out
printf '{ "Building 1": { "Type": "shear", "Number of storeys": "3" },\n  "Building 1": { "Floor masses": "1000" } }\n' > key-twice.json
expect 1 "key-twice.json:2: the key \"Building 1\" appears a second time in one object; the first is at line 1" modal key-twice.json --output out
shear > fine.prm
expect 1 "poundfe: error: --output is given twice" modal fine.prm --output a --output b
expect 1 "poundfe: error: --help is given twice" --help -h
separation hazard/summary.json "0.02, 0.05, 0.02" > levels-twice.prm
expect 1 "parameter 'Separation/Site hazard/PGA levels': lists 0.02 twice (values 1 and 3): give each once" separation levels-twice.prm --output out
sed 's/set Return periods    = 100, 144, 250, 475/set Return periods = 100, 475, 475/' site-hazard.prm > periods-twice.prm
expect 1 "parameter 'Site hazard/Return periods': lists 475 twice (values 2 and 3)" site-hazard periods-twice.prm --output out
{ shear; printf 'subsection Spectrum\n  set Damping ratios = 0.05, 0.02, 0.05\nend\n'; } > ratios-twice.prm
expect 1 "parameter 'Spectrum/Damping ratios': lists 0.05 twice (values 1 and 3)" spectrum ratios-twice.prm --output out

# --- class 9: messages that say the true cause
printf '\177ELF\002\001\001\000\000\000' > binary.prm # an executable's first bytes
expect 1 "binary.prm:1: a NUL byte (column 8): a binary file, not a text parameter file" modal binary.prm --output out
printf '\xef\xbb\xbf' > bom.csv
cat memvele-catalogue-illustrative.csv >> bom.csv
catalogue bom.csv bom.prm
expect 0 "events within the distance" site-hazard bom.prm --output out
mkdir directory.csv
catalogue directory.csv directory.prm
expect 1 "directory.csv: parameter 'Site hazard/Catalogue file': is a directory, not a catalogue" site-hazard directory.prm --output out
# a read-only output directory (root writes anywhere: it runs as nobody)
mkdir read-only && chmod 555 read-only && chmod 755 . && chmod 644 fine.prm
if [ "$(id -u)" -eq 0 ]; then
  printf '#!/bin/sh\nexec setpriv --reuid=65534 --regid=65534 --clear-groups "%s" "$@"\n' "$poundfe" > as-nobody
  chmod 755 as-nobody
  as_user=./as-nobody
else
  as_user=$poundfe
fi
poundfe=$as_user expect 1 "poundfe: error: permission denied: cannot write in the output directory $work/read-only" modal fine.prm --output "$work/read-only"
poundfe=$as_user expect 1 "poundfe: error: permission denied: cannot create directory read-only/out" modal fine.prm --output read-only/out
{ shear; printf 'subsection Building 2\n  set Type = shear\nend\n'; } > building2.prm
expect 1 "building2.prm:12: 'Building 2' is given, but Model/Number of buildings is 1 (raise it, or remove the section)" modal building2.prm --output out
printf '{ "Building 1": { "Type": "shear", "Number of storeys": "3", "Floor masses": "1000", "Storey stiffnesses": "5e6" },\n  "Building 2": { "Type": "shear" } }\n' > building2.json
expect 1 "building2.json:2: 'Building 2' is given, but Model/Number of buildings is 1 (raise it, or remove the section)" modal building2.json --output out

# --- class 2: one realization per level (the issue's case)
sed 's/set Realizations = 12/set Realizations = 1/' "$pair" > one-pair.prm
{ cat one-pair.prm; printf 'subsection Separation\n  subsection Site hazard\n    set File = hazard/summary.json\n    set PGA levels = 0.02, 0.05, 0.1\n  end\nend\n'; } > one.prm
n=$((n + 1))
if timeout -k 5 120 "$poundfe" separation one.prm --output one > one.log 2> one.err; then
  python3 - one/summary.json hazard/summary.json <<'PY' && echo "ok   one realization per level: the gap of the closed form, and a warning" || fail "one realization per level"
import json, math, sys
s = json.load(open(sys.argv[1])); h = json.load(open(sys.argv[2]))
pair = s["site_hazard"]["pairs"][0]
c, b = pair["median_at_1g_m"], pair["exponent_b"]
# beta_D ~ 0: P(D > g | a) is the step at a = (g/c)^(1/b); the gap for
# lambda* = -ln(1 - p)/T is c a*^b, a* the PGA of annual rate lambda* on the
# Gumbel fit: I* = u - s ln lambda*, Trifunac-Brady a* = 10^(0.014 + 0.3 I*) cm/s^2
p, T = s["site_hazard"]["target_probability"], s["site_hazard"]["exposure_years"]
rate = -math.log1p(-p) / T
I = h["fit"]["location"] - h["fit"]["scale"] * math.log(rate)
a = 10 ** (0.014 + 0.3 * I) / 100 / 9.80665
exact = c * a ** b
got = pair["gap_for_target_probability_m"]
print(f"gap {got} m, closed form {exact} m, beta_D {pair['dispersion_beta_d']}")
if abs(got - exact) > 1e-8 * exact:
    sys.exit(f"the gap {got} m is not the closed form {exact} m")
if not any("rests on 1 realization" in w for w in s.get("warnings", [])):
    sys.exit("no warning in summary.json")
PY
  grep -q "warning: pair shear3-shear2: the demand's dispersion beta_D = .* rests on 1 realization" one.log one.err ||
    fail "one realization per level: no warning on the console"
else
  fail "one realization per level: exit $?: $(head -c 400 one.err)"
fi

report "issue-28 hostile-input"
