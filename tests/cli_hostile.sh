#!/usr/bin/env bash
# The hostile-input table: what a careless or hostile user gives wallload,
# and what it must answer. Every row asserts the exit code (2 for bad input
# or usage, 1 for a run or I/O failure, never 0 on nonsense, never a crash)
# and an extended regular expression that stderr must match: the position
# (FILE:LINE:COL or FILE:LINE where the input has one) and the reason.
# Every command runs under a time limit: a hang fails its row.
#
# Classes: files and the YAML reader; values (types, units, ranges, numbers
# that are not numbers); derived quantities (particles, outputs, memory,
# runtime budget); names that become files and datasets; the command line;
# results files given to `report`; output directories. Full disks and
# signals have their own scripts (cli_faults.sh, cli_signals.sh), and
# tests/scenarios/bad/ holds one file per schema rule (cli_bad_scenarios.sh).
set -u
bin=$1; src=$2
fail=0; rows=0
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
cd "$work" || exit 1

# A valid scenario, 6 lines; a row's extra lines start at line 7.
cat > base.yaml <<'YAML'
scenario: h
water: {depth: 0.5 m}
domain: {length: 20 m}
wall: {x: 15 m, height: 1 m}
loads:
  solitary: {height: 0.1 m}
YAML
# mk NAME LINE...: base.yaml with LINEs appended (from line 7).
mk() { local n=$1; shift; { cat base.yaml; printf '%s\n' "$@"; } > "$n.yaml"; }
# sub NAME SED: base.yaml edited by a sed expression.
sub() { sed "$2" base.yaml > "$1.yaml"; }

