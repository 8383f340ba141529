#!/usr/bin/env bash
# End-to-end: [contact] young_modulus derives kn and ks (docs/physics.md, "Choosing the contact
# stiffness"); `blockdem check` prints the derivation, the contact period and the static
# overlap; a modulus given with kn, and a settling that fails, are reported by name.
# Usage: test_material_stiffness.sh BLOCKDEM SOURCE_DIR
set -u
bin=$1
tmp=$(mktemp -d); trap 'rm -rf "$tmp"' EXIT
failures=0
fail() { echo "FAIL: $*"; failures=$((failures + 1)); }
expect_in() { grep -qF -- "$2" <<<"$1" || fail "expected '$2' in: $1"; }

# Three 0.6 x 0.9 m drums of E = 30 GPa: kn = E t w / (2 h) = 1e10 N/m, ks = kn / 2.4.
cat > "$tmp/column.toml" <<'TOML'
[simulation]
duration = 0.5
[contact]
young_modulus = 30.0e9
poisson_ratio = 0.2
mu = 0.7
e = 0.4
[[bodies]]
name = "table"
kind = "driven"
shape = "rectangle"
width = 4.0
height = 0.2
center = [0.0, -0.1]
[[assemblies]]
type = "column"
name = "drum"
base_center = [0.0, 0.0]
count = 3
width = 0.6
height = 0.9
density = 2600.0
TOML
out=$("$bin" check "$tmp/column.toml" 2>&1) || fail "check failed: $out"
expect_in "$out" "default / default: kn = 1e+10 N/m, ks = 4.167e+09 N/m"
expect_in "$out" "rule block_deformability: E = 3e+10 Pa, nu = 0.2, typical block 0.9 m high, 0.6 m wide, 1 m thick"
expect_in "$out" "kn'' = 3.333e+10 Pa/m"
# T = 2 pi sqrt(1404 / 1e10) = 2.354 ms; m g / kn = 1.377e-6 m = 1.53e-6 of 0.9 m.
expect_in "$out" "shortest T = 0.002354 s (drum0)"
expect_in "$out" "largest overlap 1.38e-06 m = 1.53e-06 of the body's height"
# The run uses it: twice E, the stable step shrinks by sqrt(2).
limit() { "$bin" check "$tmp/column.toml" "$@" | sed -n 's/.*stable limit \([^ ]*\) s.*/\1/p'; }
ratio=$(/usr/bin/python3 -c "print(abs($(limit) / $(limit --set contact.young_modulus=60e9) - 2 ** 0.5) < 1e-3)")
[ "$ratio" = "True" ] || fail "stable limit at 2 E: not 1 / sqrt(2) of the limit at E"
"$bin" run "$tmp/column.toml" --out "$tmp/run" -q > /dev/null 2>&1 || fail "run failed"

# A modulus with an explicit kn: which wins is not obvious, so it is refused by key.
msg=$("$bin" check "$tmp/column.toml" --set contact.kn=1e9 2>&1); rc=$?
[ $rc -eq 2 ] || fail "modulus with kn: exit $rc, expected 2"
expect_in "$msg" "key 'contact.kn': give either young_modulus"

# A block toppling off a narrow table cannot settle: the message names it and how far it went.
# (The model's extent is given large so that it is still falling, not taken out, at 1.5 s.)
cat > "$tmp/falls.toml" <<'TOML'
[simulation]
duration = 0.1
domain = [[-100.0, -100.0], [100.0, 100.0]]
[contact]
kn = 1.0e7
ks = 1.0e7
mu = 0.6
e = 0.4
[[bodies]]
name = "table"
kind = "fixed"
shape = "rectangle"
width = 0.4
height = 0.2
center = [-0.1, -0.1]
[[bodies]]
name = "leaning"
shape = "polygon"
vertices = [[0.0, 0.000001], [0.422618262, 0.906308787], [0.150725926, 1.033094266], [-0.271892336, 0.126786479]]
density = 2400.0
[settling]
max_time = 1.5
TOML
msg=$("$bin" check "$tmp/falls.toml" 2>&1); rc=$?
[ $rc -eq 3 ] || fail "falling block: exit $rc, expected 3, a run that failed after it started ($msg)"
expect_in "$msg" "did not settle within 1.5 s: body 'leaning' still moves"
expect_in "$msg" "x m g L"
expect_in "$msg" "since settling started"
grep -qE "e\+[0-9]{3}" <<<"$msg" && fail "an absurd ratio in: $msg"

[ $failures -eq 0 ] && echo "all material stiffness checks passed"
exit $failures
