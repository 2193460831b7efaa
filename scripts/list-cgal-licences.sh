#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# Which CGAL headers the library compiles in, by CGAL package and licence: every header the
# preprocessor opens for the sources that include CGAL (found by grep), read from each header's
# own "$URL: .../<Package>/include/..." and "SPDX-License-Identifier:" lines.
#
# usage: scripts/list-cgal-licences.sh [BUILD_DIR]   (default build; needs compile_commands.json)
set -euo pipefail
cd "$(dirname "$0")/.."
build=${1:-build}
[[ -f $build/compile_commands.json ]] || { echo "no $build/compile_commands.json: configure first" >&2; exit 2; }
sources=$(grep -rlE '#include\s*[<"]CGAL/' geometry/src bindings 2>/dev/null | grep '\.cpp$' || true)
[[ -n $sources ]] || { echo "no source includes CGAL" >&2; exit 1; }
headers=$(for source in $sources; do
  # The compiler's own command for the source, made to preprocess only and list what it opens.
  command=$(/usr/bin/python3 - "$build/compile_commands.json" "$PWD/$source" <<'PY'
import json, shlex, sys
for entry in json.load(open(sys.argv[1])):
    if entry["file"] == sys.argv[2]:
        args = shlex.split(entry["command"])
        keep, skip = [], False
        for a in args:
            if skip: skip = False; continue
            if a == "-o": skip = True; continue
            if a == "-c" or a.endswith("ccache"): continue
            keep.append(a)
        print(entry["directory"] + "\t" + shlex.join(keep))
        break
PY
)
  [[ -n $command ]] || continue
  (cd "${command%%$'\t'*}" && eval "${command#*$'\t'} -E -H -o /dev/null" 2>&1 >/dev/null) |
    grep -oE '/[^ ]*/CGAL/[^ ]+' | grep -E '\.h$' || true
done | sort -u)
echo "CGAL headers compiled into the library, by package and licence (from each header):"
for header in $headers; do
  package=$(grep -m1 -oE '\$URL: [^ ]*/([A-Za-z_0-9]+)/include/' "$header" | sed -E 's|.*/([A-Za-z_0-9]+)/include/|\1|' || true)
  licence=$(grep -m1 'SPDX-License-Identifier' "$header" | sed 's/.*Identifier: *//' || true)
  echo "${package:-?}|${licence:-?}"
done | sort | uniq -c | awk -F'|' '{ printf "  %-40s %s\n", $1, $2 }'