# row NAME RC ERE CMD...: run CMD (30 s at most), compare.
row() {
  local name=$1 want=$2 ere=$3; shift 3
  rows=$((rows + 1))
  local out rc
  out=$(timeout 30 "$@" 2>&1 >/dev/null); rc=$?
  out=${out//$'\n'/ }
  if [ "$rc" = "$want" ] && grep -qE -- "$ere" <<<"$out"; then
    echo "PASS $name: exit $rc: ${out:0:200}"
  else
    echo "FAIL $name: want exit $want and /$ere/; got exit $rc: ${out:0:400}"
    fail=$((fail + 1))
  fi
}
chk() { local name=$1 want=$2 ere=$3 file=$4; shift 4; row "$name" "$want" "$ere" "$bin" check "$file" "$@"; }

# ---- files and the YAML reader -----------------------------------------------
chk "missing file" 2 "nosuch.yaml: cannot open the scenario file: No such file or directory" nosuch.yaml
mkdir dir.yaml
chk "a directory" 2 "dir.yaml: is a directory" dir.yaml
: > empty.yaml
chk "empty file" 2 "empty.yaml:1:1: .*empty" empty.yaml
printf 'scenario: h\nwater: {depth: 0.5 m}\ndom\0ain: {length: 20 m}\n' > nul.yaml
chk "NUL byte, line 3" 2 "nul.yaml:3:4: malformed YAML: control characters" nul.yaml
printf 'scenario: h\nwater: {depth: 0.5 m}\ndomain: {length: 20 m}\nwall: {x: \xff15 m}\n' > utf8.yaml
chk "invalid UTF-8, line 4" 2 "utf8.yaml:4:11: malformed YAML: invalid leading UTF-8" utf8.yaml
printf 'scenario: h\nwater: {depth: 0.5 m}\r\x01\n' > ctrl.yaml
chk "control byte" 2 "ctrl.yaml:2:.*malformed YAML: control characters" ctrl.yaml
head -c 4096 /dev/urandom > random.yaml
chk "random bytes" 2 "random.yaml:[0-9]+:[0-9]+: " random.yaml
{ cat base.yaml; printf -- '---\nscenario: x\n'; } > twodocs.yaml
chk "second document" 2 "twodocs.yaml:8:1: a second YAML document" twodocs.yaml
printf 'scenario: h\nwater:\n\tdepth: 0.5 m\n' > tab.yaml
chk "tab indentation" 2 "tab.yaml:3:1: malformed YAML" tab.yaml
printf 'scenario: "h\nwater: {depth: 0.5 m}\n' > quote.yaml
chk "unterminated quote" 2 "quote.yaml:3:1: malformed YAML: .*quoted scalar started at 1:11" quote.yaml
printf 'scenario: h\nwater: {depth: [0.5 m}\n' > bracket.yaml
chk "unclosed bracket" 2 "bracket.yaml:2:.*malformed YAML" bracket.yaml
{ printf 'a: &a ["lol","lol","lol","lol","lol","lol","lol","lol","lol"]\n'
  p=a; for n in b c d e f g h i j; do printf '%s: &%s [*%s,*%s,*%s,*%s,*%s,*%s,*%s,*%s,*%s]\n' $n $n $p $p $p $p $p $p $p $p $p; p=$n; done; } > laughs.yaml
chk "billion laughs (aliases)" 2 "laughs.yaml:1:1: a: unknown key 'a'" laughs.yaml
mk aliased 'gauges: &g [{name: A, x: 5 m}]' 'wall2: *g'
chk "alias under an unknown key" 2 "aliased.yaml:8:1: wall2: unknown key" aliased.yaml
mk merge 'run: {<<: {end_time: 3 s}}'
chk "merge key" 2 "merge.yaml:7:7: run.<<: unknown key '<<'" merge.yaml
mk dupkey 'wall: {probes: 3}'
chk "a key twice" 2 "dupkey.yaml:7:1: wall: this key appears twice" dupkey.yaml
python3 -c "print('scenario: h\nwater: {depth: ' + '['*50000 + ']'*50000 + '}')" > deep.yaml
chk "nested 50000 deep" 2 "deep.yaml:2:[0-9]+: .*nest" deep.yaml
python3 -c "
import sys
sys.stdout.write(open('base.yaml').read())
sys.stdout.write(('#' + 'x'*99 + '\n') * 30000)" > large.yaml
chk "3 MB of comments" 2 "large.yaml:[0-9]+:[0-9]+: YAML document larger than 1 MiB" large.yaml
sub longdesc "s/^scenario: h/scenario: h\ndescription: $(head -c 5000 /dev/zero | tr '\0' d)/"
chk "5000-character text" 2 "longdesc.yaml:2:14: description: found a value of 5000 characters" longdesc.yaml
mk longkey "run: {$(head -c 2000 /dev/zero | tr '\0' k): 3}"
chk "2000-character key" 2 "longkey.yaml:7:[0-9]+: malformed YAML" longkey.yaml

# ---- values --------------------------------------------------------------------
mk nan 'numerics: {coefh: .nan}'
chk "NaN" 2 "nan.yaml:7:19: numerics.coefh: found '.nan', which is not a number" nan.yaml
mk inf 'run: {end_time: .inf s}'
chk "infinity" 2 "inf.yaml:7:17: run.end_time: found '.inf s', which is not a number" inf.yaml
mk overflow 'run: {end_time: 1e400 s}'
chk "1e400 (overflows)" 2 "overflow.yaml:7:17: run.end_time: .*not a number" overflow.yaml
mk underflow 'numerics: {nu: 1e-400}'
chk "1e-400 (underflows)" 2 "underflow.yaml:7:16: numerics.nu: .*not a number" underflow.yaml
mk hex 'run: {end_time: 0x10 s}'
chk "hexadecimal" 2 "hex.yaml:7:17: run.end_time: .*not a number" hex.yaml
mk boolean 'run: {end_time: true}'
chk "a boolean for a number" 2 "boolean.yaml:7:17: run.end_time: found 'true'" boolean.yaml
mk null 'run: {end_time: ~}'
chk "null" 2 "null.yaml:7:17: run.end_time: found '~'" null.yaml
mk listnum 'run: {end_time: [1, 2]}'
chk "a list for a number" 2 "listnum.yaml:7:17: run.end_time: found a list" listnum.yaml
sub mapdepth 's/water: {depth: 0.5 m}/water: {depth: {value: 0.5 m}}/'
chk "a mapping for a number" 2 "mapdepth.yaml:2:16: water.depth: found a mapping" mapdepth.yaml
mk bathmap 'bathymetry: {from: 1 m, slope: 0.1}'
chk "a mapping for a list" 2 "bathmap.yaml:7:13: bathymetry: found a mapping; expected a list" bathmap.yaml
sub negdepth 's/depth: 0.5 m/depth: -0.5 m/'
chk "negative depth" 2 "negdepth.yaml:2:16: water.depth" negdepth.yaml
sub zerodepth 's/depth: 0.5 m/depth: 0 m/'
chk "zero depth" 2 "zerodepth.yaml:2:16: water.depth: .*above 0" zerodepth.yaml
sub nounit 's/length: 20 m/length: 20/'
chk "no unit" 2 "nounit.yaml:3:18: domain.length: .*without a unit" nounit.yaml
sub badunit 's/length: 20 m/length: 20 furlong/'
chk "unknown unit" 2 "badunit.yaml:3:18: domain.length: .*unknown unit 'furlong'" badunit.yaml
sub wrongdim 's/length: 20 m/length: 20 kg/'
chk "a mass for a length" 2 "wrongdim.yaml:3:18: domain.length: .*a mass where a length" wrongdim.yaml
mk probesneg 'numerics: {verlet_steps: -3}'
chk "negative count" 2 "probesneg.yaml:7:26: numerics.verlet_steps: found '-3'" probesneg.yaml
sub probesfrac 's/height: 1 m}/height: 1 m, probes: 2.5}/'
chk "fractional count" 2 "probesfrac.yaml:4:38: wall.probes: found '2.5'; expected a whole number" probesfrac.yaml
sub probesbig 's/height: 1 m}/height: 1 m, probes: 1000000000}/'
chk "a billion probes" 2 "probesbig.yaml:4:38: wall.probes: found '1000000000'" probesbig.yaml
mk threads0 'run: {threads: 0}'
chk "zero threads" 2 "threads0.yaml:7:16: run.threads: found '0'" threads0.yaml
mk gravity 'water: {gravity: 1e-300 m/s^2}'
chk "gravity 1e-300" 2 "gravity.yaml:7:1: water: this key appears twice" gravity.yaml
sub gravity2 's/water: {depth: 0.5 m}/water: {depth: 0.5 m, gravity: 1e-300 m\/s^2}/'
chk "gravity 1e-300 (range)" 2 "gravity2.yaml:2:32: water.gravity: found '1e-300 m/s\^2'" gravity2.yaml
mk endtime 'run: {end_time: 1e300 s}'
chk "end time 1e300 s" 2 "endtime.yaml:7:17: run.end_time: found '1e300 s'" endtime.yaml
mk interval 'run: {output_interval: 1e-12 s}'
chk "output interval 1e-12 s" 2 "interval.yaml:7:24: run.output_interval: found '1e-12 s'" interval.yaml
mk coefh 'numerics: {coefh: 0.1}'
chk "coefh below the solver's range" 2 "coefh.yaml:7:19: numerics.coefh: found '0.1'; expected a value from 0.5 and up to 2" coefh.yaml
mk coefsound 'numerics: {coefsound: 1000}'
chk "coefsound above the range" 2 "coefsound.yaml:7:23: numerics.coefsound: found '1000'; expected a value from 5 and up to 100" coefsound.yaml
mk cfl0 'numerics: {cfl: 0}'
chk "CFL 0" 2 "cfl0.yaml:7:17: numerics.cfl: found '0'; expected a value above 0" cfl0.yaml
sub density 's/water: {depth: 0.5 m}/water: {depth: 0.5 m, density: 1e9 kg\/m^3}/'
chk "density 1e9" 2 "density.yaml:2:32: water.density: found '1e9 kg/m\^3'" density.yaml
mk badchoice 'numerics: {boundary: mdbc}'
chk "unknown choice" 2 "badchoice.yaml:7:22: numerics.boundary: found 'mdbc'; did you mean 'dbc'\? valid: adami, dbc" badchoice.yaml
mk typo 'numerics: {coefsond: 20}'
chk "misspelt key" 2 "typo.yaml:7:12: numerics.coefsond: unknown key 'coefsond'; did you mean 'coefsound'" typo.yaml
mk toomany "gauges: [$(for i in $(seq 1 70); do printf '{name: g%d, x: 5 m},' $i; done){name: last, x: 5 m}]"
chk "too many gauges" 2 "toomany.yaml:7:[0-9]+: gauges\[[0-9]+\]: too many entries" toomany.yaml

# ---- derived quantities -------------------------------------------------------
mk dptiny 'resolution: {dp: 1e-10 m}'
chk "dp 1e-10 m (particle count)" 2 "dptiny.yaml:7: resolution.dp: dp = 1e-10 m needs about [0-9.e+]+ particles" dptiny.yaml
sub wallhigh 's/height: 1 m}/height: 1e20 m}/'
chk "wall 1e20 m high" 2 "wallhigh.yaml: resolution.particles_per_height: .*particles" wallhigh.yaml
# dp 0.1 mm: 7.5e8 particles (under the 2^30 a run can index), 224 GiB
mk memory 'resolution: {dp: 0.0001 m}'
mem_kib=$(awk '/^MemTotal/ {print $2}' /proc/meminfo)
if [ "${mem_kib:-0}" -gt 250000000 ]; then
  echo "SKIP memory rows: this machine has more than 250 GB (the 224 GiB run would fit)"
else
chk "beyond this machine's memory" 2 "memory.yaml:7: resolution.dp: the run needs about [0-9.]+ GiB of memory" memory.yaml
chk "memory: --force-large cannot lift it" 2 "memory.yaml:7: resolution.dp: the run needs about" memory.yaml --force-large
fi
# dp 1 mm: 2.2 GiB, 14 days on 2 threads (beyond 24 h up to 28 threads)
mk budget 'resolution: {dp: 0.001 m}'
chk "beyond the runtime budget" 2 "budget.yaml:7: resolution.dp: the run would take about .* beyond the budget of 24.0 h" budget.yaml --backend cpu
chk "a tighter --budget" 2 "base.yaml: resolution.particles_per_height: .*beyond the budget of 4 s" base.yaml --backend cpu --budget 0.001
row "assess refuses before the run" 2 "budget.yaml:7: resolution.dp: the run would take" "$bin" assess budget.yaml --backend cpu -o never
[ -e never ] && { echo "FAIL assess refused a run but made its directory"; fail=$((fail + 1)); }
mk outputs 'run: {output_interval: 1e-5 s, end_time: 20 s}'
chk "two million outputs" 2 "outputs.yaml:7: run.output_interval: .*outputs, more than 1000000" outputs.yaml
mk nofit 'loads: {solitary: {height: 0.1 m, at: 16 m}}'
chk "a wave behind the wall" 2 "nofit.yaml:7:1: loads: this key appears twice" nofit.yaml

# ---- names that become files and datasets -------------------------------------
sub pathname 's/^scenario: h/scenario: ..\/x/'
chk "scenario name with a path" 2 "pathname.yaml:1:11: scenario: '../x'" pathname.yaml
sub dotname 's/^scenario: h/scenario: .hidden/'
chk "scenario name starting with a dot" 2 "dotname.yaml:1:11: scenario: '.hidden'" dotname.yaml
mk gwall 'gauges: [{name: wall, x: 5 m}]'
chk "gauge named wall" 2 "gwall.yaml:7:17: gauges\[0\].name: 'wall' is not a gauge name" gwall.yaml
mk gcomma 'gauges: [{name: "A,B", x: 5 m}]'
chk "gauge name with a comma" 2 "gcomma.yaml:7:17: gauges\[0\].name: 'A,B' is not a gauge name" gcomma.yaml
mk gnl 'gauges: [{name: "A\nB", x: 5 m}]'
chk "gauge name with a newline" 2 "gnl.yaml:7:17: gauges\[0\].name: .* is not a gauge name" gnl.yaml
mk glong "gauges: [{name: $(head -c 40 /dev/zero | tr '\0' g), x: 5 m}]"
chk "gauge name of 40 characters" 2 "glong.yaml:7:17: gauges\[0\].name: .*1 to 31" glong.yaml
mk gdup 'gauges: [{name: A, x: 5 m}, {name: A, x: 6 m}]'
chk "two gauges of one name" 2 "gdup.yaml:7:36: gauges\[1\].name: 'A' is already the name of gauges\[0\]" gdup.yaml
mk tmissing 'report: {template: nosuch.yaml}'
chk "report template missing" 2 "nosuch.yaml" tmissing.yaml
printf 'title: [unclosed\n' > badtemplate.yaml
mk tbad 'report: {template: badtemplate.yaml}'
chk "report template malformed" 2 "badtemplate.yaml:[0-9]+:[0-9]+: " tbad.yaml
python3 -c "print('title: ' + '['*50000 + ']'*50000)" > deeptemplate.yaml
mk tdeep 'report: {template: deeptemplate.yaml}'
chk "report template nested 50000 deep" 2 "deeptemplate.yaml:1:71: YAML nested deeper than 64 levels; a report template" tdeep.yaml

# ---- the command line ----------------------------------------------------------
row "no command" 2 "usage: wallload COMMAND" "$bin"
row "unknown command" 2 "unknown command 'frobnicate'" "$bin" frobnicate
row "check without a file" 2 "usage: wallload check FILE.yaml" "$bin" check
row "check of two files" 2 "usage: wallload check .*'base.yaml' not understood" "$bin" check base.yaml base.yaml
row "check --backend gpu" 2 "check: --backend: found 'gpu'; valid: cpu, cuda, auto" "$bin" check base.yaml --backend gpu
row "assess unknown option" 2 "assess: unknown option '--fast'; valid: " "$bin" assess base.yaml --fast
row "assess --threads 0" 2 "assess: --threads: found '0'; expected 1 to 4096" "$bin" assess base.yaml --threads 0
row "assess --threads x" 2 "assess: --threads: found 'x'" "$bin" assess base.yaml --threads x
row "assess --threads without a value" 2 "assess: --threads needs a value" "$bin" assess base.yaml --threads
row "assess --end-time -1" 2 "assess: --end-time: found '-1'; expected seconds > 0" "$bin" assess base.yaml --end-time -1
row "assess --end-time nan" 2 "assess: --end-time: found 'nan'" "$bin" assess base.yaml --end-time nan
row "assess --budget 0" 2 "assess: --budget: found '0'; expected hours above 0" "$bin" assess base.yaml --budget 0
row "assess --budget inf" 2 "assess: --budget: found 'inf'" "$bin" assess base.yaml --budget inf
row "convert unknown option" 2 "convert: unknown option '--bogus'" "$bin" convert --bogus
row "convert two sources" 2 "convert: " "$bin" convert --charge 10 lb --energy 100 kJ
row "convert charge without unit" 2 "convert: .*(unit|charge)" "$bin" convert --charge 10
row "validate unknown case" 2 "validate: unknown case 'nosuchcase'; valid: hydrostatic" "$bin" validate nosuchcase
row "bench unknown case" 2 "bench: --case: found 'bogus'; valid: dambreak2d, dambreak3d, all" "$bin" bench --case bogus

# ---- results files given to report ---------------------------------------------
row "report: missing results" 2 "nosuch.h5: cannot open the results file: No such file or directory" "$bin" report nosuch.h5
row "report: a directory" 2 "dir.yaml: is a directory" "$bin" report dir.yaml
row "report: a YAML file" 2 "base.yaml: found a file that is not HDF5" "$bin" report base.yaml
printf '\211HDF\r\n\032\n' > trunc.h5
row "report: a truncated HDF5 file" 2 "trunc.h5: .*(damaged|truncated)" "$bin" report trunc.h5

# ---- output directories ----------------------------------------------------------
touch afile
row "output under a regular file" 2 "afile/x: cannot create the output directory \(Not a directory\)" "$bin" assess base.yaml -o afile/x --quiet
row "output under a missing directory" 2 "no/such/dir: cannot create the output directory \(No such file or directory\)" "$bin" assess base.yaml -o no/such/dir --quiet
mkdir exists
row "output directory exists" 2 "exists: the output directory exists; use --force" "$bin" assess base.yaml -o exists --quiet
row "validate: output under a regular file" 2 "validate: afile/v: cannot create the output directory \(Not a directory\)" "$bin" validate hydrostatic -o afile/v --quick

echo "$rows rows, $fail failed"
[ "$rows" -ge 60 ] || { echo "FAIL the table has $rows rows; the issue asks for at least 60"; fail=$((fail + 1)); }
exit $fail
