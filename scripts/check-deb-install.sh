#!/usr/bin/env bash
# Installs poundfe's Debian package on a fresh Debian 12 and runs it there:
# a minimal bookworm system made by debootstrap in ROOT, the package
# installed into it by apt from the .deb alone (apt must find every
# dependency in Debian's archive from the package's Depends, recommended
# packages left out), then inside that system, with no PYTHONPATH:
#   poundfe --version
#   poundfe run of the default example (input/two-buildings.prm as installed
#     in /usr/share/doc/poundfe/examples), which must complete
#   python3 -c "import poundfe; ..." running the same example in memory and
#     checking it against the command line's drift.csv
# then, with the recommended gnuplot-nox and openmpi-bin, the run's figures
# and `mpirun -np 2 poundfe montecarlo`, and removes the package again
# (nothing of it left in dist-packages).
# It downloads a Debian system and deal.II's dependencies (~400 MB; 2.3 GB
# unpacked) and
# needs root (debootstrap, chroot, mount): not run by CI.
#
#   scripts/check-deb-install.sh DEB ROOT
#     DEB   the package: `cpack -G DEB` in the build directory
#     ROOT  a directory outside the repository for the system; made by
#           debootstrap when it holds none (kept, so that a second check
#           reuses it; remove it to start again from a fresh system)
#   MIRROR (environment): Debian mirror, http://deb.debian.org/debian by default
set -eu
[ $# -eq 2 ] || { echo "usage: $0 DEB ROOT" >&2; exit 1; }
deb=$(readlink -f "$1") root=$(readlink -m "$2")
mirror=${MIRROR:-http://deb.debian.org/debian}
[ -f "$deb" ] || { echo "no package $deb" >&2; exit 1; }
fail() { echo "FAIL $*"; exit 1; }
# the host's own / (by any path, a bind mount too: the same device and inode)
# would get the host's apt sources rewritten and the package installed on it
[ "$(stat -c %d:%i "$root" 2> /dev/null)" != "$(stat -c %d:%i /)" ] ||
  fail "ROOT $2 is this system's own /: give an empty directory for the Debian 12 system"
[ "$(id -u)" = 0 ] || { echo "$0 needs root (debootstrap, chroot)" >&2; exit 1; }

# 1. A fresh Debian 12 (minbase: what every Debian system has, no more).
if [ ! -f "$root/etc/debian_version" ]; then
  command -v debootstrap > /dev/null || apt-get install -y debootstrap
  debootstrap --variant=minbase bookworm "$root" "$mirror"
fi
grep -q '^12\.' "$root/etc/debian_version" || fail "$root is not Debian 12"
# a default installation's archives: the release, its updates and security
cat > "$root/etc/apt/sources.list" <<EOF
deb $mirror bookworm main
deb $mirror bookworm-updates main
deb http://deb.debian.org/debian-security bookworm-security main
EOF
cp /etc/resolv.conf "$root/etc/resolv.conf"
mounted=()
for fs in proc dev dev/pts sys; do
  mountpoint -q "$root/$fs" || { mount --bind "/$fs" "$root/$fs"; mounted=("$root/$fs" "${mounted[@]}"); }
done
# a mount left would keep the host's /dev, /proc, /sys under ROOT, where
# `rm -rf ROOT` reaches them: the check fails, naming each one
cleanup() {
  local status=$? left=()
  for m in "${mounted[@]}"; do
    umount "$m" || true
    ! mountpoint -q "$m" || left+=("$m")
  done
  if [ ${#left[@]} -gt 0 ]; then
    echo "FAIL still mounted after cleanup: ${left[*]}; umount them before removing $root" >&2
    exit 1
  fi
  exit "$status"
}
trap cleanup EXIT
inside() {
  chroot "$root" env -i PATH=/usr/sbin:/usr/bin:/sbin:/bin HOME=/root LANG=C.UTF-8 \
    DEBIAN_FRONTEND=noninteractive "$@"
}

# 2. The package by apt, its dependencies from the archive alone.
cp "$deb" "$root/tmp/poundfe.deb"
inside apt-get update -q > "$root/tmp/apt-update.log" || { cat "$root/tmp/apt-update.log"; fail "apt-get update"; }
inside apt-get install -y -q --no-install-recommends /tmp/poundfe.deb \
  > "$root/tmp/apt-install.log" 2>&1 || { tail -30 "$root/tmp/apt-install.log"; fail "apt-get install of the package"; }
echo "ok   installed: $(inside dpkg-query -W -f '${Package} ${Version}' poundfe)" \
     "with $(grep -c '^Setting up' "$root/tmp/apt-install.log") packages set up"

# 3. The program and the module, as a user of that system runs them.
inside poundfe --version | grep -q '^poundfe' || fail "poundfe --version"
echo "ok   $(inside poundfe --version | head -1)"
example=/usr/share/doc/poundfe/examples/input/two-buildings.prm
inside sh -c "cd /tmp && rm -rf example && poundfe run $example --output example > run.log 2>&1" ||
  { cat "$root/tmp/run.log"; fail "poundfe run of the default example"; }
grep -q '"status": "completed' "$root/tmp/example/summary.json" || fail "the default example did not complete"
echo "ok   poundfe run $example: $(grep -o '"status": "[^"]*"' "$root/tmp/example/summary.json")"
cat > "$root/tmp/check_module.py" <<EOF
import os
import numpy as np
import poundfe
assert "PYTHONPATH" not in os.environ
results = poundfe.run(poundfe.read("$example"))
drift = np.loadtxt("example/drift.csv", delimiter=",", skiprows=1)
assert np.array_equal(results.drift.data, drift), "drift differs from the command line's"
print("ok   import poundfe from", os.path.dirname(poundfe.__file__) + ": the default example's",
      "drift in memory equal to the command line's,", drift.shape[0], "rows")
EOF
inside sh -c "cd /tmp && python3 check_module.py" || fail "import poundfe and run the default example"

# 4. With what the package recommends (apt installs it unless told not to):
# the run draws its figures and completes without warnings, and mpirun runs
# an MPI command on two ranks.
inside apt-get install -y -q gnuplot-nox openmpi-bin \
  > "$root/tmp/apt-recommends.log" 2>&1 || { tail -20 "$root/tmp/apt-recommends.log"; fail "apt-get install gnuplot-nox openmpi-bin"; }
inside sh -c "cd /tmp && rm -rf example && poundfe run $example --output example > run.log 2>&1" ||
  { cat "$root/tmp/run.log"; fail "poundfe run with gnuplot"; }
grep -q '"status": "completed"' "$root/tmp/example/summary.json" ||
  fail "the default example with gnuplot: $(grep -o '"status": "[^"]*"' "$root/tmp/example/summary.json")"
# the figures of the default example (its summary.json also lists any that
# gnuplot could not draw under "missing_figures")
for png in drift_profile acceleration_profile roof_displacement energy ground_motion contact_force; do
  [ -s "$root/tmp/example/$png.png" ] || fail "the default example with gnuplot drew no $png.png"
done
echo "ok   with gnuplot: completed, $(ls "$root/tmp/example/"*.png | wc -l) figures"
montecarlo=/usr/share/doc/poundfe/examples/input/montecarlo-pounding.prm
inside env OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 \
  sh -c "cd /tmp && rm -rf mc && mpirun -np 2 poundfe montecarlo $montecarlo --output mc --set 'Monte Carlo/Realizations=4' > mc.log 2>&1" ||
  { cat "$root/tmp/mc.log"; fail "mpirun -np 2 poundfe montecarlo"; }
grep -q '"status": "completed' "$root/tmp/mc/summary.json" || fail "montecarlo on two ranks did not complete"
echo "ok   mpirun -np 2 poundfe montecarlo $montecarlo: $(grep -o '"ranks": [0-9]*' "$root/tmp/mc/summary.json" | head -1)"

# 5. Removed, it leaves nothing in dist-packages (the compiled files too).
inside apt-get remove -y -q poundfe > "$root/tmp/apt-remove.log" 2>&1 ||
  { tail -20 "$root/tmp/apt-remove.log"; fail "apt-get remove"; }
[ ! -e "$root/usr/lib/python3/dist-packages/poundfe" ] || fail "dist-packages/poundfe left after removal"
echo "ok   removed: nothing left in /usr/lib/python3/dist-packages/poundfe"
