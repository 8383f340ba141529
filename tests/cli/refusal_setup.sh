# Sourced, with the test's arguments, by the CLI tests of refused input:
#   source "$(dirname "$0")/refusal_setup.sh" "$@"
# sets blockdem (the binary) and source_dir from them, a scratch folder $work removed at exit,
# fail (stops the test), and expect_refused (expect_refused.sh).
blockdem=$1
source_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "FAIL: $*" >&2; exit 1; }
source "$(dirname "${BASH_SOURCE[0]}")/expect_refused.sh"
