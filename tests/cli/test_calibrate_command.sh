#!/usr/bin/env bash
# End-to-end checks of `blockdem calibrate` (docs/calibration.md): a fit from r, from r^2 and
# from a decay of peaks; the keys it prints load in a scenario that `blockdem check` accepts;
# fitting kn; and bad input (exit 2 with a message naming the option), a block too squat to rock
# or whose friction is below b/h among it; --toml that cannot be written exits 4.
# The blocks are 0.2 m wide concrete, kn = 1e7 N/m: each DEM run takes a few milliseconds.
# Usage: test_calibrate_command.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }
block=(--width 0.2 --height 1.0 --kn 1e7 --termination zero_overlap)

# 1. From r: 0.96 of Housner's r for aspect 5 (Housner: 1 - 1.5 / 26 = 0.942308).
out=$("$bin" calibrate "${block[@]}" --restitution 0.9046 --toml "$tmp/keys.toml" 2>&1); rc=$?
[ $rc -eq 0 ] || fail "calibrate --restitution exited $rc: $out"
expect_in "$out" "Housner     r = 1 - 1.5 sin^2 alpha = 0.942308"
expect_in "$out" "fit         h_n = "
expect_in "$out" 'termination = "zero_overlap"'
achieved=$(sed -n 's/^fit .*: r = \([0-9.]*\) .*/\1/p' <<<"$out")
/usr/bin/python3 -c "import sys; a=float(sys.argv[1]); sys.exit(0 if abs(a - 0.9046) <= 1e-3 else 1)" "$achieved" \
  || fail "achieved r '$achieved' is not within 1e-3 of 0.9046"
h_from_r=$(sed -n 's/^h_n = \([0-9.]*\) .*/\1/p' "$tmp/keys.toml")
[ -n "$h_from_r" ] || fail "no h_n in the keys file: $(cat "$tmp/keys.toml")"

# 2. The keys paste into a scenario: the same block on a table, checked by `blockdem check`.
{ cat <<'TOML'
[simulation]
duration = 0.5
[[bodies]]
name = "table"
kind = "fixed"
shape = "rectangle"
width = 4.0
height = 0.2
center = [0.0, -0.1]
[[bodies]]
name = "block"
shape = "rectangle"
width = 0.2
height = 1.0
center = [0.0, 0.5]
density = 2400.0
TOML
  cat "$tmp/keys.toml"; } > "$tmp/scenario.toml"
out=$("$bin" check "$tmp/scenario.toml" 2>&1); rc=$?
[ $rc -eq 0 ] || fail "check of the pasted keys exited $rc: $out"
expect_in "$out" "h_n = $(printf '%.4g' "$h_from_r")"
expect_in "$out" "termination = zero_overlap"

# 3. From r^2: the same target gives the same fit.
out=$("$bin" calibrate "${block[@]}" --energy-ratio "$(/usr/bin/python3 -c 'print(0.9046**2)')" 2>&1); rc=$?
[ $rc -eq 0 ] || fail "calibrate --energy-ratio exited $rc: $out"
expect_in "$out" "h_n = $h_from_r"

# 4. From a decay of peaks [deg]: per-impact r read from the peaks, the first peak is the release.
out=$("$bin" calibrate "${block[@]}" --peaks 5.0,4.2,3.5 --peaks-unit deg 2>&1); rc=$?
[ $rc -eq 0 ] || fail "calibrate --peaks exited $rc: $out"
expect_in "$out" "3 peaks, 2 impacts"
expect_in "$out" "released from 0.0872665 rad"

# 5. kn fitted at a given damping.
out=$("$bin" calibrate --width 0.2 --height 1.0 --kn 1e8 --fit kn --h-n 0.9 --restitution 0.9046 2>&1); rc=$?
[ $rc -eq 0 ] || fail "calibrate --fit kn exited $rc: $out"
expect_in "$out" "fit         kn = "
expect_in "$out" "# [N/m] per contact point, fitted"

# 6. Bad input: exit 2 and a message naming the option.
expect_bad() {
  local part=$1; shift
  out=$("$bin" calibrate "$@" 2>&1); rc=$?
  [ $rc -eq 2 ] || fail "calibrate $* exited $rc, expected 2: $out"
  expect_in "$out" "$part"
}
expect_bad "--width" --width -0.2 --height 1.0 --kn 1e7 --restitution 0.9
expect_bad "--kn" --width 0.2 --height 1.0 --kn 0 --restitution 0.9
expect_bad "must be in (0, 1)" "${block[@]}" --restitution 1.2
expect_bad "give exactly one of" "${block[@]}" --restitution 0.9 --energy-ratio 0.81
expect_bad "free rocking only decays" "${block[@]}" --peaks 3,4 --peaks-unit deg
expect_bad "or the block would topple" "${block[@]}" --peaks 20,10 --peaks-unit deg
expect_bad "--fit kn needs" "${block[@]}" --fit kn --restitution 0.9
# A friction far below b/h (0.05 < 0.2 / 0.6): the block slides, and the "fit" came from runs
# with per-impact r of 1.23 and 1.25: refused after the fit (exit 3), naming the impact. A
# friction below b/h alone is no obstacle: a free-rocking square block at mu 0.8 fits (below).
out=$("$bin" calibrate --width 0.2 --height 0.6 --kn 1e7 --restitution 0.8 --mu 0.05 2>&1); rc=$?
[ $rc -eq 3 ] || fail "a sliding block's fit: exit $rc, expected 3: $out"
expect_in "$out" "gained energy at impact"
out=$("$bin" calibrate --width 0.5 --height 0.5 --kn 1e8 --restitution 0.2 --mu 0.8 2>&1) || fail "a square block at mu 0.8: $out"
expect_in "$out" "fit         h_n = "
# A squat block (width / height 10: Housner's r = -0.485) cannot rock on: refused before any DEM
# run (it ran and failed with "raise kn").
expect_bad "key '--width': with --height 0.2 m: width / height = 10 is at least sqrt(2), so Housner's r = 1 - 1.5 sin^2 alpha = -0.4851 <= 0" --width 2 --height 0.2 --kn 1e7 --restitution 0.8
out=$("$bin" calibrate --width 2 --height 0.2 --kn 1e7 --restitution 0.8 2>&1)
grep -q "DEM runs\|raise kn" <<<"$out" && fail "the squat block was run: $out"
# --toml to a full device: exit 4 naming it (it exited 1), where a device node can be made.
if mknod "$tmp/full" c 1 7 2>/dev/null; then
  out=$("$bin" calibrate "${block[@]}" --restitution 0.9046 --toml "$tmp/full" 2>&1); rc=$?
  [ $rc -eq 4 ] || fail "--toml to a full device: exit $rc, expected 4: $out"
  expect_in "$out" "could not write the output: $tmp/full: cannot write"
fi
# Far below Housner's r with a stiff no-tension contact: not reachable, and the message says
# what is.
expect_bad "is not reachable by fitting h_n (kn = 1e+09 N/m)" --width 0.2 --height 1.0 --kn 1e9 --restitution 0.7
expect_bad "Below Housner's r a stiff contact cannot go" --width 0.2 --height 1.0 --kn 1e9 --restitution 0.7

[ $failures -eq 0 ] && echo "all calibrate checks passed"
exit $failures
