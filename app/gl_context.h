// OpenGL 4.5 core contexts: a GLFW window (interactive, or hidden for captures), OSMesa
// (headless, software) and EGL (headless: surfaceless on Mesa, device platform on NVIDIA).
// Creating one also loads the GL entry points with glad and sets the conventions every
// pass relies on (reversed-Z clip control).
#pragma once

#include <memory>
#include <string>

struct GLFWwindow;

namespace vista {

enum class Backend { Glfw, OSMesa, Egl };

// "glfw", "osmesa", "egl".
const char* backendName(Backend b);

class GlContext {
public:
    virtual ~GlContext() = default;
    virtual Backend backend() const = 0;
    // Makes this context current again on the calling thread (after another was made and destroyed,
    // as a capture run in the same process does).
    virtual bool makeCurrent() = 0;
    // The GLFW window, or null for headless contexts.
    virtual GLFWwindow* window() { return nullptr; }
    std::string renderer() const;  // GL_RENDERER
};

struct ContextOptions {
    int width = 320, height = 180;  // window size; headless contexts render to FBOs only
    bool visible = true;            // GLFW: show the window
    bool fullscreen = false;
    bool vsync = true;
    bool debug = false;             // KHR_debug output to stderr
    std::string title = "vista";
};

// Returns null and sets error on failure (the message says what to try instead).
std::unique_ptr<GlContext> createContext(Backend backend, const ContextOptions& options, std::string& error);

// True when a window can be opened: a display (X11 or Wayland) is reachable.
bool displayAvailable();

}  // namespace vista
