#!/usr/bin/env bash
# The manual page stays true to the program: every command, knot and session sub-command and
# every option of `shadow4d --help` is named in packaging/shadow4d.1.
#   tests/packaging/man_page_covers_cli.sh PATH/TO/shadow4d packaging/shadow4d.1
set -euo pipefail
bin=$1
page=$(sed -e 's/\\-/-/g' -e 's/\\f[BIRP]//g' "$2")  # the roff text without its escapes
missing=0
names() {  # the words listed under "Subcommands:" in a --help
  "$bin" "$@" --help | sed -n '/^Subcommands:/,/^$/p' | awk 'NR > 1 && NF {print $1}'
}
check() {
  if ! grep -qE -- "(^|[^a-z-])$1([^a-z-]|$)" <<<"$page"; then
    echo "man page: '$1' ($2) is not described" >&2
    missing=1
  fi
}
for c in $(names); do check "$c" "command"; done
for c in $(names knot); do check "$c" "knot sub-command"; done
for c in $(names session); do check "$c" "session sub-command"; done
for o in $("$bin" --help | grep -oE -- '--[a-z][a-z-]*' | sort -u); do check "$o" "option"; done
[[ $missing == 0 ]] && echo "man page: every command and option of --help is described"
exit $missing
