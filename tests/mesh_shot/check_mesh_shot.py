#!/usr/bin/python3
"""tools/mesh-shot on a cube: the picture has the size asked, the cube in
the middle and the background in the corners; the same cube with vertex
normals (the exporter's nx ny nz) gives the same picture; a PLY it cannot
read is one line and exit 2."""
import struct
import subprocess
import sys
import tempfile
from pathlib import Path

from PIL import Image

BACKGROUND = round(0.92 * 255)  # mesh-shot's kBackground


def cube_ply(path, normals=False):
    v = [(x, y, z) for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
    # Counter-clockwise from outside; index = 4x + 2y + z.
    quads = [(0, 1, 3, 2), (4, 6, 7, 5), (0, 4, 5, 1), (2, 3, 7, 6), (0, 2, 6, 4), (1, 5, 7, 3)]
    tris = [t for a, b, c, d in quads for t in ((a, b, c), (a, c, d))]
    n = "property float nx\nproperty float ny\nproperty float nz\n" if normals else ""
    head = (f"ply\nformat binary_little_endian 1.0\nelement vertex {len(v)}\n"
            f"property float x\nproperty float y\nproperty float z\n{n}property ushort material\n"
            f"element face {len(tris)}\nproperty list uchar uint vertex_indices\nend_header\n")
    if normals:  # along the diagonals, as a smooth cube's would be
        body = b"".join(struct.pack("<ffffffH", *p, *(c * 1.1547 for c in p), i % 2) for i, p in enumerate(v))
    else:
        body = b"".join(struct.pack("<fffH", *p, i % 2) for i, p in enumerate(v))
    body += b"".join(struct.pack("<BIII", 3, *t) for t in tris)
    path.write_bytes(head.encode() + body)


def main():
    shot = sys.argv[1]
    with tempfile.TemporaryDirectory() as d:
        d = Path(d)
        cube_ply(d / "cube.ply")
        png = d / "cube.png"
        r = subprocess.run([shot, str(d / "cube.ply"), "-o", str(png), "--size", "96x64", "--eye", "1.6,1.3,-2.2",
                            "--target", "0,0,0", "--wire"], capture_output=True, text=True, timeout=120)
        assert r.returncode == 0, r.stderr
        im = Image.open(png).convert("RGB")
        assert im.size == (96, 64), im.size
        bg = (BACKGROUND,) * 3
        assert im.getpixel((0, 0)) == bg and im.getpixel((95, 63)) == bg, (im.getpixel((0, 0)), im.getpixel((95, 63)))
        centre = im.getpixel((48, 32))
        assert max(abs(c - BACKGROUND) for c in centre) > 20, centre
        cube_ply(d / "smooth.ply", normals=True)
        r = subprocess.run([shot, str(d / "smooth.ply"), "-o", str(d / "smooth.png"), "--size", "96x64", "--eye",
                            "1.6,1.3,-2.2", "--target", "0,0,0", "--wire"], capture_output=True, text=True, timeout=120)
        assert r.returncode == 0, r.stderr
        assert Image.open(d / "smooth.png").convert("RGB").tobytes() == im.tobytes(), "normals changed the picture"
        (d / "ascii.ply").write_text("ply\nformat ascii 1.0\nelement vertex 0\nend_header\n")
        r = subprocess.run([shot, str(d / "ascii.ply"), "-o", str(png), "--eye", "0,0,-3", "--target", "0,0,0"],
                           capture_output=True, text=True, timeout=60)
        assert r.returncode == 2 and r.stderr.count("\n") == 1, (r.returncode, r.stderr)
    print("mesh-shot: ok")


if __name__ == "__main__":
    main()
