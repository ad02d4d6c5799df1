#!/usr/bin/env python3
"""An interrupted `gsdot3 report` leaves nothing beside its --out (issue 51).

usage: interrupt_test.py GSDOT3 WORKDIR SIGNAL...

For each signal (INT, TERM): starts `gsdot3 report --out WORKDIR/SIG/out`, waits until its
staging folder out.partial-PID-N appears, sends the signal, and checks that the process ended by that
signal and that WORKDIR/SIG holds nothing (no out, no staging folder). Python, not sh: a background job
of a non-interactive sh starts with SIGINT ignored, which gsdot3 rightly leaves ignored.
"""
import os
import shutil
import signal
import subprocess
import sys
import time


def run(gsdot3, work, name):
    sig = getattr(signal, 'SIG' + name)
    folder = os.path.join(work, name)
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    p = subprocess.Popen([gsdot3, 'report', '--out', os.path.join(folder, 'out')],
                         stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    staging = 'out.partial-%d-' % p.pid
    deadline = time.monotonic() + 60
    while not any(n.startswith(staging) for n in os.listdir(folder)):
        if p.poll() is not None or time.monotonic() > deadline:
            p.kill()
            return 'FAIL %s: no staging folder %s* appeared (exit %s)' % (name, staging, p.poll())
        time.sleep(0.01)
    time.sleep(0.5)  # into the run (4 s at the default 512x448; 96x80 ends in 0.5 s): frames being written
    p.send_signal(sig)
    code = p.wait(timeout=60)
    left = sorted(os.listdir(folder))
    if code != -sig or left:
        return 'FAIL %s: exit %s (want %s), left beside --out: %s' % (name, code, -sig, left)
    return 'OK %s: ended by the signal, nothing left' % name


def main():
    gsdot3, work = sys.argv[1], sys.argv[2]
    results = [run(gsdot3, work, name) for name in sys.argv[3:]]
    print('\n'.join(results))
    return 1 if any(r.startswith('FAIL') for r in results) else 0


if __name__ == '__main__':
    sys.exit(main())
