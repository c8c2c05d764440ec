#!/bin/bash
# Compares the cuts of two builds on corpus surfaces: for every surface, K and
# strategy it runs Testing/Benchmarks/cut_digest (the cutter alone, with the
# filter's defaults) of the old build and the new one, alternating, and
# prints one line per case with both times and whether the cuts are the
# same bit for bit (equal digests), then a summary. Figures, not a test.
#
#   bash Testing/Corpus/compare_cuts.sh OLD_BUILD NEW_BUILD [--corpus DIR] [--ks 16,64]
#        [--strategies RecursiveBisection,ParallelPlanes] [--surfaces a,b] [--timeout 300]
#
# A build is a build tree holding bin/cut_digest (cmake --build BUILD --target cut_digest).
# The cutter's warnings (cut_digest's standard error) are not shown.
set -euo pipefail
HERE="$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)"
OLD="$1/bin/cut_digest"; NEW="$2/bin/cut_digest"; shift 2
CORPUS="$HERE/../../out/corpus"; KS="16,64"; STRATEGIES="RecursiveBisection,ParallelPlanes"; SURFACES=""; TIMEOUT=300
while [ $# -gt 0 ]; do
    case "$1" in
        --corpus) CORPUS="$2"; shift 2;;
        --ks) KS="$2"; shift 2;;
        --strategies) STRATEGIES="$2"; shift 2;;
        --surfaces) SURFACES="$2"; shift 2;;
        --timeout) TIMEOUT="$2"; shift 2;;
        *) echo "compare_cuts.sh: unknown option $1" >&2; exit 2;;
    esac
done
for tool in "$OLD" "$NEW"; do
    [ -x "$tool" ] || { echo "compare_cuts.sh: $tool is missing (cmake --build BUILD --target cut_digest)" >&2; exit 2; }
done
if [ -n "$SURFACES" ]; then
    files=(); for s in ${SURFACES//,/ }; do files+=("$CORPUS/$s.off"); done
else
    files=("$CORPUS"/*.off)
fi
field() { sed -n "s/.*\"$1\": \"\\{0,1\\}\\([^,\"}]*\\).*/\\1/p"; }
same=0; differ=0; failed=0; ratios=()
for f in "${files[@]}"; do
    for k in ${KS//,/ }; do
        for st in ${STRATEGIES//,/ }; do
            old=$(timeout "$TIMEOUT" "$OLD" "$f" "$k" "$st" 2>/dev/null || true)
            new=$(timeout "$TIMEOUT" "$NEW" "$f" "$k" "$st" 2>/dev/null || true)
            od=$(echo "$old" | field digest); nd=$(echo "$new" | field digest)
            os=$(echo "$old" | field seconds); ns=$(echo "$new" | field seconds)
            if [ -z "$od" ] || [ -z "$nd" ] || [ "$od" = 0000000000000000 ] || [ "$nd" = 0000000000000000 ]; then
                verdict="failed or timed out (old: ${old:-none}; new: ${new:-none})"; failed=$((failed + 1))
            elif [ "$od" = "$nd" ]; then
                verdict=same; same=$((same + 1))
            else
                verdict=DIFFERENT; differ=$((differ + 1))
            fi
            [ -n "$os" ] && [ -n "$ns" ] && ratios+=("$(awk -v a="$os" -v b="$ns" 'BEGIN { if (a > 0) print b / a }')")
            printf '%s K=%s %s: old %ss new %ss %s\n' "$(basename "$f" .off)" "$k" "$st" "${os:--}" "${ns:--}" "$verdict"
        done
    done
done
printf '%s\n' "${ratios[@]}" | awk -v s="$same" -v d="$differ" -v x="$failed" '
    $1 > 0 { l += log($1); n++; if ($1 > m) m = $1 }
    END { printf "cases: %d the same cut, %d different, %d failed; new / old time: geometric mean %.2f, largest %.2f\n",
          s, d, x, n ? exp(l / n) : 0, m }'
