#!/usr/bin/env python3
"""Regenerates drivers/data/tablets.tsv: one row per OpenTabletDriver device identifier (VID:PID,
device-string match, input report length) with its facts, plus the tablets that have captured
data in ../shared/data/hid but no OpenTabletDriver configuration. Run from the repository root:
  scripts/gen_tablet_table.py > drivers/data/tablets.tsv
The family column is our own classification (drivers/data/families.tsv defines each family's
report layout); the OpenTabletDriver parser class decides it, except where our captures showed
the device's own descriptor already describes the pen (kept as before: 'wacom-hid')."""
import csv, glob, os, re, sys

DATA = os.path.join(os.environ.get('PENSHAPE_SHARED_DATA_DIR') or
                    os.path.join(os.path.dirname(__file__), '..', '..', 'shared', 'data'), 'hid')

# OpenTabletDriver parser class -> our family (drivers/data/families.tsv).
FAMILY = {
    'XP_PenReportParser': 'xppen',
    'XP_PenGen2ReportParser': 'xppen-gen2',
    'XP_PenOffsetPressureReportParser': 'xppen-offset-pressure',
    'XP_PenOffsetAuxReportParser': 'xppen-offset-aux',
    'UCLogicReportParser': 'uclogic',
    'UCLogicV1ReportParser': 'uclogic',
    'UCLogicTiltReportParser': 'uclogic-tilt',
    'HuionTiltReportParser': 'uclogic-tilt',
    'InspiroyReportParser': 'uclogic-tilt',
    'UCLogicV2ReportParser': 'uclogic-v2',
    'GianoReportParser': 'huion-giano',
    'VeikkReportParser': 'veikk',
    'VeikkTiltReportParser': 'veikk-tilt',
    'VeikkV1ReportParser': 'veikk-v1',
    'VeikkA15ReportParser': 'veikk-a15',
    'AcepenReportParser': 'acepen',
    'GeniusReportParser': 'genius',
    'GeniusReportParserV2': 'genius-v2',
    'XenceLabsReportParser': 'xencelabs',
    'XENXReportParser': 'xenx',
    'LifetecReportParser': 'lifetec',
    'TabletReportParser': 'tablet',
    'SkipByteTabletReportParser': 'tablet-skip1',
    'GraphireReportParser': 'wacom-graphire',
    'BambooReportParser': 'wacom-graphire',  # the same packet (OTD: same report struct)
    'IntuosReportParser': 'wacom-bamboo',
    'WacomDriverIntuosReportParser': 'wacom-bamboo-skip1',
    'IntuosV1ReportParser': 'wacom-intuos',
    'IntuosProReportParser': 'wacom-intuos',
    'WacomDriverIntuosV1ReportParser': 'wacom-intuos-skip1',
    'WacomDriverIntuosProReportParser': 'wacom-intuos-skip1',
    'Intuos3ReportParser': 'wacom-intuos3',
    'Intuos3ExtraAuxReportParser': 'wacom-intuos3',
    'WacomDriverIntuos3ReportParser': 'wacom-intuos3-skip1',
    'Intuos4ReportParser': 'wacom-intuos4',
    'WacomDriverIntuos4ReportParser': 'wacom-intuos4-skip1',
    'CintiqV1ReportParser': 'wacom-cintiq',
    'IntuosV2ReportParser': 'wacom-intuos-v2',
    'WacomDriverIntuosV2ReportParser': 'wacom-intuos-v2-skip1',
    'IntuosV3ReportParser': 'wacom-intuos-v3',
    'WacomDriverIntuosV3ReportParser': 'wacom-intuos-v3-skip1',
    'BambooPadReportParser': 'wacom-bamboo-pad',
    'PTUReportParser': 'wacom-ptu',
    # Auxiliary interfaces only (pad, touch): the pen is on the interface the descriptor describes.
    'Wacom64bAuxReportParser': 'wacom-hid',
    'BambooV2AuxReportParser': 'wacom-hid',
    # Not yet decoded by a family of ours: the descriptor path (firmware mode) only.
    'PLReportParser': 'hid',
    'WoodPadReportParser': 'hid',
    'RobotPenReportParser': 'hid',
    'FmaReportParser': 'hid',
}


