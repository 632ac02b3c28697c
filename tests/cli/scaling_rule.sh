#!/usr/bin/env bash
# One rule for scaling a ground motion (doc/verification.md, "Scaling
# rule"): with Target PGA and Scale factor both given, the PGA is their
# product, for each horizontal record file (each brought to Target PGA by its
# own peak); and the three texts that describe it, the parameters' help
# (print-parameters, whence the guide's tables), the user guide's prose and
# the theory manual, state that same rule.
#   scaling_rule.sh POUNDFE SOURCE_DIR
set -u
poundfe=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1
fail() { echo "FAIL $*"; exit 1; }

printf '0\n0.1\n-0.4\n0.3\n0\n' > x.txt   # PGA 0.4 g
printf '0\n0.8\n-0.2\n0.1\n0\n' > y.txt   # PGA 0.8 g
cat > scaled.prm <<'PRM'
subsection Model
  set Dimension = 3
end
subsection Building 1
  set Type = shear
  subsection Plan
    set Plan dimensions = 6, 6
  end
end
subsection Ground motion
  set Type         = record
  set Scale factor = 1.5
  set Components   = 2
  subsection Record
    set File        = x.txt
    set Second file = y.txt
    set Time step   = 0.01
    set Target PGA  = 0.2
  end
end
subsection Output
  set Plots = false
end
PRM
"$poundfe" ground-motion scaled.prm --output out > said 2>&1 || fail "ground-motion: $(cat said)"
# every horizontal component at Target PGA x Scale factor = 0.3 g
python3 - said <<'PY' || exit 1
import re, sys
text = open(sys.argv[1]).read()
pga = float(re.search(r"PGA = \S+ m/s\^2 \((\S+) g\)", text).group(1))
peaks = [float(p) for p in re.findall(r"peak (\S+) m/s\^2", text)]
# the report prints 6 significant digits
assert abs(pga - 0.3) < 1e-5 * 0.3, f"PGA {pga} g, expected 0.2 x 1.5 = 0.3 g"
assert len(peaks) == 2, text
for p in peaks:
    assert abs(p / 9.80665 - 0.3) < 1e-5 * 0.3, f"a component's peak {p / 9.80665} g, expected 0.3 g"
print(f"ok   PGA {pga} g of both components = Target PGA 0.2 g x Scale factor 1.5")
PY
# the same rule in the three texts (whitespace and markup aside)
rule="the PGA is Target PGA x Scale factor"
"$poundfe" print-parameters | tr -s ' \n#' ' ' | grep -qF "$rule" ||
  fail "print-parameters lacks '$rule'"
for doc in theory.md user-guide.md; do
  tr -s ' \n' ' ' < "$src/doc/$doc" | sed 's/[`*]//g; s/×/x/g' | grep -qF "$rule" ||
    fail "doc/$doc lacks '$rule'"
  tr -s ' \n' ' ' < "$src/doc/$doc" | grep -qiF "Scale factor is not applied" &&
    fail "doc/$doc still says the Scale factor is not applied with a Target PGA"
done
echo "ok   '$rule' in print-parameters, doc/theory.md and doc/user-guide.md"
