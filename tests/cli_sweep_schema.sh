#!/usr/bin/env bash
# cli_sweep_schema.sh: the scenario's sweep: section (issue 21).
#
# Every scenario in tests/scenarios/sweep/bad/ is refused by `wallload
# check` and by `wallload sweep` alike, with exit 2 and a message naming the
# file, the line and the key; the expectation is the file's first line:
#   # expect: exit=N line=L key=TEXT [more text that must appear]
# (did-you-mean=X: "did you mean 'X'?"; missing=K: "missing required key 'K'").
# `sweep` writes nothing for them. Every scenario in sweep/good/ is
# accepted, with the number of cases of its first line (# expect: cases=N).
#
# usage: cli_sweep_schema.sh WALLLOAD SOURCE_DIR
set -u
bin=$1; src=$2
fail=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for f in "$src"/tests/scenarios/sweep/bad/*.yaml; do
  exp=$(head -1 "$f" | sed -n 's/^# expect: //p')
  want_rc=$(sed -n 's/.*exit=\([0-9]*\).*/\1/p' <<<"$exp")
  want_line=$(sed -n 's/.*line=\([0-9]*\).*/\1/p' <<<"$exp")
  rest=$(sed 's/.*line=[0-9]* key=//' <<<"$exp")
  key=$(awk '{print $1}' <<<"$rest")
  extra=$(cut -s -d' ' -f2- <<<"$rest" | sed 's/did-you-mean=\([^ ]*\)/did you mean '"'"'\1'"'"'?/; s/missing=\([^ ]*\)/missing required key '"'"'\1'"'"'/')
  for cmd in check sweep; do
    if [ $cmd = sweep ]; then
      out=$("$bin" sweep "$f" -o "$work/out" 2>&1 >/dev/null); rc=$?
    else
      out=$("$bin" check "$f" 2>&1 >/dev/null); rc=$?
    fi
    ok=1
    [ "$rc" = "$want_rc" ] || ok=0
    grep -qF "$f:$want_line:" <<<"$out" || ok=0
    grep -qF -- "$key:" <<<"$out" || ok=0
    [ -z "$extra" ] || grep -qF -- "$extra" <<<"$out" || ok=0
    [ $cmd = sweep ] && [ -e "$work/out" ] && ok=0
    if [ $ok = 1 ]; then echo "PASS $cmd $(basename "$f"): exit $rc: $out"
    else echo "FAIL $cmd $(basename "$f"): want exit $want_rc line $want_line key $key '$extra'; got exit $rc: $out"; fail=$((fail+1)); fi
    rm -rf "$work/out"
  done
done
for f in "$src"/tests/scenarios/sweep/good/*.yaml; do
  n=$(head -1 "$f" | sed -n 's/^# expect: cases=//p')
  if out=$("$bin" check "$f" 2>&1) && grep -q "valid, a sweep of $n cases" <<<"$out" \
     && [ "$(grep -c '^ *[0-9][0-9]* *[0-9][0-9][0-9]_' <<<"$out")" = "$n" ]; then
    echo "PASS $(basename "$f") accepted: $n cases, each priced"
  else
    echo "FAIL $(basename "$f"): want $n cases; got: $(grep -m1 'valid\|wallload' <<<"$out")"; fail=$((fail+1))
  fi
done
# a list's values as written, a range's generated ones in from's unit, in check's listing
out=$("$bin" check "$src/tests/scenarios/sweep/good/lists_and_ranges.yaml" 2>&1)
for want in "sweep.energy\\[2\\] *20 J *(line 12)" "sweep.depth\\[1\\] *0.2 m *(line 14)" \
            "sweep.standoff\\[1\\] *1.5 m *(line 13)"; do
  grep -q "$want" <<<"$out" && echo "PASS listing: $want" || { echo "FAIL listing lacks '$want'"; fail=$((fail+1)); }
done
exit $fail
