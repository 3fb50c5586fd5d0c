"""Ctrl-C and threads: a mesh interrupted by SIGINT raises KeyboardInterrupt
with no file left, and two threads drawing at once both get the picture
(the extension's one lock serializes them on the one GL context)."""
import os
import signal
import subprocess
import sys
import textwrap
import threading
import time

import numpy as np

import marchstudio
from marchstudio.sdf import box, sphere

SCRIPT = textwrap.dedent('''
    import sys
    import marchstudio
    from marchstudio.sdf import sphere, box
    scene = marchstudio.Scene(sphere(1) - box(1.6))
    print('meshing', flush=True)
    try:
        scene.save_mesh(sys.argv[1], resolution=900)
    except KeyboardInterrupt:
        print('KeyboardInterrupt', flush=True)
        sys.exit(3)
    print('finished', flush=True)
''')


def test_ctrl_c_interrupts_a_mesh_and_leaves_no_file(tmp_path):
    out = tmp_path / 'out' / 'big.stl'
    out.parent.mkdir()
    env = dict(os.environ, PYTHONPATH=os.path.dirname(os.path.dirname(marchstudio.__file__)))
    p = subprocess.Popen([sys.executable, '-c', SCRIPT, str(out)], env=env, stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True,
                         preexec_fn=lambda: signal.signal(signal.SIGINT, signal.SIG_DFL))  # a background shell ignores it
    assert p.stdout.readline().strip() == 'meshing'
    time.sleep(1.0)  # into the job: the whole mesh takes about 20 s on llvmpipe
    p.send_signal(signal.SIGINT)
    stdout, stderr = p.communicate(timeout=120)
    assert p.returncode == 3 and stdout.strip() == 'KeyboardInterrupt', stderr
    # neither the mesh nor a temporary: the job stopped at a stage before
    # its write (a KeyboardInterrupt only after it returned finds the file)
    assert os.listdir(out.parent) == []


def test_two_threads_render_at_once():
    scene = marchstudio.Scene(sphere(1) & box(1.5))
    want = scene.render(size=(64, 36), dtype=np.uint8)
    got, errors = [None, None], []

    def draw(i):
        try:
            got[i] = scene.render(size=(64, 36), dtype=np.uint8)
        except Exception as e:  # noqa: BLE001 - the test reports any failure
            errors.append(e)

    threads = [threading.Thread(target=draw, args=(i,)) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    assert not errors and all(np.array_equal(g, want) for g in got)
    m = [None, None]
    threads = [threading.Thread(target=lambda i=i: m.__setitem__(i, scene.mesh(resolution=24))) for i in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join(timeout=120)
    assert all(x is not None and np.array_equal(x.faces, m[0].faces) for x in m)
