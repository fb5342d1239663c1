#include "gl_api.h"

#include <dlfcn.h>

#include <string>

#include "scene.h"

namespace afford::render {
namespace {

constexpr const char* kLibrary = "libOSMesa.so.8";  // Debian's libosmesa6

template <typename F>
F find(void* lib, const char* name) {
  void* f = dlsym(lib, name);
  if (f == nullptr) throw RenderError(std::string(kLibrary) + " has no function " + name);
  return reinterpret_cast<F>(f);
}

GlApi load() {
  // Never closed: the contexts and the JIT code live until the program ends.
  void* lib = dlopen(kLibrary, RTLD_NOW | RTLD_LOCAL);
  if (lib == nullptr) {
    const char* why = dlerror();
    throw RenderError(std::string("cannot load ") + kLibrary + " for rendering (Debian package libosmesa6): " +
                      (why != nullptr ? why : "unknown reason"));
  }
  GlApi api{};
  api.Begin = find<decltype(api.Begin)>(lib, "glBegin");
  api.BlendFuncSeparate = find<decltype(api.BlendFuncSeparate)>(lib, "glBlendFuncSeparate");
  api.Clear = find<decltype(api.Clear)>(lib, "glClear");
  api.ClearColor = find<decltype(api.ClearColor)>(lib, "glClearColor");
  api.Color4d = find<decltype(api.Color4d)>(lib, "glColor4d");
  api.Color4f = find<decltype(api.Color4f)>(lib, "glColor4f");
  api.ColorMaterial = find<decltype(api.ColorMaterial)>(lib, "glColorMaterial");
  api.CullFace = find<decltype(api.CullFace)>(lib, "glCullFace");
  api.DepthFunc = find<decltype(api.DepthFunc)>(lib, "glDepthFunc");
  api.DepthMask = find<decltype(api.DepthMask)>(lib, "glDepthMask");
  api.DepthRange = find<decltype(api.DepthRange)>(lib, "glDepthRange");
  api.Disable = find<decltype(api.Disable)>(lib, "glDisable");
  api.DisableClientState = find<decltype(api.DisableClientState)>(lib, "glDisableClientState");
  api.DrawArrays = find<decltype(api.DrawArrays)>(lib, "glDrawArrays");
  api.Enable = find<decltype(api.Enable)>(lib, "glEnable");
  api.EnableClientState = find<decltype(api.EnableClientState)>(lib, "glEnableClientState");
  api.End = find<decltype(api.End)>(lib, "glEnd");
  api.Finish = find<decltype(api.Finish)>(lib, "glFinish");
  api.LightModelfv = find<decltype(api.LightModelfv)>(lib, "glLightModelfv");
  api.LightModeli = find<decltype(api.LightModeli)>(lib, "glLightModeli");
  api.Lightfv = find<decltype(api.Lightfv)>(lib, "glLightfv");
  api.LineWidth = find<decltype(api.LineWidth)>(lib, "glLineWidth");
  api.LoadIdentity = find<decltype(api.LoadIdentity)>(lib, "glLoadIdentity");
  api.LoadMatrixf = find<decltype(api.LoadMatrixf)>(lib, "glLoadMatrixf");
  api.Materialf = find<decltype(api.Materialf)>(lib, "glMaterialf");
  api.Materialfv = find<decltype(api.Materialfv)>(lib, "glMaterialfv");
  api.MatrixMode = find<decltype(api.MatrixMode)>(lib, "glMatrixMode");
  api.MultMatrixf = find<decltype(api.MultMatrixf)>(lib, "glMultMatrixf");
  api.NormalPointer = find<decltype(api.NormalPointer)>(lib, "glNormalPointer");
  api.PopMatrix = find<decltype(api.PopMatrix)>(lib, "glPopMatrix");
  api.PushMatrix = find<decltype(api.PushMatrix)>(lib, "glPushMatrix");
  api.Scaled = find<decltype(api.Scaled)>(lib, "glScaled");
  api.ShadeModel = find<decltype(api.ShadeModel)>(lib, "glShadeModel");
  api.Translated = find<decltype(api.Translated)>(lib, "glTranslated");
  api.Vertex3d = find<decltype(api.Vertex3d)>(lib, "glVertex3d");
  api.VertexPointer = find<decltype(api.VertexPointer)>(lib, "glVertexPointer");
  api.Viewport = find<decltype(api.Viewport)>(lib, "glViewport");
  api.CreateContextExt = find<decltype(api.CreateContextExt)>(lib, "OSMesaCreateContextExt");
  api.DestroyContext = find<decltype(api.DestroyContext)>(lib, "OSMesaDestroyContext");
  api.GetCurrentContext = find<decltype(api.GetCurrentContext)>(lib, "OSMesaGetCurrentContext");
  api.MakeCurrent = find<decltype(api.MakeCurrent)>(lib, "OSMesaMakeCurrent");
  return api;
}

}  // namespace

const GlApi& gl() {
  static const GlApi api = load();
  return api;
}

}  // namespace afford::render
