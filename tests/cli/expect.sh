# The pattern of the hostile-input tests (hostile_input.sh, issue 14;
# hostile_input_28.sh, issue 28): source it in a scratch directory with
# $poundfe set. `expect STATUS TEXT COMMAND...` runs poundfe and checks the
# exit status, that TEXT is in its messages (stderr, then stdout), that a
# failure says one line, and that exit 1 wrote no output directory `out`.
failures=0
n=0
fail() { echo "FAIL $*"; failures=$((failures + 1)); }

# expect STATUS TEXT COMMAND...: exit status, a message (stderr, one line on
# failure; stdout on success) containing TEXT, no output directory on 1.
expect() {
  local status=$1 text=$2
  shift 2
  n=$((n + 1))
  rm -rf out
  timeout -k 5 60 "$poundfe" "$@" > stdout 2> stderr # -k: a reader blocked on a FIFO ignored SIGTERM
  local got=$?
  local said
  said=$(cat stderr stdout)
  if [ "$got" -ne "$status" ]; then
    fail "$*: exit $got, expected $status: $(head -c 400 stderr)"; return
  fi
  if ! grep -qF -- "$text" stderr stdout; then
    fail "$*: no '$text' in: $(echo "$said" | head -c 400)"; return
  fi
  if [ "$status" -ne 0 ] && [ "$(wc -l < stderr)" -ne 1 ]; then
    fail "$*: expected one line: $(head -c 400 stderr)"; return
  fi
  if [ "$status" -eq 1 ] && [ -e out ]; then
    fail "$*: output written despite bad input"; return
  fi
  echo "ok   $*: $(head -c 200 stderr)"
}

shear() { # a three-storey shear building; $1: extra text inside Building 1
  printf 'subsection Building 1\n  set Type = shear\n  set Number of storeys = 3\n'
  printf '  set Floor masses = 1000\n  set Storey stiffnesses = 5e6\n%s\nend\n' "${1:-}"
  printf 'subsection Output\n  set Plots = false\n  set Number of modes = 3\nend\n'
}

# `report NAME`: the count, and the exit status of the whole script.
report() {
  echo "$n $1 cases, $failures failures"
  [ "$failures" -eq 0 ]
}
