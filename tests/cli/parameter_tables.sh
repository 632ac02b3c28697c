#!/usr/bin/env bash
# doc/user-guide.md's parameter tables are those scripts/parameter-tables.py
# makes from `poundfe print-parameters` now: a parameter added, renamed or
# re-documented without regenerating the guide fails here.
#   parameter_tables.sh POUNDFE SOURCE_DIR
set -u
poundfe=$1 src=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cp "$src/doc/user-guide.md" "$work/guide.md"
python3 "$src/scripts/parameter-tables.py" --binary "$poundfe" --update "$work/guide.md" || exit 1
if ! diff -q "$src/doc/user-guide.md" "$work/guide.md" > /dev/null; then
  diff "$src/doc/user-guide.md" "$work/guide.md" | head -20
  echo "FAIL: doc/user-guide.md's tables are out of date: python3 scripts/parameter-tables.py --update doc/user-guide.md"
  exit 1
fi
echo "ok: the guide's parameter tables match print-parameters"
