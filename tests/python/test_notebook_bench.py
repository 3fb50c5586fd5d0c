"""A scene's notebook picture (_repr_png_), bench figures and level set,
held to the command line's: the same PNG decoder, the same bench JSON
document and the same deterministic counts, the same .vdb bytes."""
import json
import os
import struct
import subprocess
import zlib

import numpy as np
import pytest

import marchstudio
from marchstudio.sdf import circle, sphere, torus

PNG_SIGNATURE = b'\x89PNG\r\n\x1a\n'


def png_size(data):
    """(width, height) from the IHDR chunk, after checking every chunk's CRC
    and that the IDAT stream inflates to the rows the header promises."""
    assert data[:8] == PNG_SIGNATURE
    pos, idat, size, bpp = 8, b'', None, None
    while pos < len(data):
        n, kind = struct.unpack('>I4s', data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        assert struct.unpack('>I', data[pos + 8 + n:pos + 12 + n])[0] == zlib.crc32(kind + body)
        if kind == b'IHDR':
            w, h, depth, colour = struct.unpack('>IIBB', body[:10])
            size, bpp = (w, h), {2: 3, 6: 4, 0: 1, 4: 2}[colour] * depth // 8
        elif kind == b'IDAT':
            idat += body
        pos += 12 + n
    w, h = size
    assert len(zlib.decompress(idat)) == h * (1 + w * bpp)
    return size


def test_repr_png_is_the_renders_png(tmp_path):
    shape = sphere(1) | torus(1.2, 0.1)
    data = shape._repr_png_()
    assert png_size(data) == marchstudio.Scene.PREVIEW_SIZE == (320, 180)
    (tmp_path / 'p.png').write_bytes(data)
    got = marchstudio.read_image(str(tmp_path / 'p.png'))
    want = marchstudio.Scene(shape).render(size=(320, 180), dtype=np.uint8)
    assert np.array_equal(np.round(got * 255).astype(np.uint8), want[..., :got.shape[2]])
    assert want[..., :3].std() > 0
    assert circle(1)._repr_png_() is None  # a 2D shape: no picture, Jupyter shows its repr


def keys(doc):
    """The document's shape: keys and the kinds of their values, recursively."""
    if isinstance(doc, dict):
        return {k: keys(v) for k, v in doc.items()}
    if isinstance(doc, list):
        return [keys(v) for v in doc[:1]]
    return 'number' if isinstance(doc, (int, float)) and not isinstance(doc, bool) else type(doc).__name__


def test_bench_is_the_clis_document(cli, root):
    scene = os.path.join(root, 'scenes', 'part.json')
    r = subprocess.run([cli, 'bench', scene, '--json', '--size', '48x27', '--frames', '2', '--warmup', '0'],
                       check=True, capture_output=True, text=True)
    want = json.loads(r.stdout)
    got = marchstudio.load(scene).bench(size=(48, 27), frames=2, warmup=0)
    assert keys(got) == keys(want)
    assert got['schema'] == want['schema'] == 'marchstudio.bench/1'
    # the counting pass is deterministic: the same steps and map() calls per pixel
    assert got['cost'] == want['cost'] and got['cost']
    with pytest.raises(ValueError):
        marchstudio.load(scene).bench(frames=0)


def test_level_set_writes_the_clis_vdb(cli, tmp_path):
    shape = sphere(1)
    scene = marchstudio.Scene(shape)
    report = scene.level_set(tmp_path / 'py.vdb', resolution=24, band=2)
    subprocess.run([cli, 'mesh', scene.path, '-o', str(tmp_path / 'cli.vdb'), '--resolution', '24', '--band', '2'],
                   check=True, capture_output=True)
    assert report['band_voxels'] > 0
    # the same file but for the 36-character UUID OpenVDB draws for each
    # (after the magic number, file and library versions and a flag: 21 bytes)
    py, cli_vdb = (tmp_path / 'py.vdb').read_bytes(), (tmp_path / 'cli.vdb').read_bytes()
    assert len(py) == len(cli_vdb) and py[:21] == cli_vdb[:21] and py[57:] == cli_vdb[57:]
    wider = scene.level_set(tmp_path / 'wide.vdb', resolution=24, band=4)
    assert wider['band_voxels'] > report['band_voxels']
    with pytest.raises(ValueError):
        scene.level_set(tmp_path / 'x.stl')
    with pytest.raises(ValueError):
        scene.level_set(None)
    assert sorted(os.listdir(tmp_path)) == ['cli.vdb', 'py.vdb', 'wide.vdb']
