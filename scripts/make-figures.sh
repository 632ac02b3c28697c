#!/usr/bin/env bash
# Regenerate the figures the README shows (doc/figures/*.png) from the
# examples in input/, with the build in build/. About 2 minutes.
#   phase-portrait-sd.png   poundfe run input/sd-oscillator.prm (thesis Fig. 3.1 form)
#   bifurcation-sd.png      poundfe bifurcation input/sd-bifurcation.prm (Fig. 3.2 form)
#   p-bifurcation-sd.png    poundfe stationary-pdf input/sd-oscillator-noise.prm swept over
#                           alpha = Springs/SD springs:6 (Figs. 3.3-3.4 form)
#   spillway-sliding.png    poundfe run input/spillway-sliding.prm (phase portrait)
#   default-*.png           poundfe run input/two-buildings.prm (the default example):
#                           drift profile, energy balance, contact forces, a hinge's loop
#   site-hazard.png         poundfe site-hazard input/site-hazard.prm
#   drift-limits.png        poundfe run input/site-hazard.prm (drift profile with limits)
#   spectrum-kt.png, ensemble-spectrum-ec8.png, floor-spectra.png
#                           poundfe spectrum input/floor-spectra.prm [--realizations 50],
#                           poundfe run input/floor-spectra.prm
#   separation.png, pounding-probability.png
#                           poundfe separation input/separation.prm (100 realizations,
#                           about a minute)
#   separation-spectrum.png poundfe separation input/separation-spectrum.prm (response spectrum)
#   pounding-hazard.png     poundfe separation input/separation-hazard.prm (site hazard)
#   3d-torsional-pair-plan.png, 3d-torsional-shear-pair-plan.png
#                           poundfe run input/3d-torsional-pair.prm and
#                           input/3d-torsional-shear-pair.prm (impacts in plan)
set -euo pipefail
cd "$(dirname "$0")/.."
poundfe=build/poundfe
[ -x "$poundfe" ] || { echo "make-figures.sh: build first (scripts/setup.sh)" >&2; exit 1; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
mkdir -p doc/figures

"$poundfe" run input/sd-oscillator.prm --output "$work/sd" > /dev/null
cp "$work/sd/phase_portrait.png" doc/figures/phase-portrait-sd.png

"$poundfe" bifurcation input/sd-bifurcation.prm --output "$work/bifurcation" > /dev/null
cp "$work/bifurcation/bifurcation.png" doc/figures/bifurcation-sd.png

# The noisy SD oscillator's Stationary PDF section, made a sweep over alpha.
sed '/^subsection Stationary PDF/a\
  set Parameter = Springs/SD springs:6\
  set Label     = alpha = H / L of the SD spring\
  set Values    = linspace 0.3 1.5 13' input/sd-oscillator-noise.prm > "$work/p-bifurcation.prm"
"$poundfe" stationary-pdf "$work/p-bifurcation.prm" --output "$work/p-bifurcation" > /dev/null
cp "$work/p-bifurcation/p_bifurcation.png" doc/figures/p-bifurcation-sd.png

"$poundfe" run input/spillway-sliding.prm --output "$work/spillway" > /dev/null
cp "$work/spillway/phase_portrait.png" doc/figures/spillway-sliding.png
"$poundfe" run input/two-buildings.prm --output "$work/default" > /dev/null
for plot in drift_profile energy contact_force; do
  cp "$work/default/$plot.png" "doc/figures/default-${plot//_/-}.png"
done
cp "$work/default"/hysteresis_A3_*.png doc/figures/default-hysteresis.png
"$poundfe" site-hazard input/site-hazard.prm --output "$work/hazard" > /dev/null
cp "$work/hazard/hazard.png" doc/figures/site-hazard.png
"$poundfe" run input/site-hazard.prm --output "$work/limits" > /dev/null
cp "$work/limits/drift_profile.png" doc/figures/drift-limits.png

"$poundfe" spectrum input/floor-spectra.prm --output "$work/spectrum" > /dev/null
cp "$work/spectrum/spectrum.png" doc/figures/spectrum-kt.png
"$poundfe" spectrum input/floor-spectra.prm --realizations 50 --output "$work/ensemble" > /dev/null
cp "$work/ensemble/ensemble_spectrum.png" doc/figures/ensemble-spectrum-ec8.png
"$poundfe" run input/floor-spectra.prm --output "$work/floors" > /dev/null
cp "$work/floors/floor_spectra.png" doc/figures/floor-spectra.png

"$poundfe" separation input/separation.prm --output "$work/separation" > /dev/null
cp "$work/separation/separation.png" doc/figures/separation.png
cp "$work/separation/pounding_probability.png" doc/figures/pounding-probability.png
"$poundfe" separation input/separation-spectrum.prm --output "$work/separation-spectrum" > /dev/null
cp "$work/separation-spectrum/separation.png" doc/figures/separation-spectrum.png
"$poundfe" separation input/separation-hazard.prm --output "$work/separation-hazard" > /dev/null
cp "$work/separation-hazard/pounding_hazard.png" doc/figures/pounding-hazard.png
ls -l doc/figures

for example in 3d-torsional-pair 3d-torsional-shear-pair; do
  "$poundfe" run "input/$example.prm" --output "$work/$example" > /dev/null
  cp "$work/$example/impacts_plan.png" "doc/figures/$example-plan.png"
done
