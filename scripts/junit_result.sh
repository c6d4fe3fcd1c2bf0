# Sourced by the script tests that `./asr test` runs beside the gtests: writes their one-case
# JUnit result, so that their outcome joins the others in the "N passed, N failed" summary.
# junit_result FILE SUITE CASE passed|failed|skipped MESSAGE
junit_result() {
  local file="$1" suite="$2" name="$3" outcome="$4" failures=0 skipped=0 body="" message
  message="$(sed -e 's/&/\&amp;/g' -e 's/</\&lt;/g' -e 's/>/\&gt;/g' -e 's/"/\&quot;/g' <<<"$5")"
  case "$outcome" in
    failed) failures=1; body="<failure message=\"$message\"/>" ;;
    skipped) skipped=1; body="<skipped message=\"$message\"/>" ;;
  esac
  mkdir -p "$(dirname "$file")"
  cat >"$file" <<XML
<?xml version="1.0" encoding="UTF-8"?>
<testsuite name="$suite" tests="1" failures="$failures" errors="0" skipped="$skipped">
  <testcase classname="$suite" name="$name">$body</testcase>
</testsuite>
XML
}
