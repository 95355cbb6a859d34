#!/usr/bin/env python3
"""Regenerates packaging/70-penshape-tablets.rules from drivers/data/tablets.tsv: for every
supported tablet, its hidraw nodes (any bus: the HID device name is BUS:VID:PID.N) and its USB
device node (libusb: UC-Logic string descriptors) get TAG+="uaccess", so the logged-in user's
penshaped reads them without root. Run from the repository root:
  scripts/gen_udev_rules.py > packaging/70-penshape-tablets.rules"""
import os

root = os.path.join(os.path.dirname(__file__), '..')
names = {}  # (vid, pid) -> model names, in table order (several rows may share a VID:PID)
for line in open(os.path.join(root, 'drivers/data/tablets.tsv')):
    if line.startswith('#') or not line.strip():
        continue
    c = line.rstrip('\n').split('\t')
    models = names.setdefault((c[0].lower(), c[1].lower()), [])
    for name in c[12].split(' / '):
        if name not in models:
            models.append(name)
rows = [(vid, pid, ' / '.join(models)) for (vid, pid), models in names.items()]

print('# penshape: give the active local user (uaccess) the hidraw and USB nodes of the tablets')
print('# penshape supports. Generated from drivers/data/tablets.tsv by scripts/gen_udev_rules.py.')
print('# Install: sudo cp 70-penshape-tablets.rules /etc/udev/rules.d/ &&')
print('#          sudo udevadm control --reload && sudo udevadm trigger')
print('# The number sorts before 73-seat-late.rules, which turns the uaccess tag into an ACL.')
print('ACTION=="remove", GOTO="penshape_end"')
print()
for vid, pid, name in rows:
    print('# ' + name)
    print('KERNEL=="hidraw*", KERNELS=="*:%s:%s.*", TAG+="uaccess"' % (vid.upper(), pid.upper()))
    print('SUBSYSTEM=="usb", ENV{DEVTYPE}=="usb_device", ATTR{idVendor}=="%s", '
          'ATTR{idProduct}=="%s", TAG+="uaccess"' % (vid, pid))
print()
print('LABEL="penshape_end"')
