#!/usr/bin/env bash
# scripts/check-deb-install.sh refuses, before it needs root or touches
# anything, a ROOT that is the host's own / by any path: "/", "/." and a
# symbolic link to / (the same device and inode as /). Run as an
# unprivileged user when the test runs as root, so that a script that did
# not refuse stops at its root check instead of installing on the host.
set -u
script=$1
work=$(mktemp -d)
chmod 755 "$work"
trap 'rm -rf "$work"' EXIT
die() { echo "FAIL $*"; exit 1; }
: > "$work/poundfe.deb"
ln -s / "$work/host"
as_user=()
[ "$(id -u)" -ne 0 ] || as_user=(setpriv --reuid=65534 --regid=65534 --clear-groups)
for root in / /. "$work/host"; do
  out=$("${as_user[@]}" bash "$script" "$work/poundfe.deb" "$root" 2>&1) && die "ROOT $root accepted"
  grep -qF "ROOT $root is this system's own /" <<< "$out" || die "ROOT $root: $out"
done
echo "ok   check-deb-install.sh refuses the host's / as ROOT (/, /., a link to /)"
