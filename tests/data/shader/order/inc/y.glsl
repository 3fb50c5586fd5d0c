// y next to only.glsl in include dir 1
