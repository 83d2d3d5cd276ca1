// The OpenGL headers: desktop OpenGL 3.3 core, or OpenGL ES 3.0 (WebGL2) in the web page, where
// the build defines S4D_GLES (cmake/Web.cmake). The code is the same; what ES lacks
// (glPolygonMode, GL_MULTISAMPLE as a switch) is drawn another way where it is used.
#pragma once
#ifdef S4D_GLES
#include <GLES3/gl3.h>
inline void glClearDepth(double depth) { glClearDepthf(static_cast<float>(depth)); }  // ES has only the float one
#else
#include <GL/gl.h>
#include <GL/glext.h>
#endif
