"""The native API against the command line: the same scene file renders to
the same pixels and meshes to the same vertices as `marchstudio render` and
`marchstudio mesh` (the CLI run here, in the test, as a user would); errors
are marchstudio.Error carrying the CLI's one line."""
import os
import subprocess

import numpy as np
import pytest

import marchstudio
from marchstudio.sdf import X, Y, Z, box, capped_cylinder, cylinder, sphere, torus

W, H = 64, 40


def readme_shape():
    f = sphere(1) & box(1.5)
    c = cylinder(0.5)
    f -= c.orient(X) | c.orient(Y) | c.orient(Z)
    return f


@pytest.fixture(scope='module')
def part(tmp_path_factory):
    path = tmp_path_factory.mktemp('scene') / 'part.json'
    (readme_shape() | torus(1, 0.1).translate((0, 0, -0.9))).to_json(path)
    return str(path)


def read_obj(path):
    v, f = [], []
    for line in open(path):
        w = line.split()
        if w and w[0] == 'v':
            v.append([float(x) for x in w[1:4]])
        elif w and w[0] == 'f':
            f.append([int(x.split('/')[0]) - 1 for x in w[1:4]])
    return np.array(v, np.float32), np.array(f, np.uint32)


@pytest.mark.parametrize('dtype, ext', [(np.uint8, 'png'), (np.float32, 'exr')])
def test_render_equals_the_cli_bit_for_bit(part, cli, tmp_path, dtype, ext):
    out = tmp_path / f'cli.{ext}'
    subprocess.run([cli, 'render', part, '--size', f'{W}x{H}', '-o', str(out)], check=True)
    want = marchstudio.read_image(str(out))
    got = marchstudio.load(part).render(size=(W, H), dtype=dtype)
    assert got.shape == (H, W, 4) and got.dtype == dtype
    if dtype == np.uint8:
        want = np.round(want * 255).astype(np.uint8)
    nc = want.shape[2]
    assert np.array_equal(got[..., :nc], want)
    assert got[..., :3].std() > 0  # a picture, not a blank
    if nc == 3:
        assert np.all(got[..., 3] == (255 if dtype == np.uint8 else 1.0))


def test_render_writes_no_file(part, tmp_path, monkeypatch):
    # The image comes back in memory: with no usable temporary folder (a
    # file stands where it should be) a render still works, and the working
    # folder stays empty.
    not_a_dir = tmp_path / 'not-a-dir'
    not_a_dir.write_text('')
    monkeypatch.setenv('TMPDIR', str(not_a_dir))
    work = tmp_path / 'work'
    work.mkdir()
    monkeypatch.chdir(work)
    assert marchstudio.load(part).render(size=(W, H)).shape == (H, W, 4)
    assert marchstudio.load(part).render(size=(W, H), dtype=np.uint8).shape == (H, W, 4)
    assert list(work.iterdir()) == []


def test_mesh_equals_the_cli(part, cli, tmp_path):
    out = tmp_path / 'cli.obj'
    subprocess.run([cli, 'mesh', part, '--resolution', '40', '-o', str(out)], check=True, capture_output=True)
    v, f = read_obj(out)
    m = marchstudio.load(part).mesh(resolution=40)
    assert m.vertices.dtype == np.float32 and m.faces.dtype == np.uint32
    assert m.faces.shape == f.shape and np.array_equal(m.faces, f)
    assert m.vertices.shape == v.shape and np.allclose(m.vertices, v, rtol=0, atol=2e-6)
    assert m.watertight and m.report['triangles'] == len(f)


def test_readme_example_saves_a_watertight_mesh(tmp_path):
    f = readme_shape()
    report = f.save(str(tmp_path / 'out.stl'), samples=2**15)
    assert (tmp_path / 'out.stl').stat().st_size > 84
    c = report['check']
    assert c['boundary_edges'] == 0 and c['nonmanifold_edges'] == 0 and c['flipped_edges'] == 0
    # samples is fogleman's total cell count over the box: cells of volume box / 2**15
    # (the mesher pads the grid by a few cells round the box: mesh/sparse_field.h)
    lo, hi = marchstudio.Scene(f).box()
    assert abs(report['voxel'] - (np.prod(np.subtract(hi, lo)) / 2**15) ** (1 / 3)) < 1e-9


def test_generate_gives_three_corners_a_triangle():
    p = sphere(1).generate(samples=2**12)
    assert p.ndim == 2 and p.shape[1] == 3 and len(p) % 3 == 0 and len(p) > 0
    r = np.linalg.norm(p, axis=1)
    assert np.all(np.abs(r - 1) < 0.05)


def test_errors_carry_the_clis_line_and_pointer(tmp_path):
    bad = tmp_path / 'bad.json'
    bad.write_text('{"root": {"sdf": "sdShpere", "r": 1}}\n')
    with pytest.raises(marchstudio.Error, match=r"bad\.json:1: /root/sdf: unknown primitive 'sdShpere'"):
        marchstudio.load(bad).render(size=(8, 8))
    with pytest.raises(marchstudio.Error, match='unbounded'):
        marchstudio.Scene(cylinder(1)).mesh(resolution=8)
    with pytest.raises(marchstudio.Error, match='no-such-file'):
        marchstudio.load(tmp_path / 'no-such-file.json').mesh(resolution=8)
    # and the interpreter goes on
    assert marchstudio.Scene(sphere()).box() is not None


def test_bad_arguments_are_value_errors(part):
    s = marchstudio.load(part)
    with pytest.raises(ValueError):
        s.render(size=(0, 10))
    with pytest.raises(ValueError):
        s.render(dtype=np.int16)
    with pytest.raises(ValueError):
        s.mesh(resolution=8, voxel=0.1)
    with pytest.raises(ValueError):
        s.mesh(bounds=((1, 1, 1), (0, 0, 0)))


def test_save_writes_every_mesh_format(tmp_path):
    f = capped_cylinder(-Z, Z, 0.5)
    for ext in ('stl', 'obj', 'ply', 'glb', 'vdb'):
        f.save(str(tmp_path / f'rod.{ext}'), samples=2**12)
        assert (tmp_path / f'rod.{ext}').stat().st_size > 0
    assert sorted(os.listdir(tmp_path)) == sorted(['rod.stl', 'rod.obj', 'rod.mtl', 'rod.ply', 'rod.glb', 'rod.vdb'])
