#!/usr/bin/env bash
# The README's first command on a fresh Debian 12 machine, as a new user
# runs it: a minimal root made by debootstrap from the archive this machine's
# apt already uses, the checkout's files copied in (git ls-files: no build
# folder, no compiler cache), no display, then `scripts/odelab.sh run`
# inside it. It must install the window's packages, build test0 and run it
# headless with status 0; the time from nothing to that run's end is
# printed ("fresh root: first run in N s").
#
#   checks/scripts/fresh_root.sh [SOURCE_DIR]      (default: this checkout)
#   checks/scripts/fresh_root.sh --prepare          only make the cached root
#
# The pristine root is made once and kept as a tarball under
# ${XDG_CACHE_HOME:-$HOME/.cache}/odelab/ (ODELAB_FRESH_ROOT_CACHE overrides
# the folder); each run unpacks a new copy under /var/tmp and removes it on
# every exit path. Status: 0 passed, 1 failed, 77 skipped (not root, no
# debootstrap, chroot or mounting not permitted, no archive found), each
# said on one line. FRESH_ROOT_KEEP=1 keeps the run's root for a look.
set -uo pipefail

prepare=0
if [ "${1:-}" = --prepare ]; then prepare=1; shift; fi
source_dir=$(cd "${1:-$(dirname "${BASH_SOURCE[0]}")/../..}" && pwd)
cache=${ODELAB_FRESH_ROOT_CACHE:-${XDG_CACHE_HOME:-$HOME/.cache}/odelab}
suite=bookworm
say() { printf 'fresh root: %s\n' "$*"; }
skip() { say "skipped: $*"; exit 77; }
fail() { say "FAIL: $*"; exit 1; }

# ---- can this machine do it at all? Each missing piece skips, never fails.
[ "$(id -u)" -eq 0 ] || skip "needs root (debootstrap, chroot and mount do)"
command -v debootstrap >/dev/null || skip "debootstrap not installed (apt-get install debootstrap)"
command -v git >/dev/null && git -C "$source_dir" rev-parse --git-dir >/dev/null 2>&1 ||
  skip "$source_dir is not a git checkout: the tree copied in is git ls-files' list"
chroot / true 2>/dev/null || skip "chroot is not permitted here (no CAP_SYS_CHROOT)"

# The archive the host's apt uses for Debian itself: the first URI of a
# source that serves the suite, from the one-line and the deb822 formats.
mirror() {
  local f
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    # "deb [options] URI SUITE COMPONENTS...": the options dropped first.
    [ -f "$f" ] && sed 's/\[[^]]*\]//' "$f" | awk -v s="$suite" '$1 == "deb" && $3 == s { print $2; exit }'
  done
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] && awk -v s="$suite" 'BEGIN { RS = ""; FS = "\n" }
      { uri = ""; ok = 0; deb = 0
        for (i = 1; i <= NF; i++) {
          if ($i ~ /^URIs:/) { split(substr($i, 6), u, " "); uri = u[1] }
          if ($i ~ /^Suites:/) { n = split(substr($i, 8), w, " "); for (j = 1; j <= n; j++) if (w[j] == s) ok = 1 }
          if ($i ~ /^Types:/ && $i ~ /[ \t]deb([ \t]|$)/) deb = 1 }
        if (ok && deb && uri != "") { print uri; exit } }' "$f"
  done
}
archive=$(mirror | head -n 1)
[ -n "$archive" ] || skip "no apt source for Debian $suite in /etc/apt/sources.list or sources.list.d"

# ---- the pristine root, made once ---------------------------------------
tarball=$cache/debian-$suite-minbase.tar
mkdir -p "$cache" || fail "cannot make the cache folder $cache"
if [ ! -f "$tarball" ]; then
  say "making the pristine root once: debootstrap --variant=minbase $suite from $archive (a few minutes)"
  staging=$(mktemp -d /var/tmp/odelab-debootstrap.XXXXXX)
  # The staging root holds no mount, so a plain removal is safe.
  trap 'rm -rf --one-file-system "$staging"' EXIT
  started=$(date +%s)
  if ! debootstrap --variant=minbase "$suite" "$staging/root" "$archive" >"$staging/debootstrap.log" 2>&1; then
    tail -n 20 "$staging/debootstrap.log"
    grep -qi "permission denied\|operation not permitted" "$staging/debootstrap.log" &&
      skip "debootstrap was not permitted here (see the log above)"
    fail "debootstrap failed (the last lines of its log are above)"
  fi
  # Downloaded packages are not part of a fresh machine.
  rm -rf "$staging/root/var/cache/apt/archives/"*.deb
  tar -C "$staging/root" -cf "$tarball.part" . && mv "$tarball.part" "$tarball" || fail "cannot write $tarball"
  say "pristine root cached in $tarball ($(( $(date +%s) - started )) s, not counted below)"
  rm -rf --one-file-system "$staging"
  trap - EXIT
fi

[ "$prepare" -eq 0 ] || { say "pristine root: $tarball"; exit 0; }

