#!/usr/bin/env python3
"""No argument list reaches exit 3 (internal error) or a signal (issue 51).

usage: argv_guard.py GSDOT3 WORKDIR DATADIR

Every command (and subcommand) `gsdot3 --help` lists is run on a cheap valid base argument list; each
option its `--help` lists (so a new option is covered without editing this file) is given, in place of
the base's, each value of a list of valid, boundary and invalid ones, and each positional each file-like
value. A run passes when it exits 0, 1 or 2, and an exit 2 ends with one line starting "gsdot3: error:"
(progress lines may come before it). A run that outlives the time limit is reported, not failed. Prints
one line per failure and the closing line "N runs: ..., K failures".
"""
import concurrent.futures
import os
import re
import shutil
import subprocess
import sys

TIMEOUT = 8  # seconds; the values are chosen so that most runs end in well under one

def values(work):
    """Every value for the cheap commands, a short list for the slow ones (a second or more per valid
    run), and the values of a positional."""
    full = ['', '0', '-1', '1', '0.5', '99999999999999999999', '1x1', '0x0', '100000x1', 'nan', 'bogus',
            os.path.join(work, 'no-such-file'), os.path.join(work, 'adir'), os.path.join(work, 'rgb.png'),
            os.path.join(work, 'd.gs')]
    short = ['', '-1', '0', 'nan', 'bogus', '99999999999999999999', os.path.join(work, 'rgb.png')]
    files = ['', os.path.join(work, 'no-such-file'), os.path.join(work, 'adir'), os.path.join(work, 'rgb.png'),
             os.path.join(work, 'd.gs'), os.path.join(work, 'v.txt')]
    return full, short, files


def bases(work, data):
    """A cheap valid argument list per command path, whether the command is slow, and the command whose
    options it shares (report and dump take render's scene options: only their own are run here)."""
    rgb, grey, dump = (os.path.join(work, n) for n in ('rgb.png', 'grey.png', 'd.gs'))
    mesh = os.path.join(data, 'meshes', 'quad_bump.obj')
    render = ['--method', 'two-pass', '--size', '16x16', '--out', 'o']
    return {
        ('alu',): (['--vertex', 'ff402040'], False, None),
        ('normal-encoding',): (['--no-worst-case', '--bits', '4'], True, None),
        ('mem', 'addr'): (['--psm', 'PSMCT32', '0', '0'], False, None),
        ('mem', 'view'): (['-o', 'm.png'], False, None),
        ('mesh-info',): ([mesh], False, None),
        ('prove',): (['--claim', 'eq4.signed-multiply', '--no-variants'], False, None),
        ('prove', 'merge'): ([os.path.join(work, 'part.json')], False, None),
        ('pvr-bump',): ([rgb, 'b.raw'], False, None),
        ('quality',): (['--scenes', '0'], True, None),
        ('render',): (render, False, None),
        ('report',): (render, True, ('render',)),
        ('ssbump', 'from-normal'): ([rgb, 's.png'], False, None),
        ('ssbump', 'from-height'): ([grey, 's.png', '--scale', '1'], False, None),
        ('vectors', 'gen'): (['--unit', 'colclamp'], False, None),
        ('vectors', 'ver'): ([os.path.join(work, 'v.txt')], False, None),
        ('dump-info',): ([dump], False, None),
        ('compare',): ([rgb, rgb], False, None),
        ('replay',): ([dump, '--out', 'rep'], False, None),
        ('probe',): (['--out', 'p.gs'], False, None),
        ('probe', 'decode'): ([os.path.join(work, 'shot.png')], False, None),
        ('dump',): (['--method', 'two-pass', '--size', '16x16', '--out', 'x.gs'], True, ('render',)),
        ('cost',): ([dump], False, None),
    }


def run(gsdot3, cwd, args):
    try:
        p = subprocess.run([gsdot3] + args, cwd=cwd, stdin=subprocess.DEVNULL, stdout=subprocess.DEVNULL,
                           stderr=subprocess.PIPE, timeout=TIMEOUT)
    except subprocess.TimeoutExpired:
        return 'timeout', ''
    return p.returncode, p.stderr.decode('utf-8', 'replace')


def help_of(gsdot3, path):
    out = subprocess.run([gsdot3] + list(path) + ['--help'], stdout=subprocess.PIPE, check=True).stdout.decode()
    options, positionals, subcommands, section = [], [], [], None
    for line in out.splitlines():
        if re.match(r'^\S.*:$', line):
            section = line[:-1]
            continue
        m = re.match(r'^  (?:-\w,)?(--[\w-]+)(.*)$', line)
        if section == 'Options' and m and m.group(1) not in ('--help', '--version'):
            rest = re.split(r'\s{2,}', m.group(2).lstrip(' '), maxsplit=1)[0] if m.group(2).startswith(' ') else ''
            options.append((m.group(1), rest != ''))
        m = re.match(r'^  ([A-Z][A-Z0-9_]*) ', line)
        if section == 'Positionals' and m:
            positionals.append(m.group(1))
        m = re.match(r'^  ([a-z][\w-]*)', line)
        if section == 'Subcommands' and m:
            subcommands.append(m.group(1))
    return options, positionals, subcommands


