#!/usr/bin/env bash
# SPDX-License-Identifier: BSD-3-Clause
# usage: run_and_compare.sh REFERENCE OUTPUT COMMAND [ARGS...]
# Runs COMMAND (which writes OUTPUT), then requires OUTPUT to equal REFERENCE byte for byte;
# on a difference, shows the first differing lines.
set -euo pipefail
reference=$1 output=$2
shift 2
rm -f "$output"
"$@"
if cmp -s "$reference" "$output"; then
  echo "identical: $(wc -l < "$output") answers, $(wc -c < "$output") bytes"
  exit 0
fi
echo "answers differ from $reference:"
diff "$reference" "$output" | head -n 20 | cut -c 1-400
exit 1
