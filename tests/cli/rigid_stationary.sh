#!/usr/bin/env bash
# stationary-pdf with rigid contact (Contact/Model = nonsmooth): the linear
# oscillator of stationary-linear.prm (m = 1, k = 1, c = 1 under white noise
# of intensity D = 0.1) against a rigid barrier at its equilibrium (x <= 0)
# with restitution e = 1, whose stationary response is the linear one
# folded, x = -|y| (stationary_pdf_check.py impact: p(x) = 2 p_y(x) on
# x <= 0, the mean and variance of the half-normal, v and the amplitude
# unchanged; 4 standard errors of N_eff = T / (2 tau_c) effectively
# independent samples), at 1e-2 s (Moreau-Jean takes an impact within a
# step: the fold is blurred by ~ h sigma_v = 3e-3 m against sigma = 0.32 m).
# The commands whose method rigid contact cannot give refuse it saying why.
set -u
poundfe=$1 input=$2
here=$(cd "$(dirname "$0")" && pwd)
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
. "$here/expect.sh"

if ! "$poundfe" --version | grep -q "nonsmooth"; then
  echo "rigid-stationary: this build has no Siconos (penalty only): nothing to check"
  exit 0
fi
sed -e 's/^\( *set Time step *=\).*/\1 0.01/' -e 's/^\( *set Duration *=\).*/\1 1020/' \
    -e 's/^\( *set Number of realizations *=\).*/\1 16/' "$input" > impact.prm
printf 'subsection Contact\n  set Model = nonsmooth\n  set Law = linear\n  set Barriers = 1 1 right 0\n  set Coefficient of restitution = 1\nend\n' >> impact.prm
"$poundfe" stationary-pdf impact.prm --output pdf > pdf.out 2> pdf.err ||
  fail "stationary-pdf exited $?: $(head -c 300 pdf.err)"
python3 "$here/stationary_pdf_check.py" pdf impact 0.1 1 1 || fail "the folded densities"
# the refusals that say why (dynamic-form, bifurcation)
expect 1 "Moreau-Jean's time stepping takes an impact" dynamic-form impact.prm --output out
expect 1 "Lyapunov exponent follows a neighbouring trajectory" bifurcation impact.prm --output out
echo "rigid-stationary: $n refusals checked, $failures failures"
exit $((failures > 0))
