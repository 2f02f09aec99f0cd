#!/usr/bin/python3
"""The runtime's layering, checked: no file includes a header of a higher layer.

  scripts/check_layers.py [SOURCE_DIR] [--graph] [--self-test]

runtime/layers.txt lists the layers bottom first, each with its folders; a file may include
headers of its own layer and of lower ones. Every `#include "..."` of every .cpp/.hpp under
runtime/ that names a file of runtime/ is checked. Exit 1, naming file, line and both layers,
on an upward include, on a folder of runtime/ that is in no layer, or when docs/runtime.md's
layer table does not list layers.txt's layers in its order. --graph also prints the folder
include graph's strongly connected components (how the include cycles were measured);
--self-test also checks that a planted upward include is refused.
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"', re.M)
DOC_ROW = re.compile(r'^\|\s*`([a-z_]+)`\s*\|', re.M)


def read_layers(runtime):
    layers, folder_layer = [], {}
    if not os.path.exists(os.path.join(runtime, 'layers.txt')):  # a tree from before the layers: --graph only
        return layers, {e: None for e in os.listdir(runtime) if os.path.isdir(os.path.join(runtime, e))} | {'.': None}
    for line in open(os.path.join(runtime, 'layers.txt'), encoding='utf-8'):
        line = line.split('#', 1)[0].strip()
        if not line:
            continue
        name, *folders = line.split()
        layers.append(name)
        for f in folders:
            folder_layer[f] = len(layers) - 1
    return layers, folder_layer


def folder_of(rel):
    return rel.split('/', 1)[0] if '/' in rel else '.'


def sources(runtime):
    for root, _, files in os.walk(runtime):
        for name in sorted(files):
            if name.endswith(('.cpp', '.hpp')):
                path = os.path.join(root, name)
                yield os.path.relpath(path, runtime), open(path, encoding='utf-8').read()


def includes(runtime, text):
    for m in INCLUDE.finditer(text):
        target = m.group(1)
        if os.path.isfile(os.path.join(runtime, target)):
            yield text.count('\n', 0, m.start()) + 1, target


def strongly_connected(edges, nodes):
    index, low, stack, on, out, counter = {}, {}, [], set(), [], [0]

    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in sorted(edges.get(v, ())):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            component = []
            while True:
                w = stack.pop()
                on.discard(w)
                component.append(w)
                if w == v:
                    break
            out.append(sorted(component))

    for v in sorted(nodes):
        if v not in index:
            visit(v)
    return out


def self_test(source):
    """The check must fail on an upward include: a copy of runtime/ with one planted."""
    import shutil
    import subprocess
    import tempfile
    with tempfile.TemporaryDirectory() as tmp:
        shutil.copytree(os.path.join(source, 'runtime'), os.path.join(tmp, 'runtime'))
        shutil.copytree(os.path.join(source, 'docs'), os.path.join(tmp, 'docs'))
        planted = os.path.join(tmp, 'runtime', 'input', 'scene.hpp')
        with open(planted, 'a', encoding='utf-8') as f:
            f.write('\n#include "run/static_run.hpp"\n')
        run = subprocess.run([sys.executable, os.path.abspath(__file__), tmp], capture_output=True, text=True)
        if run.returncode != 1 or 'runtime/input/scene.hpp' not in run.stdout or 'layer drivers' not in run.stdout:
            print(f'FAIL self-test: an include of run/ planted in input/scene.hpp gave exit {run.returncode}:\n{run.stdout}')
            return False
    print('ok   self-test: an include of run/ planted in input/scene.hpp is refused')
    return True


def main(argv):
    args = [a for a in argv[1:] if not a.startswith('--')]
    source = os.path.abspath(args[0] if args else os.path.join(os.path.dirname(__file__), '..'))
    runtime = os.path.join(source, 'runtime')
    layers, folder_layer = read_layers(runtime)
    problems = []
    for entry in sorted(os.listdir(runtime)):
        if layers and os.path.isdir(os.path.join(runtime, entry)) and entry not in folder_layer:
            problems.append(f'runtime/{entry}/: in no layer (add it to runtime/layers.txt)')
    edges, checked = {}, 0
    for rel, text in sources(runtime):
        src = folder_of(rel)
        for line, target in includes(runtime, text):
            checked += 1
            dst = folder_of(target)
            if dst != src and '.' not in (src, dst):  # the graph of folders (runtime/'s own files aside)
                edges.setdefault(src, set()).add(dst)
            a, b = folder_layer.get(src), folder_layer.get(dst)
            if a is not None and b is not None and b > a:
                problems.append(f'runtime/{rel}:{line}: includes "{target}": layer {layers[a]} ({src}/) may not '
                                f'include layer {layers[b]} ({dst}/), which is above it')
    doc = open(os.path.join(source, 'docs', 'runtime.md'), encoding='utf-8').read()
    documented = [m for m in DOC_ROW.findall(doc) if m in layers]
    if layers and documented != layers:
        problems.append(f'docs/runtime.md: its layer table lists {documented}, runtime/layers.txt has {layers}')
    if '--graph' in argv:
        components = strongly_connected(edges, set(folder_layer) - {'.'})
        cycles = [c for c in components if len(c) > 1]
        print(f'{len(components)} strongly connected components of {len(folder_layer) - 1} folders; '
              f'{len(cycles)} with more than one folder: {cycles}')
    for p in problems:
        print('FAIL', p)
    print(f'{checked} includes of runtime/ headers checked against {len(layers)} layers: '
          f'{len(problems)} problem(s)')
    if '--self-test' in argv and not self_test(source):
        return 1
    return 1 if problems else 0


if __name__ == '__main__':
    sys.exit(main(sys.argv))
