#!/usr/bin/env bash
# The installed program (cmake --install) and its Debian package (cpack -G
# DEB): the installed tree holds the program, the Python package where
# Debian's python3 finds it, the documentation and the examples; the
# installed program runs the default example from anywhere to the build's
# numbers; the Python tests pass against the installed module with the build
# tree off the path; the package lists the same files, names its
# dependencies, and runs unpacked.
# Arguments: BUILD SOURCE [PYTHON PYTHONDIR] (PYTHONDIR relative to the
# prefix; no Python part without them).
set -eu
build=$1 source=$2 python=${3:-} pydir=${4:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL $*"; exit 1; }
prefix=$work/prefix doc=share/doc/poundfe

# 1. The installed tree.
cmake --install "$build" --prefix "$prefix" > "$work/install.log" || { cat "$work/install.log"; fail "cmake --install"; }
[ -x "$prefix/bin/poundfe" ] || fail "no bin/poundfe"
# what the tree must hold: the program, the docs, every example and mesh
expected=(bin/poundfe "$doc/README.md" "$doc/CHANGELOG.md" "$doc/doc/user-guide.md"
          "$doc/doc/figures/default-drift-profile.png")
for file in $(cd "$source" && find input meshes -type f | sort); do expected+=("$doc/examples/$file"); done
if [ -n "$python" ]; then
  for file in "$source"/source/python/poundfe/*.py; do expected+=("$pydir/poundfe/$(basename "$file")"); done
fi
for file in "${expected[@]}"; do [ -f "$prefix/$file" ] || fail "not installed: $file"; done
# the compiled parts of the Python package: the full module's and the interpreter's
if [ -n "$python" ]; then
  for extension in _core _opensees; do
    compgen -G "$prefix/$pydir/poundfe/$extension.*.so" > /dev/null || fail "not installed: $extension"
  done
fi
# the program module bin/poundfe loads, in LIBDIR/poundfe (CMakeLists.txt)
# and the OpenSees interpreter's module beside it
for module in poundfe-program.so poundfe-opensees.so; do
  [ -n "$(find "$prefix/lib" -path "*/poundfe/$module" 2> /dev/null)" ] ||
    fail "no lib/.../poundfe/$module"
done
# and nothing else at its top: no test, bench or build file
top=$(cd "$prefix" && ls | tr '\n' ' ')
[ "$top" = "bin lib share " ] || [ "$top" = "bin share " ] || fail "unexpected top of the tree: $top"
[ "$(ls "$prefix/bin")" = poundfe ] || fail "bin holds more than poundfe: $(ls "$prefix/bin")"
# no path of the build tree in the installed program's run path
if readelf -d "$prefix/bin/poundfe" | grep -E 'RPATH|RUNPATH' | grep -qF "$build"; then
  fail "bin/poundfe's run path names the build tree"
fi
echo "ok   installed tree (${#expected[@]} files checked)"

# 2. The installed program from a scratch directory, on the installed example.
mkdir "$work/run" && cd "$work/run"
installed=$prefix/bin/poundfe examples=$prefix/$doc/examples
"$installed" --version | grep -q poundfe || fail "--version"
"$installed" template pounding | cmp -s - "$source/input/templates/pounding.prm" || fail "template pounding"
"$installed" modal "$examples/input/setback-frame.prm" --output modal > /dev/null ||
  fail "modal of the installed Gmsh example (../meshes/setback.msh) exited $?"
# the default example as scripts/run-example.sh runs it (3 s: no need to shorten it)
example=$examples/input/two-buildings.prm
"$installed" modal "$example" --output installed/modal > /dev/null || fail "installed modal exited $?"
"$installed" run "$example" --output installed > /dev/null || fail "installed run exited $?"
"$build/poundfe" run "$example" --output built > /dev/null || fail "built run exited $?"
grep -q '"status": "completed' installed/summary.json || fail "installed run not completed"
for file in drift.csv impacts.csv contact_force.csv energy.csv; do
  cmp -s installed/$file built/$file || fail "$file differs between the installed and the built program"
done
# an OpenSees script, through the installed interpreter's module
mkdir opensees
"$installed" opensees "$source/tests/opensees/sdof_linear.tcl" opensees > opensees.log 2>&1 ||
  fail "installed opensees exited $?: $(cat opensees.log)"
[ -s opensees/sdof_disp.out ] || fail "installed opensees wrote no sdof_disp.out: $(ls opensees)"
echo "ok   installed poundfe: default example identical to build/poundfe's; an OpenSees script runs"

