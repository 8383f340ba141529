#!/usr/bin/env bash
# End-to-end checks of `blockdem run` and `blockdem check`: outputs, --set, and bad input
# (message names the file/key/body, non-zero exit, results written before a failure stay).
# Usage: test_run_command.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1; src=$2
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }

# 1. The paper's sliding example runs and writes its outputs.
out=$("$bin" run "$src/examples/paper/sliding.toml" --out "$tmp/sliding" --set simulation.duration=1.0 2>&1) || fail "sliding run failed: $out"
expect_in "$out" "block:"
head -1 "$tmp/sliding/history.csv" | grep -q '^t,table.x,table.y,table.rot,table.vx,table.vy,table.vrot,table.ax,table.ay,table.arot,block.x' \
  || fail "history.csv header: $(head -1 "$tmp/sliding/history.csv")"
rows=$(wc -l < "$tmp/sliding/history.csv")
[ "$rows" -eq 1002 ] || fail "history.csv has $rows lines, expected 1002 (header + 1001 rows at 1 ms for 1 s)"
grep -q '"status": "completed"' "$tmp/sliding/summary.json" || fail "summary status"
grep -q '"balance_error_relative"' "$tmp/sliding/summary.json" || fail "summary energy"

# 2. Each of the paper's four shear damping ratios is one --set away.
for hs in 0 0.01 0.5 1.0; do
  "$bin" run "$src/examples/paper/sliding.toml" --out "$tmp/hs$hs" -q --set contact.h_s=$hs --set simulation.duration=0.2 >/dev/null 2>&1 \
    || fail "h_s = $hs"
  grep -q "h_s = $hs" "$tmp/hs$hs/scenario.toml" || fail "scenario.toml should record h_s = $hs"
done

# 3. check prints the derived quantities.
out=$("$bin" check "$src/examples/paper/sliding.toml" 2>&1) || fail "check failed"
for part in "h_n = 0.28" "stable limit" "is proven stable" "C_n = " "mass [kg]" "peak 3.5 m/s^2"; do expect_in "$out" "$part"; done

# 4. Bad input: a clear message and exit status 2; nothing is run.
run_bad() {  # name, expected text, run arguments...
  local name=$1 want=$2; shift 2
  local msg; msg=$("$bin" "$@" 2>&1); local rc=$?
  [ $rc -eq 2 ] || fail "$name: exit $rc, expected 2 ($msg)"
  expect_in "$msg" "$want"
}
sed 's/^mu = 0.3 /muu = 0.3 /' "$src/examples/paper/sliding.toml" > "$tmp/typo.toml"
run_bad typo "typo.toml:" check "$tmp/typo.toml"
run_bad typo-suggest "did you mean 'mu'?" check "$tmp/typo.toml"
run_bad missing-file "cannot open the file" run "$tmp/nope.toml" --out "$tmp/x"
run_bad bad-set "did you mean 'h_s'?" check "$src/examples/paper/sliding.toml" --set contact.hs=1
run_bad overlap "bodies 'table' and 'block' overlap at the start" check "$src/examples/paper/sliding.toml" --set 'bodies.block.center=[0.0, 0.05]'
run_bad dt "is above the stable limit" check "$src/examples/paper/sliding.toml" --set simulation.dt=0.01
cat > "$tmp/concave.toml" <<'TOML'
[simulation]
duration = 1.0
[contact]
kn = 1e5
ks = 1e5
mu = 0.5
[[bodies]]
name = "arrow"
shape = "polygon"
vertices = [[0.0, 0.0], [0.5, 0.0], [0.5, 0.3], [0.25, 0.0], [0.0, 0.3]]
density = 2000.0
TOML
# (A concave outline is a body since issue 13; this arrow's tip touches its base.)
run_bad concave "key 'bodies.arrow.vertices': vertex 3 (0.25, 0) m lies on the edge from vertex 0 to vertex 1" check "$tmp/concave.toml"
[ ! -e "$tmp/x" ] || fail "a refused run must not create its output folder"

# 5. A run that goes unstable: exit 3, the message names the body and time, and what was
#    written stays readable (history rows complete, summary marked failed).
msg=$("$bin" run "$src/tests/cli/data/unstable_stack.toml" --out "$tmp/unstable" -q 2>&1); rc=$?
[ $rc -eq 3 ] || fail "unstable: exit $rc, expected 3"
expect_in "$msg" "unstable: "
expect_in "$msg" "fastest body 'b"
grep -q '"status": "failed"' "$tmp/unstable/summary.json" || fail "unstable summary status"
awk -F, 'NR == 1 { n = NF } NF != n { bad = 1 } END { exit bad || NR < 10 }' "$tmp/unstable/history.csv" \
  || fail "unstable history.csv is not complete rows"

[ $failures -eq 0 ] && echo "all run/check CLI checks passed"
exit $failures
