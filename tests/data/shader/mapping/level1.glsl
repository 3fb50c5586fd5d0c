// level1.glsl: includes a second level, then has more code
float level1_before = 1.0;
#include "deeper/level2.glsl"
#ifndef SKIP_L1_ERROR
float level1_after = undefined_MARK_L1;  // deliberate error
#endif
