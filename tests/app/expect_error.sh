#!/usr/bin/env bash
# expect_error.sh PATTERN COMMAND...: the command must fail cleanly: exit code 1 or 2 (not a
# crash or a signal), print PATTERN (extended regex) on stderr, and no sanitizer report.
set -u
pattern=$1
shift
err=$(mktemp)
"$@" >/dev/null 2>"$err"
code=$?
status=0
if [ "$code" -ne 1 ] && [ "$code" -ne 2 ]; then
  echo "expected exit code 1 or 2, got $code"; status=1
fi
if ! grep -Eq -- "$pattern" "$err"; then
  echo "stderr does not match /$pattern/"; status=1
fi
if grep -Eq "AddressSanitizer|runtime error:|LeakSanitizer" "$err"; then
  echo "sanitizer report"; status=1
fi
if [ $status -ne 0 ]; then echo "--- stderr:"; cat "$err"; fi
rm -f "$err"
exit $status
