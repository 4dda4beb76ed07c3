#!/usr/bin/env bash
# help_test.sh EXE OPTIONS [EXE OPTIONS ...]: each benchmark's --help exits 0, names the
# executable in its usage line and lists every option of OPTIONS (comma-separated), each with
# its type and, where it has one, its default.
set -u
status=0
while [ $# -ge 2 ]; do
  exe=$1 options=$2
  shift 2
  name=$(basename "$exe")
  out=$("$exe" --help 2>&1)
  code=$?
  if [ $code -ne 0 ]; then echo "$name --help: exit code $code"; status=1; fi
  if ! grep -q "^Usage: $name \[OPTIONS\]" <<<"$out"; then
    echo "$name --help: no usage line"; status=1
  fi
  IFS=, read -ra list <<<"$options"
  for option in "${list[@]}"; do
    if ! grep -Eq "^  $option [A-Z]+" <<<"$out" && ! grep -Eq "^  $option( |$)" <<<"$out"; then
      echo "$name --help: does not list $option"; status=1
    fi
  done
  [ $status -ne 0 ] && echo "--- $name --help:" && echo "$out"
done
exit $status
