"""results_dir_check.py DIR: the files of a `wallload assess` output
directory, as tests/cli_faults.sh and tests/cli_signals.sh judge them after
a refused write or a signal: every final file complete (JSON parses, CSV
rows whole and the last line ended, the XDMF index parses, an HDF5 file's
superblock records an end of file within the file, the PDF passes pdfinfo),
no temporary file (*.tmp, *.part) and no lock left (--allow-temporary: a
killed run's are allowed, and it is not held to the next rule, since it
may have stopped between two renames of one move into place), and one
run's files (no CSV or snapshot file of a case that summary.json does not
list). Prints the problems (and, with
--statuses, each case's status from summary.json); exit 1 when there are
problems."""
import csv, json, os, subprocess, sys
import xml.etree.ElementTree as ET
args = [a for a in sys.argv[1:] if not a.startswith('--')]
flags = set(a for a in sys.argv[1:] if a.startswith('--'))
d = args[0]
probs = []
names = sorted(os.listdir(d)) if os.path.isdir(d) else []
for n in names:
    p = os.path.join(d, n)
    try:
        if n.endswith('.tmp') or n.endswith('.part'):
            if '--allow-temporary' not in flags:
                probs.append('temporary file left: ' + n)
        elif n == '.wallload.lock':
            if '--allow-temporary' not in flags:
                probs.append('lock file left')
        elif n.endswith('.json'):
            json.load(open(p))
        elif n.endswith('.csv'):
            text = open(p).read()
            if not text.endswith('\n'):
                raise ValueError('last line not ended')
            rows = list(csv.reader(text.splitlines()))
            if not rows or any(len(r) != len(rows[0]) for r in rows):
                raise ValueError('rows of unequal length')
        elif n.endswith('.xmf'):
            if ET.parse(p).getroot().tag != 'Xdmf':
                raise ValueError('not XDMF')
        elif n.endswith('.h5'):
            # HDF5 superblock: signature, and the end-of-file address it
            # records within the file's size (a cut file fails this)
            b = open(p, 'rb').read(64)
            if b[:8] != b'\x89HDF\r\n\x1a\n':
                raise ValueError('no HDF5 signature')
            so = b[13] if b[8] in (0, 1) else b[9]
            off = 40 if b[8] in (0, 1) else 28
            if b[8] == 1:
                off += 4
            eof = int.from_bytes(b[off:off + so], 'little')
            if eof > os.path.getsize(p):
                raise ValueError('superblock says %d bytes, the file has %d' % (eof, os.path.getsize(p)))
        elif n.endswith('.pdf'):
            r = subprocess.run(['pdfinfo', p], capture_output=True, text=True)
            if r.returncode != 0 or 'Pages:' not in r.stdout:
                raise ValueError('pdfinfo: ' + r.stderr.strip())
    except Exception as e:
        probs.append('%s: %s' % (n, e))
killed = '--allow-temporary' in flags  # may have stopped between two renames of one move
if 'summary.json' in names and not killed:
    try:
        cases = set(json.load(open(os.path.join(d, 'summary.json')))['cases'])
        for n in names:
            for stem in ('_wall.csv', '_gauges.csv'):
                if n.endswith(stem) and n[:-len(stem)] not in cases:
                    probs.append('%s: a case summary.json does not list' % n)
            if n.startswith('particles_') and n.split('_', 1)[1].rsplit('.', 1)[0] not in cases:
                probs.append('%s: a case summary.json does not list' % n)
    except Exception as e:
        probs.append('summary.json: %s' % e)
elif not killed and any(n.endswith('.csv') or n == 'results.h5' or n == 'report.pdf' for n in names):
    probs.append('results without summary.json: ' + ' '.join(names))
if '--statuses' in flags and 'summary.json' in names and not probs:
    cases = json.load(open(os.path.join(d, 'summary.json')))['cases']
    print(' '.join('%s=%s' % (k, v['status']) for k, v in cases.items()))
else:
    print('; '.join(probs))
sys.exit(1 if probs else 0)
