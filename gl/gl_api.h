// The OpenGL and OSMesa functions vigil calls, loaded from the OSMesa library when the first context is made
// (GlContext), instead of linked. OSMesa brings LLVM along: 48 MB of a process's memory and 40 % of its start
// (docs/results/2026-12-estimator-speed.md, "Process start"), which a run that draws nothing (no figure, no
// camera image) no longer pays.
//
// Code that draws includes this header instead of <GL/gl.h>. After it, each function of the list below is a
// macro that calls through the loaded table, as the usual GL loaders do, so the drawing code reads as plain
// OpenGL. A function missing from the list is still declared by <GL/gl.h> but defined nowhere: the build
// fails to link until it is added here.
#pragma once

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

// X(name) for every function vigil calls.
#define VIGIL_GL_FUNCTIONS(X)         \
  X(OSMesaCreateContextAttribs)       \
  X(OSMesaDestroyContext)             \
  X(OSMesaMakeCurrent)                \
  X(glBegin)                          \
  X(glBindFramebuffer)                \
  X(glBindRenderbuffer)               \
  X(glBindTexture)                    \
  X(glBlendFunc)                      \
  X(glBlitFramebuffer)                \
  X(glCallList)                       \
  X(glCheckFramebufferStatus)         \
  X(glClear)                          \
  X(glClearColor)                     \
  X(glClearDepth)                     \
  X(glColor3f)                        \
  X(glColor4f)                        \
  X(glDeleteFramebuffers)             \
  X(glDeleteRenderbuffers)            \
  X(glDepthFunc)                      \
  X(glDisable)                        \
  X(glEnable)                         \
  X(glEnd)                            \
  X(glEndList)                        \
  X(glFinish)                         \
  X(glFramebufferRenderbuffer)        \
  X(glGenFramebuffers)                \
  X(glGenLists)                       \
  X(glGenRenderbuffers)               \
  X(glGenTextures)                    \
  X(glGenerateMipmap)                 \
  X(glGetIntegerv)                    \
  X(glLineWidth)                      \
  X(glLoadIdentity)                   \
  X(glLoadMatrixd)                    \
  X(glMatrixMode)                     \
  X(glNewList)                        \
  X(glOrtho)                          \
  X(glPixelStorei)                    \
  X(glPointSize)                      \
  X(glReadPixels)                     \
  X(glRenderbufferStorageMultisample) \
  X(glScissor)                        \
  X(glTexCoord2d)                     \
  X(glTexEnvi)                        \
  X(glTexImage2D)                     \
  X(glTexParameteri)                  \
  X(glVertex2d)                       \
  X(glVertex3d)                       \
  X(glViewport)

namespace vigil::gl {

struct Api {
#define VIGIL_GL_MEMBER(name) decltype(&::name) name = nullptr;
  VIGIL_GL_FUNCTIONS(VIGIL_GL_MEMBER)
#undef VIGIL_GL_MEMBER
};

// The table, loaded on the first call (from any thread, once); std::runtime_error naming the library, or the
// function it lacks, when it cannot be loaded (a later call tries again).
const Api& Functions();

// The library the table is loaded from (its soname, found by the build).
const char* OsMesaLibrary();

}  // namespace vigil::gl

#ifndef VIGIL_GL_API_NO_REDIRECT
#define OSMesaCreateContextAttribs ::vigil::gl::Functions().OSMesaCreateContextAttribs
#define OSMesaDestroyContext ::vigil::gl::Functions().OSMesaDestroyContext
#define OSMesaMakeCurrent ::vigil::gl::Functions().OSMesaMakeCurrent
#define glBegin ::vigil::gl::Functions().glBegin
#define glBindFramebuffer ::vigil::gl::Functions().glBindFramebuffer
#define glBindRenderbuffer ::vigil::gl::Functions().glBindRenderbuffer
#define glBindTexture ::vigil::gl::Functions().glBindTexture
#define glBlendFunc ::vigil::gl::Functions().glBlendFunc
#define glBlitFramebuffer ::vigil::gl::Functions().glBlitFramebuffer
#define glCallList ::vigil::gl::Functions().glCallList
#define glCheckFramebufferStatus ::vigil::gl::Functions().glCheckFramebufferStatus
#define glClear ::vigil::gl::Functions().glClear
#define glClearColor ::vigil::gl::Functions().glClearColor
#define glClearDepth ::vigil::gl::Functions().glClearDepth
#define glColor3f ::vigil::gl::Functions().glColor3f
#define glColor4f ::vigil::gl::Functions().glColor4f
#define glDeleteFramebuffers ::vigil::gl::Functions().glDeleteFramebuffers
#define glDeleteRenderbuffers ::vigil::gl::Functions().glDeleteRenderbuffers
#define glDepthFunc ::vigil::gl::Functions().glDepthFunc
#define glDisable ::vigil::gl::Functions().glDisable
#define glEnable ::vigil::gl::Functions().glEnable
#define glEnd ::vigil::gl::Functions().glEnd
#define glEndList ::vigil::gl::Functions().glEndList
#define glFinish ::vigil::gl::Functions().glFinish
#define glFramebufferRenderbuffer ::vigil::gl::Functions().glFramebufferRenderbuffer
#define glGenFramebuffers ::vigil::gl::Functions().glGenFramebuffers
#define glGenLists ::vigil::gl::Functions().glGenLists
#define glGenRenderbuffers ::vigil::gl::Functions().glGenRenderbuffers
#define glGenTextures ::vigil::gl::Functions().glGenTextures
#define glGenerateMipmap ::vigil::gl::Functions().glGenerateMipmap
#define glGetIntegerv ::vigil::gl::Functions().glGetIntegerv
#define glLineWidth ::vigil::gl::Functions().glLineWidth
#define glLoadIdentity ::vigil::gl::Functions().glLoadIdentity
#define glLoadMatrixd ::vigil::gl::Functions().glLoadMatrixd
#define glMatrixMode ::vigil::gl::Functions().glMatrixMode
#define glNewList ::vigil::gl::Functions().glNewList
#define glOrtho ::vigil::gl::Functions().glOrtho
#define glPixelStorei ::vigil::gl::Functions().glPixelStorei
#define glPointSize ::vigil::gl::Functions().glPointSize
#define glReadPixels ::vigil::gl::Functions().glReadPixels
#define glRenderbufferStorageMultisample ::vigil::gl::Functions().glRenderbufferStorageMultisample
#define glScissor ::vigil::gl::Functions().glScissor
#define glTexCoord2d ::vigil::gl::Functions().glTexCoord2d
#define glTexEnvi ::vigil::gl::Functions().glTexEnvi
#define glTexImage2D ::vigil::gl::Functions().glTexImage2D
#define glTexParameteri ::vigil::gl::Functions().glTexParameteri
#define glVertex2d ::vigil::gl::Functions().glVertex2d
#define glVertex3d ::vigil::gl::Functions().glVertex3d
#define glViewport ::vigil::gl::Functions().glViewport
#endif
