#!/usr/bin/env bash
# Runs `lsolid skeleton` on each file of a list and counts those read.
# usage: bench/dialect-coverage/measure.sh LSOLID LIST  (paths in LIST are
# relative to the current directory); prints one line per file: the exit
# status, the file and the first error, then the count.
set -uo pipefail
lsolid=$1
list=$2
read_count=0
total=0
while IFS= read -r file; do
  [ -z "$file" ] && continue
  total=$((total + 1))
  errors=$(timeout 60 "$lsolid" skeleton "$file" 2>&1 >/dev/null)
  status=$?
  [ "$status" -eq 0 ] && read_count=$((read_count + 1))
  printf '%s\t%s\t%s\n' "$status" "$file" \
    "$(printf '%s\n' "$errors" | grep -m1 'error' | cut -c1-200)"
done <"$list"
echo "read: $read_count of $total"