def shared_names():
    """Device names of every VID:PID with captured data in ../shared/data/hid."""
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
    return names


def family_of(vid, pid, parser, init):
    if vid == '056a' and pid in ('0010', '0061'): return 'wacom-graphire'
    fam = FAMILY.get(parser)
    if fam is None:
        sys.exit('gen_tablet_table: no family for OpenTabletDriver parser ' + parser)
    # Wacom tablets whose own descriptor describes the pen after the mode switch (our captures
    # of CTL-4100, PTH-460, PTK-470...): keep the descriptor path, as before.
    if fam in ('wacom-intuos-v2', 'wacom-intuos-v3') and 'F:0202' in init: return 'wacom-hid'
    return fam


def number(s):
    v = float(s)
    return str(int(v)) if v == int(v) else ('%.4f' % v).rstrip('0')


def otd_rows():
    rows = list(csv.DictReader(open(os.path.join(DATA, 'opentabletdriver/configs_summary.tsv')),
                               delimiter='\t'))
    out = {}  # (vid, pid, match, len) -> row; first configuration in file order wins
    for r in rows:
        vid, pid = r['vid'].lower(), r['pid'].lower()
        init = r['init(F=feature,O=output hex; S=string idx)'].strip()
        # One string index per step (the summary lists several as S:100,123).
        init = ' '.join(' '.join('S:' + i for i in step[2:].split(',')) if step.startswith('S:')
                        else step for step in init.split())
        key = (vid, pid, r['device_string_match'] or '-', r['input_report_len'] or '0')
        fam = family_of(vid, pid, r['report_parser'], init)
        facts = [fam, init or '-', key[3], number(r['max_x']), number(r['max_y']),
                 number(r['max_pressure']), number(r['width_mm']), number(r['height_mm']),
                 r['pen_buttons'] or '0', key[2]]
        if key in out:
            # OpenTabletDriver cannot tell these configurations apart either (it takes the
            # first match): keep the first one's facts and name both.
            if out[key][1] != facts:
                print('gen_tablet_table: %s:%s %s len %s: %s and %s differ; keeping the first'
                      % (vid, pid, key[2], key[3], out[key][0], r['name']), file=sys.stderr)
            if r['name'] not in out[key][0].split(' / '):
                out[key][0] += ' / ' + r['name']
            continue
        out[key] = [r['name'], facts]
    return out


def main():
    print('# penshape tablet table: one row per device identifier (VID:PID, device strings, report')
    print('# length) -> family, init, maxima, physical size, pen buttons, name.')
    print('# Facts from the OpenTabletDriver configurations (../shared/data/hid/opentabletdriver,')
    print('# LGPL-3.0) and the device names of wacom-hid-descriptors, hid-tools and DIGImend;')
    print('# regenerate with scripts/gen_tablet_table.py. 0 = unknown (the device tells at runtime).')
    print('# Columns: vid pid family init report_len x_max y_max pressure_max width_mm height_mm')
    print('#   pen_buttons device_match name')
    print('# init: F:hex feature report, O:hex output report, S:index string descriptor, or -.')
    print('# device_match: - or index=regex;... on the USB string descriptors (all must match).')
    otd = otd_rows()
    lines = []
    for (vid, pid, match, length), (name, facts) in otd.items():
        lines.append([vid, pid] + facts[:-1] + [match, name])
    otd_pairs = {(k[0], k[1]) for k in otd}
    names = shared_names()
    # Captured tablets OpenTabletDriver has no configuration for: the descriptor path, with the
    # facts we already had (PenPartner: the Linux wacom driver's numbers).
    extra = {('056a', '0010'): ['wacom-graphire', '-', '0', '10208', '7424', '511', '127.6', '92.8', '2'],
             ('056a', '0061'): ['wacom-graphire', '-', '0', '3250', '2320', '255', '65', '46.4', '2']}
    for key in sorted(names):
        if key in otd_pairs: continue
        name = ' / '.join(sorted(n for n in names[key] if n))
        facts = extra.get(key, ['hid', '-', '0', '0', '0', '0', '0', '0', '0'])
        lines.append(list(key) + facts + ['-', name])
    for l in sorted(lines, key=lambda l: (l[0], l[1], l[11] == '-', l[11], int(l[4]))):
        print('\t'.join(l))


main()
