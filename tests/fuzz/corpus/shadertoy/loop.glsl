void mainImage(out vec4 c, in vec2 f) { for(;;){} }
// */ /* 
