#!/bin/sh
# windows_skip_unless_built.sh EXE COMMAND...
#
# Runs COMMAND when the Windows program EXE was built and Wine is there;
# otherwise says which is missing and exits 77, CTest's skip (the Windows
# checks are skipped, not failed, where no cross-build was made).
exe=$1
shift
if [ ! -f "$exe" ]; then
  echo "SKIP: $exe was not built (scripts/odelab.sh windows builds it)"
  exit 77
fi
if ! command -v wine >/dev/null; then
  echo "SKIP: wine is not installed (scripts/odelab.sh windows installs it)"
  exit 77
fi
exec "$@"