# ---- this run's copy ----------------------------------------------------
work=$(mktemp -d /var/tmp/odelab-fresh-root.XXXXXX)
root=$work/root
mounted=()
# The processes this run started inside the root (apt, the compilers, test0),
# found by their root folder: ended by id when the run is cut short.
stop_root_processes() {  # SIGNAL
  local p
  for p in /proc/[0-9]*; do
    [ "$(readlink "$p/root" 2>/dev/null)" = "$root" ] && kill "-$1" "${p#/proc/}" 2>/dev/null
  done
}
cleanup() {
  local m i
  stop_root_processes TERM
  sleep 1
  stop_root_processes KILL
  # Unmount in reverse order; lazily where something still holds a mount
  # (a process left behind), so that the removal below never crosses into
  # the host's /dev or /proc.
  for ((i = ${#mounted[@]} - 1; i >= 0; i--)); do
    m=${mounted[$i]}
    umount "$m" 2>/dev/null || umount -l "$m" 2>/dev/null || say "warning: could not unmount $m"
  done
  if [ "${FRESH_ROOT_KEEP:-0}" = 1 ]; then
    say "kept $root"
  elif ! grep -q " $work/" /proc/mounts; then
    rm -rf --one-file-system "$work"
  else
    say "warning: $work still holds a mount; not removed"
  fi
}
trap cleanup EXIT
trap 'exit 130' INT
trap 'exit 143' TERM
mkdir -p "$root" && tar -C "$root" -xf "$tarball" || fail "cannot unpack $tarball into $root"

# The checkout's files, as a clone would have them (tracked, and new files
# not ignored, so an uncommitted change is tried too): no build folder.
dest=$root/root/odelab
mkdir -p "$dest"
(cd "$source_dir" && git ls-files -z --cached --others --exclude-standard |
   tar --null --no-recursion --ignore-failed-read -T - -cf - 2>/dev/null) | tar -C "$dest" -xf - ||
  fail "cannot copy the checkout's files into the root"
[ -x "$dest/scripts/odelab.sh" ] || fail "scripts/odelab.sh did not arrive in the root"

# The network and the archive as the host has them.
cp -L /etc/resolv.conf "$root/etc/resolv.conf" 2>/dev/null || say "warning: no /etc/resolv.conf to copy"
rm -f "$root/etc/apt/sources.list" "$root/etc/apt/sources.list.d/"*
[ -f /etc/apt/sources.list ] && cp /etc/apt/sources.list "$root/etc/apt/"
for f in /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources; do
  [ -f "$f" ] && cp "$f" "$root/etc/apt/sources.list.d/"
done
# Keys a source names by Signed-By that the root does not have.
for key in $(cat /etc/apt/sources.list /etc/apt/sources.list.d/*.list /etc/apt/sources.list.d/*.sources 2>/dev/null |
             grep -o 'signed-by=[^] ]*\|Signed-By: *[^ ]*' | sed 's/^[Ss]igned-[Bb]y[=:] *//' | sort -u); do
  [ -f "$key" ] && [ ! -f "$root$key" ] && mkdir -p "$root$(dirname "$key")" && cp "$key" "$root$key"
done

mount -t proc proc "$root/proc" || skip "mounting /proc in the root is not permitted here"
mounted+=("$root/proc")
# Compilers and apt want /dev/null, /dev/urandom and friends: the host's.
mount --bind /dev "$root/dev" || skip "bind-mounting /dev into the root is not permitted here"
mounted+=("$root/dev")

# ---- the first command ---------------------------------------------------
# A clean environment: no DISPLAY, no compiler cache, no JOBS: what a new
# user's shell has.
say "running scripts/odelab.sh run in a fresh Debian $suite root ($archive), no display"
# Each line of its output is stamped with the second it came (bash's own
# clock: no process per line), so that the phases can be told apart below.
log=$work/run.log
started=$(date +%s)
chroot "$root" /usr/bin/env -i HOME=/root PATH=/usr/local/sbin:/usr/local/bin:/usr/sbin:/usr/bin:/sbin:/bin \
  LANG=C.UTF-8 TERM=dumb /bin/bash -c 'cd /root/odelab && scripts/odelab.sh run' 2>&1 |
  while IFS= read -r line; do printf '%(%s)T %s\n' -1 "$line"; done >"$log"
status=${PIPESTATUS[0]}
ended=$(date +%s)
elapsed=$((ended - started))
failures=0
expect() {  # expect PATTERN WHAT-IS-WRONG: the run's output has a line matching PATTERN
  grep -q "$1" "$log" || { say "FAIL: $2"; failures=$((failures + 1)); }
}
[ "$status" -eq 0 ] || { say "FAIL: scripts/odelab.sh run ended with status $status"; failures=$((failures + 1)); }
expect "^[0-9]* odelab: no display (DISPLAY is not set): running test0 headless" "odelab.sh did not say it ran test0 headless"
# test0's own lines: its title and the metrics a whole headless run prints.
expect "^[0-9]* test0 - Box & Sphere: .* simulated seconds" "test0 did not start headless"
expect "^[0-9]* sim_seconds = " "test0 printed no metrics (its run did not end)"
if [ "$failures" -ne 0 ]; then
  tail -n 40 "$log" | cut -d' ' -f2-
  exit 1
fi
sed -n 's/^[0-9]* \(odelab: \)/\1/p' "$log"
# The phases, from odelab.sh's own lines: installing (from the start; none
# where nothing was missing), configuring and building, running.
at() { sed -n "s/^\([0-9]*\) odelab: $1.*/\1/p" "$log" | head -n 1; }
built_from=$(at building) ran_from=$(at "no display")
phases=
[ -n "$built_from" ] && [ -n "$ran_from" ] &&
  phases="installing $((built_from - started)) s, configuring and building $((ran_from - built_from)) s, running $((ended - ran_from)) s; "
say "first run in $elapsed s (${phases}$(nproc) cores, load average at the end $(cut -d' ' -f1-3 /proc/loadavg))"
