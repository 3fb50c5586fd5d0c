#!/usr/bin/env python3
"""The expected values of tests/unit/test_flip.cpp, from NVIDIA's own FLIP
implementation (PyPI package flip-evaluator 1.7), on the same synthetic image
pairs the test builds. Used only to check our implementation (io/flip.cpp,
written from the paper); nothing of it is in marchstudio. Run it in a
virtual environment:
  python3 -m venv /tmp/flipvenv && /tmp/flipvenv/bin/pip install flip-evaluator==1.7 numpy
  /tmp/flipvenv/bin/python tools/flip-reference.py
"""
import flip_evaluator
import numpy as np

W, H = 48, 32


def q(v):
    """8-bit levels, as the test builds them."""
    return np.round(np.clip(v, 0, 1) * 255.0) / 255.0


def gradient():
    img = np.zeros((H, W, 3), np.float32)
    for y in range(H):
        for x in range(W):
            img[y, x] = (q(x / (W - 1)), q(y / (H - 1)), q(0.5))
    return img


def with_block(img):
    out = img.copy()
    out[10:16, 20:26] = (q(1.0), q(0.2), q(0.1))
    return out


def checker(shift):
    img = np.zeros((H, W, 3), np.float32)
    for y in range(H):
        for x in range(W):
            v = q(0.9) if ((x + shift) // 4 + y // 4) % 2 == 0 else q(0.1)
            img[y, x] = (v, v, v)
    return img


for name, a, b in [('gradient_block', gradient(), with_block(gradient())),
                   ('checker_shift', checker(0), checker(1)),
                   ('gradient_checker', gradient(), checker(0))]:
    m, mean, _ = flip_evaluator.evaluate(a, b, 'LDR', applyMagma=False)
    print(f'{name}: mean {mean:.9g}, max {float(m.max()):.9g}, pixel (22, 12) {float(np.squeeze(m)[12, 22]):.9g}, '
          f'pixel (0, 0) {float(np.squeeze(m)[0, 0]):.9g}')
