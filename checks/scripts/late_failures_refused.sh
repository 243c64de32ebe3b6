#!/bin/sh
# late_failures_refused.sh PROGRAM FILE
#
# The one rule for the files a run writes (checks/file_rules.json), kept by
# PROGRAM headless before its run: each target below is refused with status 2
# and a message naming why, before the scene runs, so the run writes nothing
# (neither its output FILE, Test2_output.txt or the like, nor the metrics)
# and what stood at the target is left as it was:
#   - FILE hard-linked to a file "victim": "has more than one link"
#     (the run's rows went into victim, status 0);
#   - --metrics-json hard-linked to victim: "has more than one link";
#   - --metrics-json with a 250-byte name, whose hidden temporary name
#     beside it cannot exist: "name is too long" (the whole run ran, marked
#     FILE "# complete", then failed with status 1);
#   - --metrics-json in a folder that does not exist: "no such folder";
#   - --metrics-json naming another user's file in a sticky folder (/tmp),
#     which rename(2) may not replace: "another user's file in a sticky
#     folder" (the whole run ran, then status 1). It needs a second user:
#     as root the run drops to nobody (setpriv); otherwise it is skipped.
program=$(cd "$(dirname "$1")" && pwd)/$(basename "$1") file=$2
check_name=late_failures
. "$(dirname "$0")/output_check_common.sh"

# refused NAME PHRASE ARGS...: a run in the fresh folder $root/NAME (set up
# by the caller) must end with status 2 naming PHRASE, writing nothing.
refused() {
  name=$1 phrase=$2
  shift 2
  cd "$root/$name" || exit 2
  before=$(ls -A | sort)
  timeout 60 "$program" --headless --seconds 0.1 "$@" >/dev/null 2>"$root/$name.err"
  status=$?
  [ "$status" = 2 ] || fail "$name: status $status, expected 2"
  grep -q "^error: .*$phrase" "$root/$name.err" && ok "$name refused: $(head -1 "$root/$name.err")" ||
    fail "$name: message '$(head -1 "$root/$name.err")' lacks '$phrase'"
  [ "$(ls -A | sort)" = "$before" ] || fail "$name: the refused run left files: $(ls -A | tr '\n' ' ')"
}

mkdir "$root/output_hard_link" && cd "$root/output_hard_link" || exit 2
echo precious > victim && ln victim "$file"
refused output_hard_link "has more than one link"
[ "$(cat victim)" = precious ] || fail "output_hard_link: victim now holds '$(head -1 victim)'"

mkdir "$root/metrics_hard_link" && cd "$root/metrics_hard_link" || exit 2
echo precious > victim && ln victim m.json
refused metrics_hard_link "has more than one link" --metrics-json m.json
[ "$(cat victim)" = precious ] || fail "metrics_hard_link: victim now holds '$(head -1 victim)'"

mkdir "$root/long_name" || exit 2
long=$(printf '%0250d' 0 | tr 0 a)
refused long_name "name is too long" --metrics-json "$long"

mkdir "$root/missing_folder" || exit 2
refused missing_folder "no such folder" --metrics-json no/such/folder/m.json

# refused_as_nobody NAME PHRASE ARGS...: as refused, run by the user nobody.
if [ "$(id -u)" = 0 ] && command -v setpriv >/dev/null 2>&1 &&
  setpriv --reuid=65534 --regid=65534 --clear-groups sh -c 'test -x "$1"' sh "$program"; then
  mkdir -p "$root/sticky/out" && chmod 755 "$root" "$root/sticky" && chmod 1777 "$root/sticky" &&
    chown 65534:65534 "$root/sticky/out" || exit 2
  echo precious > "$root/sticky/m.json"  # root's file in nobody's sticky folder
  cd "$root/sticky/out" || exit 2
  setpriv --reuid=65534 --regid=65534 --clear-groups timeout 60 "$program" --headless --seconds 0.1 \
    --metrics-json "$root/sticky/m.json" >/dev/null 2>"$root/sticky.err"
  status=$?
  [ "$status" = 2 ] || fail "sticky: status $status, expected 2"
  grep -q "^error: .*another user's file in a sticky folder" "$root/sticky.err" &&
    ok "sticky refused: $(head -1 "$root/sticky.err")" || fail "sticky: message '$(head -1 "$root/sticky.err")'"
  [ -z "$(ls -A)" ] || fail "sticky: the refused run left files: $(ls -A | tr '\n' ' ')"
  [ "$(cat "$root/sticky/m.json")" = precious ] || fail "sticky: the file was replaced"
else
  echo "skipped: sticky: needs root and setpriv (a file of another user), and a program nobody can run"
fi
[ "$failures" = 0 ]
