#!/usr/bin/env python3
"""validate_table.py OUTDIR: reference/RESULTS.md's tables from the
validation.json files that bench/validate_parallel.sh wrote (one directory
per case). Prints markdown: the summary table, then each case's levels."""
import json
import pathlib
import sys


def md(x):
    """a table cell: '|' (as in max|eta|) would end the cell"""
    return str(x).replace('|', '\\|')


def pct(x):
    return 'n/a' if x is None else '%+.1f %%' % (100 * x)


def main(out):
    cases = []
    for f in sorted(pathlib.Path(out).glob('*/validation.json')):
        cases += json.load(open(f))['cases']
    print('| case | primary metric | error by level | runtime [s] | order p | result at the finest level |')
    print('| --- | --- | --- | --- | --- | --- |')
    for c in cases:
        lv = c['levels']
        m0 = [l['metrics'][0] for l in lv if l['metrics']]
        name = m0[0]['name'] if m0 else '?'
        errs = ', '.join(pct(m['error']) if m['kind'] == 'relative' else '%.1f %%' % (100 * m['error'])
                         for m in m0)
        rts = ', '.join('%.1f' % l['runtime']['value'] for l in lv)
        order = '%.2f' % c['order'] if c.get('order') is not None else 'n/a'
        if c.get('order') is not None and not c.get('order_meaningful'):
            order += ' (not meaningful)'
        elif c.get('extrapolated_error') is not None:
            order += ' (extrapolated %s)' % pct(c['extrapolated_error'])
        res = ('pass' if c['pass'] else '**FAIL**') + ': ' + c['verdict']
        print('| %s | %s | %s | %s | %s | %s |' % (c['name'], md(name), errs, rts, order, md(res)))
    for c in cases:
        print('\n## %s: %s\n' % (c['name'], c['title']))
        print('| level | dp [m] | particles | steps | runtime [s] | metric | value | reference | error | tol | pass |')
        print('|---|---|---|---|---|---|---|---|---|---|---|')
        for i, l in enumerate(c['levels'], 1):
            for m in l['metrics']:
                tol = 'n/a' if m['tolerance'] is None else '%.1f %%' % (100 * m['tolerance'])
                err = pct(m['error']) if m['kind'] == 'relative' else '%.4g' % m['error']
                ok = ('yes' if m['pass'] else '**NO**') if m['judged'] else 'info'
                print('| %d | %.4g | %d | %d | %.1f | %s | %.5g %s | %.5g | %s | %s | %s |' % (
                    i, l['dp']['value'], l['particles'], l['steps'], l['runtime']['value'],
                    md(m['name']), m['value'], m['unit'], m['reference'], err, tol, ok))
            if l['status'] != 'ok':
                print('| %d | | | | | status | %s | | | | %s |' % (i, l['status'], md(l['message'])))


if __name__ == '__main__':
    main(sys.argv[1] if len(sys.argv) > 1 else 'validation-results')
