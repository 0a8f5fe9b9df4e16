#!/usr/bin/env bash
# Every scenario in tests/scenarios/bad/ must be rejected by `wallload check`
# with exit code 2 and a message naming the file, the right line and the key.
# The expectation is the file's first line:
#   # expect: exit=N line=L key=TEXT [more text that must appear]
# (line=0: the message has no line, e.g. a rule across several keys).
# Every scenario in tests/scenarios/good/ must be accepted (exit 0).
set -u
bin=$1; src=$2
fail=0
for f in "$src"/tests/scenarios/bad/*.yaml; do
  exp=$(head -1 "$f" | sed -n 's/^# expect: //p')
  want_rc=$(sed -n 's/.*exit=\([0-9]*\).*/\1/p' <<<"$exp")
  want_line=$(sed -n 's/.*line=\([0-9]*\).*/\1/p' <<<"$exp")
  rest=$(sed 's/.*line=[0-9]* key=//' <<<"$exp")
  out=$("$bin" check "$f" 2>&1 >/dev/null); rc=$?
  ok=1
  [ "$rc" = "$want_rc" ] || ok=0
  if [ "$want_line" != 0 ]; then grep -qF "$f:$want_line:" <<<"$out" || ok=0; fi
  # every word group of the rest must appear (did-you-mean=X means "did you mean 'X'")
  key=$(awk '{print $1}' <<<"$rest")
  grep -qF -- "$key" <<<"$out" || ok=0
  extra=$(cut -d' ' -f2- <<<"$rest" | sed 's/did-you-mean=\([^ ]*\)/did you mean '"'"'\1'"'"'?/; s/missing=\([^ ]*\)/missing required key '"'"'\1'"'"'/')
  [ "$extra" = "$key" ] || [ -z "$extra" ] || grep -qF -- "$extra" <<<"$out" || ok=0
  if [ $ok = 1 ]; then echo "PASS $(basename "$f"): exit $rc: $out"
  else echo "FAIL $(basename "$f"): want exit $want_rc line $want_line '$rest'; got exit $rc: $out"; fail=$((fail+1)); fi
done
for f in "$src"/tests/scenarios/good/*.yaml "$src"/scenarios/*.yaml; do
  if out=$("$bin" check "$f" 2>&1); then echo "PASS $(basename "$f") accepted"
  else echo "FAIL $(basename "$f") rejected: $out"; fail=$((fail+1)); fi
done
exit $fail