# 3. The Python tests against the installed module, the build tree off the path.
if [ -n "$python" ]; then
  if "$python" -c 'import sysconfig, sys; sys.exit("deb_system" not in sysconfig.get_scheme_names())'; then
    [ "$pydir" = lib/python3/dist-packages ] || fail "Debian's python3, but the module goes to $pydir"
    # installed with --prefix /usr, python3 finds it with no PYTHONPATH
    env -u PYTHONPATH "$python" -c 'import sys; sys.exit("/usr/lib/python3/dist-packages" not in sys.path)' ||
      fail "/usr/lib/python3/dist-packages is not on $python's path"
  fi
  export PYTHONPATH=$prefix/$pydir POUNDFE=$installed PYTHONDONTWRITEBYTECODE=1
  where=$("$python" -c 'import poundfe, sys; print(poundfe.__file__); print(*sys.path)')
  case "$where" in "$prefix/$pydir/poundfe/__init__.py"*) ;; *) fail "poundfe imported from: $where" ;; esac
  case "$where" in *"$build"*) fail "the build tree is on Python's path: $where" ;; esac
  cd "$source/tests/python"
  tests=$(ls test_*.py | sed 's/\.py$//' | tr '\n' ' ')
  "$python" -m unittest $tests > "$work/python.log" 2>&1 || { tail -30 "$work/python.log"; fail "Python tests"; }
  echo "ok   Python tests against the installed module: $(tail -3 "$work/python.log" | tr '\n' ' ')"
  cd "$work"
fi

# 4. The Debian package, when cpack and dpkg-deb are there. Its shared
# libraries' dependencies (dpkg-shlibdeps reads the symbol tables of deal.II,
# PETSc and Trilinos: over 30 s of CPU) are computed only with
# POUNDFE_TEST_SHLIBDEPS=1; the package's other fields and its contents are
# the same without.
if ! command -v cpack > /dev/null || ! command -v dpkg-deb > /dev/null; then
  echo "skip Debian package: no cpack or dpkg-deb"
  exit 0
fi
shlibdeps=OFF
[ "${POUNDFE_TEST_SHLIBDEPS:-0}" = 1 ] && shlibdeps=ON
cpack -G DEB --config "$build/CPackConfig.cmake" -B "$work/deb" -D CPACK_DEBIAN_PACKAGE_SHLIBDEPS=$shlibdeps \
  > "$work/cpack.log" 2>&1 || { tail -30 "$work/cpack.log"; fail "cpack -G DEB"; }
deb=$(ls "$work"/deb/poundfe_*.deb)
dpkg-deb -c "$deb" | awk '{print $NF}' | sed 's|^\./|/|' > "$work/contents"
for file in "${expected[@]}"; do
  grep -qxF "/usr/$file" "$work/contents" || fail "not in the package: /usr/$file"
done
for extension in _core _opensees; do # the full module's and the lean interpreter's
  grep -q "^/usr/$pydir/poundfe/$extension.*\.so$" "$work/contents" || [ -z "$python" ] ||
    fail "no $extension module in the package"
done
grep -v -e '^/usr/$' -e '^/usr/bin/' -e '^/usr/share/' -e '^/usr/lib/' -e '^/$' "$work/contents" &&
  fail "the package has files outside /usr/bin, /usr/lib and /usr/share"
dpkg-deb -f "$deb" > "$work/control"
field() { sed -n "s/^$1: //p" "$work/control"; }
version=$(sed -n 's/^ *set(CPACK_PACKAGE_VERSION "\(.*\)")/\1/p' "$build/CPackConfig.cmake")
[ "$(field Package)" = poundfe ] || fail "Package: $(field Package)"
[ "$(field Version)" = "$version" ] || fail "Version: $(field Version), project(): $version"
[ "$(field Section)" = science ] || fail "Section: $(field Section)"
field Maintainer | grep -q '<.*@.*>' || fail "Maintainer: $(field Maintainer)"
if [ $shlibdeps = ON ]; then
  field Depends | grep -q 'libdeal.ii' || fail "Depends without deal.II: $(field Depends)"
fi
if [ -n "$python" ]; then
  field Depends | grep -q 'python3-numpy' || fail "Depends without python3-numpy: $(field Depends)"
  field Depends | grep -q 'python3 (>= ' || fail "Depends without python3: $(field Depends)"
fi
field Recommends | grep -q 'gnuplot-nox' || fail "Recommends without gnuplot-nox: $(field Recommends)"
dpkg-deb -I "$deb" postinst > /dev/null && dpkg-deb -I "$deb" prerm > /dev/null || fail "no postinst/prerm"
# unpacked, it runs
dpkg -x "$deb" "$work/root"
"$work/root/usr/bin/poundfe" modal "$work/root/usr/$doc/examples/input/three-storey-shear.prm" \
  --output "$work/unpacked-modal" > /dev/null || fail "the unpacked program exited $?"
if [ -n "$python" ]; then
  PYTHONPATH=$work/root/usr/$pydir "$python" -c 'import poundfe, sys; sys.exit(not poundfe.__file__.startswith(sys.argv[1]))' \
    "$work/root/usr/$pydir" || fail "import poundfe from the unpacked package"
fi
echo "ok   $(basename "$deb"): $(wc -l < "$work/contents") entries; Depends: $(field Depends | cut -c1-120)..."
