#!/usr/bin/env bash
# `wallload convert` prints the seeds' numbers (seed 001 section 3.1.1 A and
# Table 4; references independent of wallload), and rejects bad options with
# exit code 2.
set -u
bin=$1
fail=0
expect() { # description, output, regex
  if grep -qE -- "$3" <<<"$2"; then echo "PASS $1"; else echo "FAIL $1: no /$3/ in:"; echo "$2"; fail=$((fail+1)); fi
}
out=$("$bin" convert --charge 32 lb --water-depth 8 ft); rc=$?
[ $rc = 0 ] || { echo "FAIL convert --charge exit $rc"; fail=$((fail+1)); }
# seed 001: 32 lb -> R0 = 8.28 m, eta0 = 2.07 m (mean of the 34 and 36 coefficients)
expect "32 lb is 14.515 kg (seed 001: 14.5 kg)" "$out" 'charge weight W \(TNT\) +14\.51'
expect "R0 = 8.28 m (seed 001)" "$out" 'crater radius R0 +8\.27[5-9]'
expect "eta0 = 2.07 m (seed 001)" "$out" 'crater depth eta0 +2\.0[67]'
out=$("$bin" convert --energy 177 kJ)
# seed 001 Table 4, Robertson: eta0 R0 = 5.9 m^2, Hmax r = 7.25 m^2
expect "177 kJ -> eta0 R0 = 5.87 m^2 (seed 001 Table 4: 5.9)" "$out" 'eta0 R0 +5\.8[6-9]'
expect "177 kJ -> Hmax r = 7.25 m^2 (seed 001 Table 4)" "$out" 'Hmax r +7\.2[45]'
out=$("$bin" convert --charge 0.03 kg)
expect "0.03 kg -> R0 = 1.3 m (seed 001 Table 4, Yu Yao)" "$out" 'crater radius R0 +1\.29[0-9]'
out=$("$bin" convert --solitary-height 0.05 m --water-depth 0.36 m)
# REFERENCES 3.4 exact table: E/(rho g h^3) at eps = 0.139 lies between 0.0510 (0.10) and 0.0956 (0.15)
expect "solitary energy shown with the seed-001 value" "$out" 'energy 0\.958 rho g h\^3 +438\.4'
for bad in "--charge" "--charge 32 furlong" "--charge 32 lb --energy 3 kJ" "--solitary-height 0.05 m" "--bogus 1"; do
  # shellcheck disable=SC2086
  msg=$("$bin" convert $bad 2>&1 >/dev/null); rc=$?
  if [ $rc = 2 ] && [ -n "$msg" ]; then echo "PASS convert $bad -> exit 2: $(head -1 <<<"$msg")"
  else echo "FAIL convert $bad -> exit $rc: $msg"; fail=$((fail+1)); fi
done
exit $fail
