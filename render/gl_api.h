// OpenGL and OSMesa as a table of functions, loaded from libOSMesa.so.8 the
// first time a picture is rendered. Linked normally, Mesa and the LLVM it
// pulls in were loaded and initialised at every start of the program, about
// 28 ms, also by the commands that never render (`afford run`, `check`).
// The declarations come from the headers; only the addresses are looked up.
#pragma once

#include <GL/osmesa.h>

namespace afford::render {

struct GlApi {
  // OpenGL 1.x, the fixed-function calls the scene uses (glEnable -> Enable).
  decltype(&::glBegin) Begin;
  decltype(&::glClear) Clear;
  decltype(&::glClearColor) ClearColor;
  decltype(&::glColor4d) Color4d;
  decltype(&::glColor4f) Color4f;
  decltype(&::glColorMaterial) ColorMaterial;
  decltype(&::glCullFace) CullFace;
  decltype(&::glDepthFunc) DepthFunc;
  decltype(&::glDepthMask) DepthMask;
  decltype(&::glDepthRange) DepthRange;
  decltype(&::glDisable) Disable;
  decltype(&::glDisableClientState) DisableClientState;
  decltype(&::glDrawArrays) DrawArrays;
  decltype(&::glEnable) Enable;
  decltype(&::glEnableClientState) EnableClientState;
  decltype(&::glEnd) End;
  decltype(&::glFinish) Finish;
  decltype(&::glLightModelfv) LightModelfv;
  decltype(&::glLightModeli) LightModeli;
  decltype(&::glLightfv) Lightfv;
  decltype(&::glLineWidth) LineWidth;
  decltype(&::glLoadIdentity) LoadIdentity;
  decltype(&::glLoadMatrixf) LoadMatrixf;
  decltype(&::glMaterialf) Materialf;
  decltype(&::glMaterialfv) Materialfv;
  decltype(&::glMatrixMode) MatrixMode;
  decltype(&::glMultMatrixf) MultMatrixf;
  decltype(&::glNormalPointer) NormalPointer;
  decltype(&::glPopMatrix) PopMatrix;
  decltype(&::glPushMatrix) PushMatrix;
  decltype(&::glScaled) Scaled;
  decltype(&::glShadeModel) ShadeModel;
  decltype(&::glTranslated) Translated;
  decltype(&::glVertex3d) Vertex3d;
  decltype(&::glVertexPointer) VertexPointer;
  decltype(&::glViewport) Viewport;
  // OpenGL 1.4 (glext.h declares its type, not the function).
  PFNGLBLENDFUNCSEPARATEPROC BlendFuncSeparate;
  // OSMesa (OSMesaCreateContextExt -> CreateContextExt).
  decltype(&::OSMesaCreateContextExt) CreateContextExt;
  decltype(&::OSMesaDestroyContext) DestroyContext;
  decltype(&::OSMesaGetCurrentContext) GetCurrentContext;
  decltype(&::OSMesaMakeCurrent) MakeCurrent;
};

// The table, loaded on first use; throws RenderError naming the library and
// the missing function when it cannot be loaded.
const GlApi& gl();

}  // namespace afford::render
