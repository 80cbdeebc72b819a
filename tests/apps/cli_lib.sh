# Shared by the CLI test scripts (tests/apps/cli_*_test.sh), sourced as
#   source "$(dirname "${BASH_SOURCE[0]}")/cli_lib.sh" "$1"
# with the stratum executable as its argument. Gives $stratum, a scratch
# folder $tmp removed on exit, the counters behind ok/fail, expect_error,
# has_render and finish, which prints the "N passed, N failed" line and sets
# the exit status.
stratum=$1
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
passed=0 failed=0
ok() { passed=$((passed + 1)); }
fail() { echo "FAIL: $*"; failed=$((failed + 1)); }

expect_error() {  # expect_error WORD args...: non-zero exit and WORD in stderr
  local word=$1; shift
  if "$stratum" "$@" >"$tmp/out" 2>"$tmp/err"; then fail "'$*' succeeded"; return; fi
  grep -q -- "$word" "$tmp/err" && ok || fail "'$*' stderr lacks '$word': $(cat "$tmp/err")"
}

# has_render: whether this build has the renderer. Under ctest the build says
# so in STRATUM_HAS_RENDER (tests/CMakeLists.txt): then a render subcommand
# that is missing or broken fails instead of skipping the render cases. Run by
# hand without it, the executable is asked.
has_render() {
  case ${STRATUM_HAS_RENDER-} in
    1) "$stratum" render --help >/dev/null 2>&1 ||
         fail "this build has the renderer (STRATUM_HAS_RENDER=1) but 'stratum render --help' fails"
       return 0 ;;
    0) return 1 ;;
    *) "$stratum" render --help >/dev/null 2>&1 ;;
  esac
}

finish() {
  echo "$passed passed, $failed failed"
  [ "$failed" = 0 ]
}
