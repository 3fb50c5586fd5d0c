#!/usr/bin/env bash
# The Python package's figures (docs/python.md#figures): how long
# `import marchstudio` takes (the extension and numpy loaded, no GL yet),
# and fogleman/sdf's README example saved at its default samples=2**22,
# wall time from a fresh interpreter (the GL context, compile, sampling,
# meshing, checking and the STL write included). Each is the median of RUNS.
#
#   tools/python-figures.sh [OUT_DIR] [RUNS]   # default: out/python-figures 3
#
# Writes its table into docs/python.md (the python-figures markers).
set -euo pipefail
root=$(cd "$(dirname "$0")/.." && pwd)
out=${1:-$root/out/python-figures}
runs=${2:-3}
mkdir -p "$out"
export PYTHONPATH=$root/build/python
/usr/bin/python3 - "$root" "$out" "$runs" <<'PY'
import datetime, json, os, platform, statistics, subprocess, sys
root, out, runs = sys.argv[1], sys.argv[2], int(sys.argv[3])
sys.path.insert(0, os.path.join(root, 'tools'))
from doc_markers import put

def child(code):
    r = subprocess.run([sys.executable, '-c', code], cwd=out, check=True, capture_output=True, text=True)
    return json.loads(r.stdout.strip().splitlines()[-1])

IMPORT = '''
import json, time
t = time.perf_counter()
import marchstudio
print(json.dumps({"s": time.perf_counter() - t}))
'''
README = '''
import json, time
t = time.perf_counter()
from marchstudio.sdf import *
import marchstudio
f = sphere(1) & box(1.5)
c = cylinder(0.5)
f -= c.orient(X) | c.orient(Y) | c.orient(Z)
report = f.save('out.stl', samples=2**22)
s = time.perf_counter() - t
gl = marchstudio.Scene(sphere()).bench(size=(8, 8), frames=1, warmup=0)
print(json.dumps({"s": s, "triangles": report["triangles"], "renderer": gl["machine"]["gl_renderer"]}))
'''
imports = [child(IMPORT)['s'] for _ in range(runs)]
readme = [child(README) for _ in range(runs)]
cpu = next((l.split(':', 1)[1].strip() for l in open('/proc/cpuinfo') if l.startswith('model name')), platform.machine())
rows = ['Measured %s on %s (%d cores, shared with other work), %s, Python %s, median of %d:' % (
            datetime.date.today(), cpu, os.cpu_count(), readme[0]['renderer'], platform.python_version(), runs),
        '',
        '| what | wall time |', '|---|---|',
        '| `import marchstudio` | %.0f ms |' % (1000 * statistics.median(imports)),
        "| fogleman's README example, `samples=2**22` (%s triangles) | %.1f s |" % (
            format(readme[0]['triangles'], ','), statistics.median(r['s'] for r in readme))]
print('\n'.join(rows))
put(os.path.join(root, 'docs', 'python.md'), 'python-figures', rows)
PY
