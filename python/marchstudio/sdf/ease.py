"""fogleman/sdf's easing functions (t in [0, 1] -> [0, 1]), for code that
names them; the graph has no node that takes one (bend_linear,
transition_*, extrude_to are refused)."""
import math


def linear(t):
    return t


def in_quad(t):
    return t * t


def out_quad(t):
    return -t * (t - 2)


def in_out_quad(t):
    return 2 * t * t if t < 0.5 else -2 * t * t + 4 * t - 1


def in_cubic(t):
    return t * t * t


def out_cubic(t):
    return (t - 1) ** 3 + 1


def smoothstep(t):
    return t * t * (3 - 2 * t)


def in_sine(t):
    return 1 - math.cos(t * math.pi / 2)


def out_sine(t):
    return math.sin(t * math.pi / 2)


def in_out_sine(t):
    return -0.5 * (math.cos(math.pi * t) - 1)
