// graph_buffers.glsl: the scene graph interpreter's buffers
// (docs/scene-graph.md, "Two ways to evaluate"), bound by
// render/graph_field.h: per node (fn, float offset, material or a
// modifier's unit length, Lipschitz bound's bits), the floats, the program
// with the cells' lists after it, and the cell grid with its head. The
// pruning pass (MS_GRAPH_PRUNING) writes the lists and the coarse cells.
#pragma once

layout(std430, binding = 3) readonly buffer MsGraphNodes { uvec4 msGraphNode[]; };
layout(std430, binding = 4) readonly buffer MsGraphFloats { float msGraphF[]; };
#ifdef MS_GRAPH_PRUNING
layout(std430, binding = 5) buffer MsGraphProgram { uint msGraphProg[]; };
layout(std430, binding = 6) buffer MsGraphCells { uvec4 msGraphCell[]; };
// The coarse cells, after the count of the fine lists' pool taken so far.
layout(std430, binding = 7) buffer MsGraphCoarse { uint msPoolUsed; uint msPad[3]; uvec4 msGraphCoarse[]; };
#else
layout(std430, binding = 5) readonly buffer MsGraphProgram { uint msGraphProg[]; };
layout(std430, binding = 6) readonly buffer MsGraphCells { uvec4 msGraphCell[]; };
#endif
