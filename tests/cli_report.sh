#!/usr/bin/env bash
# `wallload report` end to end: assess a tiny scenario, re-render its report
# from results.h5 alone, and check the PDF against summary.json (written by
# the assessment, read here with python3): each case's peak force and
# impulse, formatted as the peaks table formats them (3 significant digits,
# kN/m and kN s/m), appear in the case's row. Also the exit codes: a
# template with an unknown section -> 2 (and no PDF), a missing results file
# (a path the user gave: bad input) -> 2 with the system's reason, bad usage -> 2. Reads the PDF with poppler's pdftotext and pdfinfo.
set -u
bin=$1; src=$2
fail=0
ok() { echo "PASS $1"; }
bad() { echo "FAIL $1"; fail=$((fail+1)); }
for tool in python3 pdftotext pdfinfo; do
  command -v $tool >/dev/null 2>&1 || { echo "SKIP $tool not installed"; exit 77; }
done
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Sanitizer builds: fontconfig keeps its parsed configuration for the life of
# the process, by design (not a wallload leak); LeakSanitizer is told so.
echo "leak:libfontconfig.so" > "$work/lsan.supp"
export LSAN_OPTIONS="suppressions=$work/lsan.supp${LSAN_OPTIONS:+:$LSAN_OPTIONS}"
cp "$src/tests/scenarios/good/tiny.yaml" "$work/tiny.yaml"
# Under the sanitizers (WL_TEST_QUICK) the same flume at twice the spacing:
# this test checks the pipeline, not the physics, and a sanitized run is
# 13 times slower (27 s against 3.7 s for the two cases here).
[ -n "${WL_TEST_QUICK:-}" ] && sed -i 's/dp: 0.02 m/dp: 0.04 m/' "$work/tiny.yaml"
cd "$work" || exit 1
out=$("$bin" assess tiny.yaml -o run --quiet --end-time 0.3 2>&1); rc=$?
[ $rc = 0 ] && [ -s run/results.h5 ] && ok "assess wrote results.h5" || { bad "assess exit $rc: $out"; exit $fail; }

out=$("$bin" report run/results.h5 -o x.pdf 2>&1); rc=$?
[ $rc = 0 ] && [ -s x.pdf ] && ok "report -o x.pdf (exit 0): $out" || bad "report exit $rc: $out"
pages=$(pdfinfo x.pdf 2>/dev/null | awk '/^Pages:/ {print $2}')
[ "${pages:-0}" -ge 8 ] && ok "x.pdf has $pages pages (pdfinfo)" || bad "x.pdf has ${pages:-no} pages"
pdftotext -layout x.pdf - 2>/dev/null | tr -s ' \n' '  ' > x.txt
grep -q "tiny" x.txt && ok "scenario name in the PDF" || bad "scenario name missing"
# the re-rendered report says what the one written by assess said
pdftotext -layout run/report.pdf - 2>/dev/null | tr -s ' \n' '  ' > assess.txt
if [ -s assess.txt ] && cmp -s assess.txt x.txt; then
  ok "report from results.h5 alone has the text of assess's report.pdf"
else
  bad "report text differs from assess's report.pdf: $(diff <(tr ' ' '\n' < assess.txt) <(tr ' ' '\n' < x.txt) | head -5 | tr '\n' ' ')"
fi

# Each case's peaks-table row starts "<case> <peak force> <time> <impulse>",
# values from summary.json formatted to 3 significant digits in kN units.
python3 - x.txt run/summary.json <<'PY'
import json, math, sys
text = open(sys.argv[1]).read()
cases = json.load(open(sys.argv[2]))['cases']
SUP = str.maketrans('-0123456789', '\u207b\u2070\u00b9\u00b2\u00b3\u2074\u2075\u2076\u2077\u2078\u2079')
def fmt(v, sig=3):
    # fixed notation to `sig` significant digits, as the report prints
    # numbers between 1e-3 and 1e6 (trailing zeros kept); outside that
    # range a mantissa times a power of ten written in superscripts
    if v == 0: return "0"
    if abs(v) < 1e-3 or abs(v) >= 1e6:
        e = math.floor(math.log10(abs(v)))
        m = '%.*f' % (sig - 1, v / 10 ** e)
        if abs(float(m)) >= 10:  # rounded into the next decade
            e += 1
            m = '%.*f' % (sig - 1, v / 10 ** e)
        return m + '\u00d710' + str(e).translate(SUP)
    e = math.floor(math.log10(abs(v)))
    s = '%.*f' % (max(0, sig - 1 - e), v)
    if len(s.lstrip('-').replace('.', '').lstrip('0')) > sig:  # rounded into the next decade
        s = '%.*f' % (max(0, sig - 2 - e), v)
    return s
fails = 0
for name, c in cases.items():
    f = c['peak_force']['value'] / 1000.0
    t = c['peak_force_time']['value']
    i = c['impulse_positive']['value'] / 1000.0
    row = "%s %s %s %s" % (name, fmt(f), fmt(t), fmt(i))
    if row in text:
        print("PASS peaks row '%s' = summary.json's peak force %.6g N/m at %.4g s, positive impulse %.6g N s/m"
              % (row, f * 1000, t, i * 1000))
    else:
        print("FAIL peaks row '%s' (summary.json peak force %.6g N/m) not in the PDF text" % (row, f * 1000))
        fails += 1
    summ = "%s kN/m" % fmt(f)
    if summ in text:
        print("PASS the summary paragraph quotes the %s peak force '%s'" % (name, summ))
    else:
        print("FAIL '%s' not in the PDF text" % summ); fails += 1
