// b.glsl: level 2, includes c.glsl from its own directory
#  include   "c.glsl"   // spaces around the directive are fine
float b_value() { return c_value() * 2.0; }