def without(base, option, takes_value):
    """`base` without `option` (and its value)."""
    out, skip = [], False
    for a in base:
        if skip:
            skip = False
        elif a == option:
            skip = takes_value
        else:
            out.append(a)
    return out


def cases(gsdot3, work, data):
    full, short, files = values(work)
    table = bases(work, data)
    paths, todo = [], [()]
    while todo:
        path = todo.pop()
        options, positionals, subs = help_of(gsdot3, path)
        todo += [path + (s,) for s in subs]
        if path:
            paths.append((path, options, positionals))
    options_of = {path: options for path, options, _ in paths}
    for path, options, positionals in paths:
        if path not in table:
            if not any(p[:len(path)] == path and p != path for p, _, _ in paths):
                yield path, None  # a command without a base here: a failure, so that it gets one
            continue
        base, slow, shares = table[path]
        yield path, base
        for option, takes_value in options:
            if shares and (option, takes_value) in options_of[shares]:
                continue
            rest = without(base, option, takes_value)
            for v in (short if slow else full) if takes_value else [None]:
                yield path, rest + ([option] if v is None else [option, v])
        # Positionals: the base's leading non-option arguments, each replaced by each file value.
        for i in range(len(positionals)):
            if i < len(base) and not base[i].startswith('-'):
                for v in files:
                    yield path, base[:i] + [v] + base[i + 1:]


def setup(gsdot3, work, data):
    shutil.rmtree(work, ignore_errors=True)
    os.makedirs(os.path.join(work, 'adir'))
    steps = [['render', '--method', 'two-pass', '--size', '16x16', '--out', os.path.join(work, 'r')],
             ['dump', '--method', 'two-pass', '--size', '16x16', '--out', os.path.join(work, 'd.gs')],
             ['probe', '--out', os.path.join(work, 'p.gs'), '--png', os.path.join(work, 'shot.png')],
             ['prove', '--claim', 'eq4.signed-multiply', '--shard', '0/1', '--json', '-o',
              os.path.join(work, 'part.json')]]
    for s in steps:
        subprocess.run([gsdot3] + s, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
    shutil.copy(os.path.join(work, 'r', 'two-pass-lit.png'), os.path.join(work, 'rgb.png'))
    shutil.copy(os.path.join(data, 'meshes', 'ramp_height.png'), os.path.join(work, 'grey.png'))
    with open(os.path.join(work, 'v.txt'), 'wb') as f:
        subprocess.run([gsdot3, 'vectors', 'gen', '--unit', 'colclamp'], check=True, stdout=f,
                       stderr=subprocess.DEVNULL)


def judge(code, err):
    if code == 'timeout':
        return 'timeout'
    if code < 0:
        return 'signal %d' % -code
    if code not in (0, 1, 2):
        return 'exit %d: %s' % (code, err.strip().splitlines()[-1:] or '')
    if code == 2:
        lines = [l for l in err.splitlines() if l.strip()]
        errors = [l for l in lines if l.startswith('gsdot3: error:')]
        if not lines or not lines[-1].startswith('gsdot3: error:') or len(errors) != 1:
            return 'exit 2 without one closing line "gsdot3: error: ...": %r' % err[-300:]
    return None


def main():
    gsdot3, work, data = os.path.abspath(sys.argv[1]), os.path.abspath(sys.argv[2]), os.path.abspath(sys.argv[3])
    setup(gsdot3, work, data)
    all_cases = list(cases(gsdot3, work, data))
    runs, failures, timeouts, codes = 0, [], [], {}

    def one(k, path, args):
        cwd = os.path.join(work, 'run%d' % k)
        os.makedirs(cwd)
        code, err = run(gsdot3, cwd, list(path) + args)
        shutil.rmtree(cwd, ignore_errors=True)
        return path, args, code, err

    with concurrent.futures.ThreadPoolExecutor(max_workers=2) as pool:
        futures = []
        for k, (path, args) in enumerate(all_cases):
            if args is None:
                failures.append('%s: no base argument list in argv_guard.py' % ' '.join(path))
                continue
            futures.append(pool.submit(one, k, path, args))
        for f in futures:
            path, args, code, err = f.result()
            runs += 1
            codes[code] = codes.get(code, 0) + 1
            verdict = judge(code, err)
            line = 'gsdot3 %s' % ' '.join(list(path) + [repr(a) if a == '' or ' ' in a else a for a in args])
            if verdict == 'timeout':
                timeouts.append(line)
            elif verdict:
                failures.append('%s: %s' % (line, verdict))
    for t in timeouts:
        print('TIMEOUT (%d s, not a failure) %s' % (TIMEOUT, t))
    for f in failures:
        print('FAIL ' + f)
    print('%d runs: %s, %d timeouts, %d failures' %
          (runs, ', '.join('exit %s %d' % (c, n) for c, n in sorted(codes.items(), key=str)), len(timeouts),
           len(failures)))
    return 1 if failures else 0


if __name__ == '__main__':
    sys.exit(main())