sys.exit(fails)
PY
fail=$((fail+$?))
sha=$(python3 -c "import hashlib,sys; print(hashlib.sha256(open('tiny.yaml','rb').read()).hexdigest())")
grep -q "$sha" x.txt && ok "input digest = python hashlib SHA-256 of the scenario file" || bad "digest $sha not in the PDF"

# default output: report.pdf beside results.h5
out=$("$bin" report run/results.h5 2>&1); rc=$?
[ $rc = 0 ] && [ -s run/report.pdf ] && ok "default output run/report.pdf" || bad "default output: exit $rc: $out"

# a template with an unknown section is refused before anything is written
cat > bad.yaml <<'YAML'
title: Broken
sections:
  - { type: title }
  - { type: peeks }
YAML
out=$("$bin" report run/results.h5 -o bad.pdf --template bad.yaml 2>&1); rc=$?
[ $rc = 2 ] && grep -q "bad.yaml:4:" <<<"$out" && grep -q "peeks" <<<"$out" \
  && ok "unknown section -> exit 2: $out" || bad "unknown section: exit $rc: $out"
[ ! -e bad.pdf ] && [ ! -e bad.pdf.part ] && ok "no PDF for a bad template" || bad "bad template left a PDF"
# a good template from a file: two sections only
cat > short.yaml <<'YAML'
title: Peaks only
sections:
  - { type: peaks, digits: 4 }
  - { type: convergence }
YAML
out=$("$bin" report run/results.h5 -o short.pdf --template short.yaml 2>&1); rc=$?
[ $rc = 0 ] && pdftotext short.pdf - | grep -q "Peaks only" && ok "--template FILE used" || bad "--template: exit $rc: $out"

# a scenario that writes its depth in feet: summary.json and the report add
# the peaks in US customary units per foot of wall, converted here from the
# SI values with the exact definitions (1 ft = 0.3048 m, 1 lbf = 0.45359237
# kg x 9.80665 m/s^2)
sed 's/depth: 0.2 m/depth: 0.65617 ft/' tiny.yaml > tinyft.yaml
out=$("$bin" assess tinyft.yaml -o ft --quiet --end-time 0.3 2>&1); rc=$?
[ $rc = 0 ] && ok "assess of a scenario in feet (exit 0)" || bad "assess tinyft.yaml exit $rc: $out"
python3 - ft/summary.json <<'PY' && ok "summary.json's user_units = SI values in lbf/ft, lbf s/ft, lbf ft/ft, ft" || bad "user_units in summary.json"
import json, sys
cases = json.load(open(sys.argv[1]))['cases']
lbf, ft = 0.45359237 * 9.80665, 0.3048
conv = {'peak_force': (ft / lbf, 'lbf/ft'), 'peak_force_boundary': (ft / lbf, 'lbf/ft'),
        'impulse': (ft / lbf, 'lbf s/ft'), 'impulse_positive_phase': (ft / lbf, 'lbf s/ft'),
        'peak_moment': (1 / lbf, 'lbf ft/ft'), 'max_runup': (1 / ft, 'ft')}
bad = 0
for name, c in cases.items():
    u = c['user_units']
    for k, (f, unit) in conv.items():
        want = c[k]['value'] * f
        got = u[k]['value']
        if u[k]['unit'] != unit or abs(got - want) > 1e-8 * max(1.0, abs(want)):
            print('%s %s: %r %s, want %r %s' % (name, k, got, u[k]['unit'], want, unit)); bad += 1
sys.exit(bad)
PY
pdftotext -layout ft/report.pdf - 2>/dev/null | tr -s ' \n' '  ' > ft.txt
grep -q "in the scenario's units (US customary" ft.txt && grep -q "\[lbf/ft\]" ft.txt \
  && ok "the report adds the peaks in lbf/ft" || bad "no US customary peaks table in the report"
grep -q "lbf/ft" x.txt && bad "a scenario in metres got a lbf/ft table" || ok "no lbf/ft table for a scenario in metres"

out=$("$bin" report missing/results.h5 -o y.pdf 2>&1); rc=$?
[ $rc = 2 ] && grep -q "cannot open the results file: No such file or directory" <<<"$out" && ok "missing results -> 2: $out" || bad "missing results -> $rc: $out"
out=$("$bin" report 2>&1); rc=$?
[ $rc = 2 ] && ok "no arguments -> 2" || bad "no arguments -> $rc: $out"
out=$("$bin" report run/results.h5 --bogus 2>&1); rc=$?
[ $rc = 2 ] && ok "unknown option -> 2" || bad "unknown option -> $rc: $out"
out=$("$bin" report run/results.h5 -o 2>&1); rc=$?
[ $rc = 2 ] && ok "-o without a file -> 2" || bad "-o without a file -> $rc: $out"
exit $fail
