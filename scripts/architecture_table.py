#!/usr/bin/env python3
"""Prints the table of docs/architecture.md that maps each operation of
src/volume and src/surface to the pipelines that use it, from the include
graph: a pipeline uses a file when the C API file it starts in reaches the
file's header through the includes of src/ (a header's .cpp counts as
included with it). Usage: python3 scripts/architecture_table.py (from the
source root); the output replaces the part between the page's
'pipelines:begin' and 'pipelines:end' markers."""
import os
import re

# Each pipeline by the C API file it starts in (src/api/); drain and
# powder-sim share drain_api.cpp, every command reads through mesh_api.cpp.
PIPELINES = [
    ('info', ['api/mesh_api.cpp']),
    ('repair', ['api/volume_api.cpp']),
    ('hollow', ['api/hollow_api.cpp']),
    ('drain, powder-sim', ['api/drain_api.cpp']),
    ('decompose', ['api/decompose_api.cpp']),
    ('mold', ['api/mold_api.cpp']),
    ('studio', ['api/decomposition_api.cpp', 'api/mold_api.cpp']),
]


def includes(path):
    with open(os.path.join('src', path)) as text:
        return re.findall(r'^#include "([^"]+)"', text.read(), re.M)


def reach(start):
    seen, todo = set(), list(start)
    while todo:
        path = todo.pop()
        if path in seen or not os.path.exists(os.path.join('src', path)):
            continue
        seen.add(path)
        for header in includes(path):
            todo.append(header)
            todo.append(os.path.splitext(header)[0] + '.cpp')
    return seen


used = [(name, reach(start)) for name, start in PIPELINES]
print('| file | ' + ' | '.join(name for name, _ in PIPELINES) + ' |')
print('|---|' + '---|' * len(PIPELINES))
for folder in ('volume', 'surface'):
    for name in sorted(os.listdir(os.path.join('src', folder))):
        if not name.endswith('.cpp'):
            continue
        path = folder + '/' + name
        marks = ['●' if path in files else '' for _, files in used]
        print(f'| `{path[:-4]}` | ' + ' | '.join(marks) + ' |')
