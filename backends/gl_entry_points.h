// The OSMesa and OpenGL entry points the GL backend calls, loaded from libOSMesa when the
// first GlBackend is made instead of linked into the program.
//
// Why: linking libOSMesa makes every process of the program map and relocate Mesa and the
// LLVM it compiles shaders with, about 42 MiB of resident memory (libLLVM-15 alone) and
// their start-up time, even when it only renders with this pipeline. Loaded on demand, a
// run that never makes a GL backend never touches them (docs/notes/2026-12-01-peak-memory.md).
//
// How: each entry point is a function pointer in namespace scenes, named exactly as the
// GL/osmesa.h function it stands for and of that function's type. Inside namespace scenes
// an unqualified call such as glClear(GL_COLOR_BUFFER_BIT) finds the pointer before the
// global prototype, so gl_backend.cpp reads as the plain GL the tutorial writes. The
// prototypes are only named in decltype, never called, so nothing links against them.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

namespace scenes {

// X(name) for every entry point the GL backend calls; a new call needs its line here.
#define RASTER_GL_ENTRY_POINTS(X)                                                                       \
  X(OSMesaCreateContextAttribs) X(OSMesaDestroyContext) X(OSMesaMakeCurrent) X(glActiveTexture)         \
  X(glAttachShader) X(glBindBuffer) X(glBindFramebuffer) X(glBindTexture) X(glBindVertexArray)          \
  X(glBlendFunc) X(glBufferData) X(glCheckFramebufferStatus) X(glClear) X(glClearColor) X(glClearDepth) \
  X(glCompileShader) X(glCreateProgram) X(glCreateShader) X(glCullFace) X(glDeleteFramebuffers)         \
  X(glDeleteProgram) X(glDeleteShader) X(glDepthFunc) X(glDepthMask) X(glDisable) X(glDrawBuffer)       \
  X(glDrawBuffers) X(glDrawElements) X(glDrawElementsInstanced) X(glEnable)                             \
  X(glEnableVertexAttribArray) X(glFinish) X(glFramebufferTexture2D) X(glFrontFace) X(glGenBuffers)     \
  X(glGenFramebuffers) X(glGenTextures) X(glGenVertexArrays) X(glGetActiveUniform) X(glGetError)        \
  X(glGetIntegerv)                                                                                      \
  X(glGetProgramInfoLog) X(glGetProgramiv) X(glGetShaderInfoLog) X(glGetShaderiv) X(glGetString)        \
  X(glGetUniformLocation) X(glLinkProgram) X(glPolygonOffset) X(glReadBuffer) X(glReadPixels)           \
  X(glShaderSource) X(glTexImage2D) X(glTexParameteri) X(glUniform1f) X(glUniform1i) X(glUniform2fv)    \
  X(glUniform3fv) X(glUniform4fv) X(glUniformMatrix4fv) X(glUseProgram) X(glVertexAttribDivisor)        \
  X(glVertexAttribPointer) X(glViewport)

#define RASTER_GL_DECLARE_ENTRY_POINT(name) extern decltype(&::name) name;
RASTER_GL_ENTRY_POINTS(RASTER_GL_DECLARE_ENTRY_POINT)
#undef RASTER_GL_DECLARE_ENTRY_POINT

// Loads libOSMesa (its Debian soname, libOSMesa.so.8, else libOSMesa.so) and every entry
// point above, once a process; later calls return at once. Where it cannot, throws
// std::runtime_error naming the library, what is missing and the Debian package that has
// it, as a GL context that cannot be made does.
void loadGlEntryPoints();

}  // namespace scenes
