// level2.glsl: second-level include
/* a block comment
   spanning lines */
float level2_ok = 2.0;
#ifndef SKIP_L2_ERROR
float level2_bad = undefined_MARK_L2;  // deliberate error
#endif
