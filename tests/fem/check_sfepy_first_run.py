"""SfePy's first run on a fresh machine, as ctest -j meets it (issue 34).

  /usr/bin/python3 tests/fem/check_sfepy_first_run.py SOURCE_DIR

Debian's SfePy creates ~/.sfepy at import with `if not exists: makedirs`, so two scripts that
import it at once on a machine without the directory can both see it missing, and the second
dies with FileExistsError. The tree's answer is scripts/fem/sfepy_ready.py, imported before
SfePy. Three checks, each with a new, empty HOME; exit 1 if any fails:

1. every Python file under scripts/, studies/ and tests/ that imports SfePy imports sfepy_ready
   before its first SfePy import (so a script added later cannot bring the race back);
2. the losing interleaving, forced: SfePy's existence check is answered truthfully (missing),
   and then a competing process creates the directory before SfePy's makedirs runs. Every SfePy
   script's imports are executed that way (runpy, not as __main__, so only the module level
   runs). On the old scripts this raises FileExistsError every time; race-free, it cannot;
3. the real thing: all the SfePy scripts' imports started at the same moment (released by one
   barrier), several processes per script.
"""
import atexit
import multiprocessing
import os
import re
import shutil
import subprocess
import sys
import tempfile

SFEPY_IMPORT = re.compile(r'^\s*(from\s+sfepy[.\s]|import\s+sfepy\b)', re.M)
READY_IMPORT = re.compile(r'^\s*import\s+sfepy_ready\b', re.M)

# Run in a child interpreter: makes os.path.exists lose the race for ~/.sfepy, then executes
# the script's module level.
FORCED_INTERLEAVING = r'''
import os, runpy, sys
script = sys.argv[1]
target = os.path.expanduser("~/.sfepy")
real_exists = os.path.exists
def exists_then_lose(path):
    answer = real_exists(path)
    if not answer and os.path.abspath(str(path)) == target:
        os.mkdir(target)  # the other process wins between the check and the create
    return answer
os.path.exists = exists_then_lose
sys.path.insert(0, os.path.dirname(os.path.abspath(script)))
runpy.run_path(script, run_name="sfepy_first_run_check")
'''


def sfepy_scripts(source):
    found = []
    for top in ('scripts', 'studies', 'tests'):
        for root, dirs, files in os.walk(os.path.join(source, top)):
            dirs[:] = [d for d in dirs if d not in ('__pycache__',)]
            for name in files:
                path = os.path.join(root, name)
                if name.endswith('.py') and path != os.path.abspath(__file__) and name != 'sfepy_ready.py':
                    text = open(path, encoding='utf-8').read()
                    if SFEPY_IMPORT.search(text):
                        found.append((path, text))
    return sorted(found)


def fresh_env():
    home = tempfile.mkdtemp(prefix='sfepy_home_')
    atexit.register(shutil.rmtree, home, True)
    env = dict(os.environ, HOME=home)
    env.pop('MPLCONFIGDIR', None)
    return env, home


def import_order_ok(path, text):
    first_sfepy = SFEPY_IMPORT.search(text).start()
    ready = READY_IMPORT.search(text)
    if ready is None or ready.start() > first_sfepy:
        print(f'FAIL {path}: imports SfePy without importing sfepy_ready first '
              '(scripts/fem/sfepy_ready.py; issue 34)')
        return False
    return True


def forced_interleaving_ok(path):
    env, home = fresh_env()
    run = subprocess.run([sys.executable, '-c', FORCED_INTERLEAVING, path], env=env,
                         capture_output=True, text=True, timeout=300)
    if run.returncode != 0 or not os.path.isdir(os.path.join(home, '.sfepy')):
        tail = '\n'.join(run.stderr.strip().splitlines()[-3:])
        print(f'FAIL {path}: the losing interleaving of SfePy\'s check-then-create, exit {run.returncode}:\n{tail}')
        return False
    print(f'ok   {path}: imports survive a competitor creating ~/.sfepy mid-check')
    return True


def released_together(args):
    path, home, barrier = args
    barrier.wait()
    env = dict(os.environ, HOME=home)
    return path, subprocess.run([sys.executable, '-c',
                                 'import os,runpy,sys; sys.path.insert(0, os.path.dirname(sys.argv[1])); '
                                 'runpy.run_path(sys.argv[1], run_name="sfepy_first_run_check")', path],
                                env=env, capture_output=True, text=True, timeout=300)


def concurrent_ok(paths, copies=3):
    _, home = fresh_env()
    jobs = [p for p in paths for _ in range(copies)]
    manager = multiprocessing.Manager()
    barrier = manager.Barrier(len(jobs))
    with multiprocessing.Pool(len(jobs)) as pool:
        results = pool.map(released_together, [(p, home, barrier) for p in jobs])
    bad = [(p, r) for p, r in results if r.returncode != 0]
    for p, r in bad:
        print(f'FAIL {p} (started with {len(jobs) - 1} others, one fresh HOME): exit {r.returncode}:\n'
              + '\n'.join(r.stderr.strip().splitlines()[-3:]))
    if not bad:
        print(f'ok   {len(jobs)} SfePy imports started at once with one fresh HOME')
    return not bad


def main():
    if len(sys.argv) != 2:
        print(__doc__.strip().splitlines()[2], file=sys.stderr)
        return 2
    source = os.path.abspath(sys.argv[1])
    scripts = sfepy_scripts(source)
    if not scripts:
        print(f'FAIL no Python file under {source} imports SfePy: wrong SOURCE_DIR?')
        return 1
    ok = all([import_order_ok(p, t) for p, t in scripts])
    ok = all([forced_interleaving_ok(p) for p, _ in scripts]) and ok
    ok = concurrent_ok([p for p, _ in scripts]) and ok
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
