#!/usr/bin/env bash
# psd_test.sh VALSALVA: `valsalva psd` on generated probe files.
# 1. Uniform: 2000 samples at 200 Hz of sin(2 pi 12.5 t) + 0.3 sin(2 pi 40 t) (column a_u) and
#    0.5 cos(2 pi 31 t) (a_v). Welch with a Hann window puts the largest bin within df/2 of the
#    tone (df = fs / segment length), so the peaks must be 12.5 and 31 Hz within df/2; the
#    spectrum's variance (sum psd df) must be the signal's within 1%: for a stationary signal they
#    differ only by the window-weighted average over segments versus the plain mean over all
#    samples (measured 0.006%).
# 2. Non-uniform: the same a_u with dt alternating 4 ms and 6 ms (a run whose dt changed): the
#    command must say it resampled, and the peak is still within df/2 of 12.5 Hz.
# 3. --segment-length 400 gives df = 0.5 Hz exactly.
set -eu
app=$1
dir=$(mktemp -d)
trap 'rm -rf "$dir"' EXIT
awk 'BEGIN { pi = atan2(0, -1); print "time,a_u,a_v";
  for (i = 0; i < 2000; i++) { t = i / 200.0;
    printf "%.17g,%.17g,%.17g\n", t, sin(2*pi*12.5*t) + 0.3*sin(2*pi*40*t), 0.5*cos(2*pi*31*t) } }' \
  > "$dir/uniform.csv"
awk 'BEGIN { pi = atan2(0, -1); print "time,a_u"; t = 0;
  for (i = 0; i < 2000; i++) { printf "%.17g,%.17g\n", t, sin(2*pi*12.5*t) + 0.3*sin(2*pi*40*t);
    t += (i % 2 == 0) ? 0.004 : 0.006 } }' > "$dir/jitter.csv"

# peak FILE: frequency of the largest psd (frequency > 0) and df.
peak() { awk -F, 'NR == 2 { next } NR == 3 { df = $1 } NR > 2 && $2 > best { best = $2; f = $1 }
  END { print f, df }' "$1"; }
near() {  # near F DF TARGET: |F - TARGET| <= DF / 2
  awk -v f="$1" -v df="$2" -v t="$3" 'BEGIN { d = f - t; if (d < 0) d = -d; exit !(d <= df / 2) }'
}
status=0
check() { if ! "$@"; then echo "FAILED: $*"; status=1; fi; }

"$app" psd "$dir/uniform.csv" --column a_u --column a_v --out "$dir/u" > "$dir/u.out"
cat "$dir/u.out"
read -r f df < <(peak "$dir/u/psd_a_u.csv")
check near "$f" "$df" 12.5
read -r f df < <(peak "$dir/u/psd_a_v.csv")
check near "$f" "$df" 31
check test -s "$dir/u/psd.png"
# variance X (signal Y) on the a_u line: |X / Y - 1| <= 0.01
check awk '/psd: a_u:/ { v = $0; sub(/.*variance /, "", v); split(v, a, " "); s = $0;
  sub(/.*\(signal /, "", s); sub(/\).*/, "", s); r = a[1] / s; ok = (r > 0.99 && r < 1.01) }
  END { exit !ok }' "$dir/u.out"
if grep -q resampled "$dir/u.out"; then echo "FAILED: uniform series reported as resampled"; status=1; fi

"$app" psd --column a_u --out "$dir/j" --no-plot "$dir/jitter.csv" > "$dir/j.out"  # file last
cat "$dir/j.out"
check grep -q "not uniform.*resampled" "$dir/j.out"
read -r f df < <(peak "$dir/j/psd_a_u.csv")
check near "$f" "$df" 12.5

"$app" psd "$dir/uniform.csv" --column a_u --segment-length 400 --out "$dir/s" --no-plot > /dev/null
read -r f df < <(peak "$dir/s/psd_a_u.csv")
check awk -v df="$df" 'BEGIN { exit !(df == 0.5) }'
check near "$f" "$df" 12.5
exit $status
