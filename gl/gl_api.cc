// Loads gl_api.h's table from the OSMesa library.
#define VIGIL_GL_API_NO_REDIRECT
#include "gl/gl_api.h"

#include <dlfcn.h>

#include <stdexcept>
#include <string>

namespace vigil::gl {
namespace {

template <class Function>
void LoadFunction(void* library, const char* name, Function* function) {
  *function = reinterpret_cast<Function>(dlsym(library, name));
  if (*function == nullptr)
    throw std::runtime_error(std::string("gl: ") + OsMesaLibrary() + " has no function " + name);
}

Api LoadApi() {
  // Kept open for the rest of the process: the contexts and the table point into it.
  void* library = dlopen(OsMesaLibrary(), RTLD_NOW | RTLD_LOCAL);
  if (library == nullptr) {
    const char* error = dlerror();
    throw std::runtime_error(std::string("gl: cannot load OSMesa (") + OsMesaLibrary() +
                             "): " + (error != nullptr ? error : "unknown error"));
  }
  Api api;
#define VIGIL_GL_LOAD(name) LoadFunction(library, #name, &api.name);
  VIGIL_GL_FUNCTIONS(VIGIL_GL_LOAD)
#undef VIGIL_GL_LOAD
  return api;
}

}  // namespace

const Api& Functions() {
  static const Api api = LoadApi();
  return api;
}

const char* OsMesaLibrary() { return VIGIL_OSMESA_LIBRARY; }

}  // namespace vigil::gl
