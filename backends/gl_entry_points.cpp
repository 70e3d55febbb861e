// Loading libOSMesa's entry points on demand (gl_entry_points.h).
#include "backends/gl_entry_points.h"

#include <dlfcn.h>

#include <mutex>
#include <stdexcept>
#include <string>

namespace scenes {

#define RASTER_GL_DEFINE_ENTRY_POINT(name) decltype(&::name) name = nullptr;
RASTER_GL_ENTRY_POINTS(RASTER_GL_DEFINE_ENTRY_POINT)
#undef RASTER_GL_DEFINE_ENTRY_POINT

namespace {

void loadLibraryAndEntryPoints() {
  // Never closed: Mesa keeps threads and atexit handlers that must outlive the process's
  // last GL call.
  void* library = nullptr;
  std::string errors;
  for (const char* soname : {"libOSMesa.so.8", "libOSMesa.so"}) {
    library = dlopen(soname, RTLD_NOW | RTLD_LOCAL);
    if (library) break;
    errors += std::string(errors.empty() ? "" : "; ") + dlerror();
  }
  if (!library)
    throw std::runtime_error("GL backend: cannot load libOSMesa (" + errors +
                             "); the GL reference needs Debian's libosmesa6 (./setup.sh installs it)");
  // Every OSMesa and GL 3.3 core entry point is exported by libOSMesa itself.
#define RASTER_GL_LOAD_ENTRY_POINT(name)                                                                  \
  name = reinterpret_cast<decltype(name)>(dlsym(library, #name));                                         \
  if (!name) throw std::runtime_error("GL backend: libOSMesa has no " #name " (Mesa too old or too new?)");
  RASTER_GL_ENTRY_POINTS(RASTER_GL_LOAD_ENTRY_POINT)
#undef RASTER_GL_LOAD_ENTRY_POINT
}

}  // namespace

void loadGlEntryPoints() {
  // A failed load is tried again by the next call, and reports the same error again.
  static std::mutex loading;
  static bool loaded = false;
  const std::lock_guard<std::mutex> lock(loading);
  if (loaded) return;
  loadLibraryAndEntryPoints();
  loaded = true;
}

}  // namespace scenes
