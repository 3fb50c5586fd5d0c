// c.glsl: level 3
float c_value() { return 3.0; }