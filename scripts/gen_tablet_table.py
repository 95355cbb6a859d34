#!/usr/bin/env python3
"""Regenerates drivers/data/tablets.tsv: one row per tablet (VID:PID) that has data in
../shared/data/hid, with facts (name, maxima, size) from the OpenTabletDriver configs summary
there. Run from the repository root: scripts/gen_tablet_table.py > drivers/data/tablets.tsv
The protocol column is our own classification (see drivers/include/penshape/drivers/tablet_table.hpp)."""
import csv, glob, os, re, sys

DATA = os.path.join(os.path.dirname(__file__), '..', '..', 'shared', 'data', 'hid')
names = {}
for r in csv.DictReader(open(os.path.join(DATA, 'wacom-hid-descriptors/INDEX.tsv')), delimiter='\t'):
    names.setdefault((r['vid'].lower(), r['pid'].lower()), set()).add(r['device'])
for f in glob.glob(os.path.join(DATA, 'wacom-hid-descriptors/**/*.hid.bin'), recursive=True):
    rel = os.path.relpath(f, os.path.join(DATA, 'wacom-hid-descriptors'))
    name = os.path.basename(f)  # <bus>:<VID>:<PID>.<n>.hid.bin
    names.setdefault((name[5:9].lower(), name[10:14].lower()), set()).add(
        rel.split(os.sep)[0].replace('_', ' '))
for f in ['hid-tools-tests/tablet_rdescs.hidrec.txt', 'udev-hid-bpf/huion_xppen_rdescs.hidrec.txt']:
    name = None
    for line in open(os.path.join(DATA, f)):
        if line.startswith('N:'): name = line[2:].strip()
        if line.startswith('I:'):
            p = line.split()
            names.setdefault((p[2].lower(), p[3].lower()), set()).add(name)
for f in glob.glob(os.path.join(DATA, 'digimend-tablets/*/index.md')):
    t = open(f).read()
    key = (re.search(r'VID: "(\w+)"', t).group(1), re.search(r'PID: "(\w+)"', t).group(1))
    names.setdefault(key, set()).add(re.search(r'vendor: (.*)', t).group(1) + ' ' +
                                     re.search(r'product: (.*)', t).group(1))
otd = list(csv.DictReader(open(os.path.join(DATA, 'opentabletdriver/configs_summary.tsv')), delimiter='\t'))

def protocol(vid, pid, rows):
    init = ' '.join(r['init(F=feature,O=output hex; S=string idx)'] for r in rows)
    if vid == '056a' and pid in ('0010', '0061'): return 'wacom-graphire', ''
    parsers = {r['report_parser'] for r in rows}
    if vid == '056a' and 'IntuosReportParser' in parsers: return 'wacom-bamboo', 'F:0202'
    if vid == '056a' and parsers & {'IntuosV1ReportParser', 'IntuosProReportParser'}:
        return 'wacom-intuos', 'F:0202'
    if 'F:0202' in init: return 'wacom-hid', 'F:0202'
    if vid == '256c' and 'S:200' in init: return 'uclogic', 'S:200'
    if vid == '256c' and 'S:100' in init: return 'uclogic', 'S:100'
    m = re.search(r'O:(02b00[24])', init)
    if m: return 'xppen', 'O:' + m.group(1)
    return 'hid', ''

print('# penshape tablet table: VID/PID -> protocol, maxima, resolution, name.')
print('# Facts from OpenTabletDriver configs (../shared/data/hid/opentabletdriver, LGPL-3.0) and the')
print('# device names of wacom-hid-descriptors, hid-tools and DIGImend; regenerate with')
print('# scripts/gen_tablet_table.py. 0 = unknown or model-dependent (the device tells at runtime).')
print('# Columns: vid pid protocol init x_max y_max pressure_max x_res_per_mm y_res_per_mm name')
for (vid, pid) in sorted(names):
    rows = [r for r in otd if r['vid'].lower() == vid and r['pid'].lower() == pid]
    proto, init = protocol(vid, pid, rows)
    facts = {(r['max_x'], r['max_y'], r['max_pressure'], r['width_mm'], r['height_mm']) for r in rows}
    x = y = p = 0; xr = yr = 0.0
    if len(facts) == 1:
        mx, my, mp, w, h = facts.pop()
        x, y, p = int(float(mx)), int(float(my)), int(float(mp))
        xr = round(x / float(w), 3) if float(w) > 0 else 0.0
        yr = round(y / float(h), 3) if float(h) > 0 else 0.0
    if vid == '056a' and pid == '0061':  # Wacom PenStation2 / PenPartner: linux wacom_wac.c facts
        x, y, p, xr, yr = 3250, 2320, 255, 50.0, 50.0
    name = ' / '.join(sorted(n for n in names[(vid, pid)] if n))
    if rows and len(rows) > 1 and len({r['name'] for r in rows}) > 1:
        name += ' (PID shared by %d models)' % len({r['name'] for r in rows})
    elif rows:
        name = rows[0]['name']
    print('\t'.join([vid, pid, proto, init or '-', str(x), str(y), str(p), str(xr), str(yr), name]))
