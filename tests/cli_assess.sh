#!/usr/bin/env bash
# `wallload assess` until the solver exists: a valid scenario is planned and
# the command says which stage is missing (exit 1); bad input exits 2.
set -u
bin=$1; src=$2
fail=0
msg=$("$bin" assess "$src/scenarios/seawall.yaml" 2>&1); rc=$?
if [ $rc = 1 ] && grep -q "SPH solver, is not built yet" <<<"$msg"; then echo "PASS assess names the missing stage"
else echo "FAIL assess: exit $rc: $msg"; fail=$((fail+1)); fi
msg=$("$bin" assess "$src/tests/scenarios/bad/04_negative_depth.yaml" 2>&1); rc=$?
[ $rc = 2 ] && echo "PASS assess bad scenario -> 2" || { echo "FAIL assess bad -> $rc: $msg"; fail=$((fail+1)); }
msg=$("$bin" assess "$src/scenarios/seawall.yaml" --bogus 2>&1); rc=$?
[ $rc = 2 ] && echo "PASS assess unknown option -> 2" || { echo "FAIL unknown option -> $rc"; fail=$((fail+1)); }
msg=$("$bin" assess /nonexistent.yaml 2>&1); rc=$?
[ $rc = 1 ] && grep -q "cannot open" <<<"$msg" && echo "PASS missing file -> 1: $msg" || { echo "FAIL missing file -> $rc: $msg"; fail=$((fail+1)); }
msg=$("$bin" frobnicate 2>&1); rc=$?
[ $rc = 2 ] && echo "PASS unknown command -> 2" || { echo "FAIL unknown command -> $rc"; fail=$((fail+1)); }
out=$("$bin" check "$src/scenarios/seawall.yaml"); rc=$?
[ $rc = 0 ] && grep -q "water.gravity .*9.81 m/s^2 .*(default)" <<<"$out" && echo "PASS check lists defaults" || { echo "FAIL check defaults"; fail=$((fail+1)); }
grep -q "bathymetry\[0\].slope .*0.175439 .*(given as 1/5.7" <<<"$out" && echo "PASS check shows the user's value beside SI" || { echo "FAIL check user value"; fail=$((fail+1)); }
exit $fail
