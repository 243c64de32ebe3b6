#!/usr/bin/env bash
# Unpacks Debian source packages for the cross-builds (Windows, browser),
# without touching the system's apt configuration: a private sources list
# (deb-src lines for the archives the system already uses) and a private
# state folder under the cache.
#
#   scripts/deps/debian-source.sh CACHE PACKAGE...
#
# Prints, one a line, the folder each PACKAGE was unpacked into
# (CACHE/src/<package>-<version>); a package already unpacked there is not
# fetched again. Needs apt-get and dpkg-source (dpkg-dev); exits 1 naming
# the package that could not be had.
set -euo pipefail

say() { printf 'debian-source: %s\n' "$*" >&2; }

if [ $# -lt 2 ]; then
  say "usage: $0 CACHE PACKAGE..."
  exit 2
fi
cache=$1
shift
for tool in apt-get dpkg-source; do
  command -v "$tool" >/dev/null || { say "error: $tool is missing (apt-get install dpkg-dev)"; exit 1; }
done

apt_dir=$cache/apt
mkdir -p "$apt_dir/lists/partial" "$apt_dir/archives/partial" "$cache/src"

# The private list: the system's own archives as deb-src, read from the
# deb822 files and from one-line sources.list entries.
sources=$apt_dir/sources.list
{
  for f in /etc/apt/sources.list.d/*.sources; do
    [ -f "$f" ] || continue
    awk '
      function flush() {
        if (types ~ /deb/ && uris != "" && suites != "")
          { n = split(suites, s, " "); for (i = 1; i <= n; i++)
              printf "deb-src %s %s %s\n", (signed != "" ? "[signed-by=" signed "] " : "") uris, s[i], comps }
        types = uris = suites = comps = signed = ""
      }
      /^[[:space:]]*$/ { flush(); next }
      /^#/ { next }
      /^Types:/ { sub(/^Types:[[:space:]]*/, ""); types = $0 }
      /^URIs:/ { sub(/^URIs:[[:space:]]*/, ""); uris = $0 }
      /^Suites:/ { sub(/^Suites:[[:space:]]*/, ""); suites = $0 }
      /^Components:/ { sub(/^Components:[[:space:]]*/, ""); comps = $0 }
      /^Signed-By:/ { sub(/^Signed-By:[[:space:]]*/, ""); signed = $0 }
      END { flush() }
    ' "$f"
  done
  for f in /etc/apt/sources.list /etc/apt/sources.list.d/*.list; do
    [ -f "$f" ] || continue
    sed -n 's/^[[:space:]]*deb[[:space:]]\+\(.*debian.*\)$/deb-src \1/p' "$f"
  done
} | sort -u > "$sources"
[ -s "$sources" ] || { say "error: no Debian archive found in /etc/apt to take sources from"; exit 1; }

apt_options=(
  -o "Dir::Etc::SourceList=$sources"
  -o "Dir::Etc::SourceParts=/nonexistent"
  -o "Dir::State::Lists=$apt_dir/lists"
  -o "Dir::Cache::Archives=$apt_dir/archives"
  -o "Dir::State::Status=/var/lib/dpkg/status"
  -o "APT::Sandbox::User=root"
)
# The index is fetched once a day at most.
stamp=$apt_dir/updated
if [ ! -f "$stamp" ] || [ -n "$(find "$stamp" -mmin +1440)" ]; then
  apt-get -qq "${apt_options[@]}" update >&2 || { say "error: apt-get update with $sources failed"; exit 1; }
  touch "$stamp"
fi

for package in "$@"; do
  version=$(apt-cache "${apt_options[@]}" showsrc "$package" 2>/dev/null |
    awk '/^Version:/ { print $2; exit }')
  [ -n "$version" ] || { say "error: no source package '$package' in $sources"; exit 1; }
  upstream=${version#*:}
  upstream=${upstream%-*}
  target=$cache/src/$package-$upstream
  if [ ! -f "$target/.unpacked" ]; then
    work=$(mktemp -d "$cache/src/.fetch-$package.XXXXXX")
    (cd "$work" && apt-get -qq "${apt_options[@]}" source --download-only "$package=$version" >&2) ||
      { rm -rf "$work"; say "error: could not fetch the source of $package $version"; exit 1; }
    # Unpacked inside the work folder (dpkg-source leaves links to the
    # tarballs beside its target), then moved into place whole.
    (cd "$work" && dpkg-source --no-check -x ./*.dsc tree >&2) ||
      { rm -rf "$work"; say "error: could not unpack $package $version"; exit 1; }
    rm -rf "$target"
    mv "$work/tree" "$target"
    rm -rf "$work"
    touch "$target/.unpacked"
  fi
  printf '%s\n' "$target"
done
