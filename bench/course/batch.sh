#!/usr/bin/env bash
# How fast `vplab grade batch` grades a class (issue 21: 300 answers in a few seconds on 2 cores).
# Writes an exercise sheet, a class of 300 answers made from its key (right ones, rounded ones, the
# matrices transposed, N negated, empty answers, broken files), and times the batch with 1 and with
# 2 jobs, three times each, in one run. Prints the gradebook's first lines.
# Usage: bench/course/batch.sh VPLAB
set -euo pipefail
vplab=$(realpath "$1")
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work"
"$vplab" exercise --seed 3 --topic pipeline --out sheet 2>/dev/null
python3 - <<'PY'
import json, os
key = json.load(open("sheet/solution.json"))
os.makedirs("class")
def rounded(j, d):
    if isinstance(j, float): return round(j, d)
    if isinstance(j, list): return [rounded(e, d) for e in j]
    if isinstance(j, dict): return {k: rounded(v, d) for k, v in j.items()}
    return j
def transposed(answer):
    a = json.loads(json.dumps(answer))
    for k, m in a["matrices"].items(): a["matrices"][k] = [[m[c][r] for c in range(4)] for r in range(4)]
    return a
def negated_n(answer):
    a = json.loads(json.dumps(answer))
    a["camera"]["n"] = [-x for x in a["camera"]["n"]]
    return a
kinds = [("right", lambda: key, 120), ("rounded", lambda: rounded(key, 2), 60), ("transposed", lambda: transposed(key), 50),
         ("negated", lambda: negated_n(key), 40), ("empty", lambda: {}, 20)]
n = 0
for name, make, count in kinds:
    for i in range(count):
        json.dump(make(), open(f"class/{name}{i:03d}.json", "w")); n += 1
for i in range(10):
    open(f"class/broken{i:03d}.json", "w").write("{\"camera\": " * (i + 1)); n += 1
assert n == 300, n
PY
for jobs in 1 2; do
  for run in 1 2 3; do
    "$vplab" grade batch --assignment sheet/assignment.json --answers class --out "out$jobs" --jobs "$jobs" 2>/dev/null
  done
done
echo
head -4 out2/grades.csv | cut -c1-160
grep -m1 "^empty" out2/grades.csv | cut -c1-160
grep -m1 "^negated" out2/grades.csv | cut -c1-160
grep -m1 "^rounded" out2/grades.csv | cut -c1-160
grep -m1 "^right" out2/grades.csv | cut -c1-160
grep -m1 "^transposed" out2/grades.csv | cut -c1-160
