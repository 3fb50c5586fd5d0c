// big.glsl: included inside an inactive #if group
float big_a = 1.0;
float big_b = 2.0;
float big_c = 3.0;
