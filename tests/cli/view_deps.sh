# Sourced by the view tests: makes sure a Debian package is there, installing it when it is
# missing (as `make deps-view` does); skips the test only when it cannot be installed.
#   need_package PACKAGE CHECK_COMMAND...
need_package() {
  local pkg=$1; shift
  "$@" >/dev/null 2>&1 && return 0
  "$source_dir/scripts/install-deps.sh" "$pkg" >/dev/null 2>&1 || true
  if ! "$@" >/dev/null 2>&1; then
    echo "SKIPPED: Debian package $pkg is not installed and could not be installed (make deps-view)"
    exit 0
  fi
}
