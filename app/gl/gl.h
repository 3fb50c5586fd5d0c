// The one GL header for the project: glad2's GL 4.5 core loader. Entry points
// are loaded per context through that context's own GetProcAddress
// (gl/context.h), never by linking libGL/libOpenGL.
#pragma once
#include <glad/gl.h>
