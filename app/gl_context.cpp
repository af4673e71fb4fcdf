// GLFW, OSMesa and EGL context creation.
#include "app/gl_context.h"

#include <glad/gl.h>

#include <GL/osmesa.h>
#include <EGL/egl.h>
#include <EGL/eglext.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

namespace vista {

const char* backendName(Backend b) {
    switch (b) {
        case Backend::Glfw: return "glfw";
        case Backend::OSMesa: return "osmesa";
        case Backend::Egl: return "egl";
    }
    return "?";
}

std::string GlContext::renderer() const {
    const GLubyte* r = glGetString(GL_RENDERER);
    return r ? reinterpret_cast<const char*>(r) : "unknown";
}

namespace {

void GLAPIENTRY debugCallback(GLenum, GLenum type, GLuint, GLenum severity, GLsizei, const GLchar* message, const void*) {
    if (severity == GL_DEBUG_SEVERITY_NOTIFICATION) return;
    std::fprintf(stderr, "GL %s: %s\n", type == GL_DEBUG_TYPE_ERROR ? "error" : "warning", message);
}

// Shared set-up once a context is current and loaded.
bool initGl(const ContextOptions& options, std::string& error) {
    GLint major = 0, minor = 0;
    glGetIntegerv(GL_MAJOR_VERSION, &major);
    glGetIntegerv(GL_MINOR_VERSION, &minor);
    if (major * 10 + minor < 45) {
        error = "OpenGL 4.5 is required, the context offers " + std::to_string(major) + "." + std::to_string(minor);
        return false;
    }
    if (options.debug) {
        glEnable(GL_DEBUG_OUTPUT);
        glEnable(GL_DEBUG_OUTPUT_SYNCHRONOUS);
        glDebugMessageCallback(debugCallback, nullptr);
    }
    glClipControl(GL_LOWER_LEFT, GL_ZERO_TO_ONE);  // reversed-Z needs [0,1] clip depth
    return true;
}

class GlfwContext final : public GlContext {
public:
    ~GlfwContext() override {
        if (window_) glfwDestroyWindow(window_);
        glfwTerminate();
    }
    Backend backend() const override { return Backend::Glfw; }
    bool makeCurrent() override {
        glfwMakeContextCurrent(window_);
        return window_ != nullptr;
    }
    GLFWwindow* window() override { return window_; }

    bool create(const ContextOptions& o, std::string& error) {
        glfwSetErrorCallback([](int, const char* message) { std::fprintf(stderr, "GLFW: %s\n", message); });
        if (!glfwInit()) {
            error = "cannot initialise GLFW (is there a display? try --backend osmesa)";
            return false;
        }
        glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 4);
        glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 5);
        glfwWindowHint(GLFW_OPENGL_PROFILE, GLFW_OPENGL_CORE_PROFILE);
        glfwWindowHint(GLFW_OPENGL_FORWARD_COMPAT, GLFW_TRUE);
        glfwWindowHint(GLFW_OPENGL_DEBUG_CONTEXT, o.debug ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_VISIBLE, o.visible ? GLFW_TRUE : GLFW_FALSE);
        glfwWindowHint(GLFW_SRGB_CAPABLE, GLFW_FALSE);  // the tone-map pass writes sRGB values itself
        GLFWmonitor* monitor = o.fullscreen ? glfwGetPrimaryMonitor() : nullptr;
        int w = o.width, h = o.height;
        if (monitor) {
            const GLFWvidmode* mode = glfwGetVideoMode(monitor);
            w = mode->width;
            h = mode->height;
        }
        window_ = glfwCreateWindow(w, h, o.title.c_str(), monitor, nullptr);
        if (!window_) {
            error = "cannot create an OpenGL 4.5 core window (the driver may lack 4.5; try --backend osmesa)";
            return false;
        }
        glfwMakeContextCurrent(window_);
        glfwSwapInterval(o.vsync ? 1 : 0);
        if (!gladLoadGL(glfwGetProcAddress)) {
            error = "cannot load OpenGL functions through GLFW";
            return false;
        }
        return initGl(o, error);
    }

private:
    GLFWwindow* window_ = nullptr;
};

class OSMesaGlContext final : public GlContext {
public:
    ~OSMesaGlContext() override {
        if (context_) OSMesaDestroyContext(context_);
    }
    Backend backend() const override { return Backend::OSMesa; }
    bool makeCurrent() override {
        // Only when another context took its place: making it current again allocates anew.
        if (context_ && OSMesaGetCurrentContext() == context_) return true;
        return context_ && OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1);
    }

    bool create(const ContextOptions& o, std::string& error) {
        const int attribs[] = {OSMESA_FORMAT, OSMESA_RGBA, OSMESA_DEPTH_BITS, 0, OSMESA_PROFILE, OSMESA_CORE_PROFILE,
                               OSMESA_CONTEXT_MAJOR_VERSION, 4, OSMESA_CONTEXT_MINOR_VERSION, 5, 0};
        context_ = OSMesaCreateContextAttribs(attribs, nullptr);
        if (!context_) {
            error = "cannot create an OSMesa OpenGL 4.5 core context (install libosmesa6, or try --backend egl)";
            return false;
        }
        // Passes render into their own framebuffers; the default one is never drawn to.
        buffer_.resize(4);
        if (!OSMesaMakeCurrent(context_, buffer_.data(), GL_UNSIGNED_BYTE, 1, 1)) {
            error = "cannot make the OSMesa context current";
            return false;
        }
        if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(OSMesaGetProcAddress))) {
            error = "cannot load OpenGL functions through OSMesa";
            return false;
        }
        return initGl(o, error);
    }

private:
    OSMesaContext context_ = nullptr;
    std::vector<unsigned char> buffer_;
};

class EglGlContext final : public GlContext {
public:
    ~EglGlContext() override {
        if (display_ != EGL_NO_DISPLAY) {
            eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
            if (context_ != EGL_NO_CONTEXT) eglDestroyContext(display_, context_);
            eglTerminate(display_);
        }
    }
    Backend backend() const override { return Backend::Egl; }
    bool makeCurrent() override {
        return context_ != EGL_NO_CONTEXT && eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_);
    }

    bool create(const ContextOptions& o, std::string& error) {
        display_ = openDisplay();
        EGLint major = 0, minor = 0;
        if (display_ == EGL_NO_DISPLAY || !eglInitialize(display_, &major, &minor)) {
            error = "cannot open an EGL display (no GPU device and no Mesa surfaceless platform; try --backend osmesa)";
            return false;
        }
        const EGLint config_attribs[] = {EGL_SURFACE_TYPE, EGL_PBUFFER_BIT, EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
        EGLConfig config = nullptr;
        EGLint count = 0;
        if (!eglChooseConfig(display_, config_attribs, &config, 1, &count) || count == 0) {
            // Surfaceless displays may offer no pbuffer configs; a context without one still works.
            const EGLint any[] = {EGL_RENDERABLE_TYPE, EGL_OPENGL_BIT, EGL_NONE};
            if (!eglChooseConfig(display_, any, &config, 1, &count)) count = 0;
            if (count == 0) config = nullptr;
        }
        if (!eglBindAPI(EGL_OPENGL_API)) {
            error = "EGL: the OpenGL API is not available";
            return false;
        }
        const EGLint context_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 4, EGL_CONTEXT_MINOR_VERSION, 5,
                                          EGL_CONTEXT_OPENGL_PROFILE_MASK, EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                          EGL_CONTEXT_OPENGL_DEBUG, o.debug ? EGL_TRUE : EGL_FALSE, EGL_NONE};
        context_ = eglCreateContext(display_, config, EGL_NO_CONTEXT, context_attribs);
        if (context_ == EGL_NO_CONTEXT || !eglMakeCurrent(display_, EGL_NO_SURFACE, EGL_NO_SURFACE, context_)) {
            error = "cannot create or bind an EGL OpenGL 4.5 core context";
            return false;
        }
        if (!gladLoadGL(reinterpret_cast<GLADloadfunc>(eglGetProcAddress))) {
            error = "cannot load OpenGL functions through EGL";
            return false;
        }
        return initGl(o, error);
    }

private:
    // A GPU device when the driver exposes one (NVIDIA), else Mesa's surfaceless platform.
    static EGLDisplay openDisplay() {
        auto query_devices = reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
        auto platform_display = reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
        if (!platform_display) return eglGetDisplay(EGL_DEFAULT_DISPLAY);
        if (query_devices) {
            EGLDeviceEXT devices[8];
            EGLint n = 0;
            if (query_devices(8, devices, &n)) {
                auto query_string = reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
                for (EGLint i = 0; i < n; ++i) {
                    const char* ext = query_string ? query_string(devices[i], EGL_EXTENSIONS) : nullptr;
                    // Mesa's software device is left to the surfaceless path below.
                    if (ext && std::string(ext).find("EGL_MESA_device_software") != std::string::npos) continue;
                    EGLDisplay d = platform_display(EGL_PLATFORM_DEVICE_EXT, devices[i], nullptr);
                    if (d != EGL_NO_DISPLAY) return d;
                }
            }
        }
        return platform_display(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    }

    EGLDisplay display_ = EGL_NO_DISPLAY;
    EGLContext context_ = EGL_NO_CONTEXT;
};

template <class T>
std::unique_ptr<GlContext> make(const ContextOptions& options, std::string& error) {
    auto context = std::make_unique<T>();
    if (!context->create(options, error)) return nullptr;
    return context;
}

}  // namespace

std::unique_ptr<GlContext> createContext(Backend backend, const ContextOptions& options, std::string& error) {
    switch (backend) {
        case Backend::Glfw: return make<GlfwContext>(options, error);
        case Backend::OSMesa: return make<OSMesaGlContext>(options, error);
        case Backend::Egl: return make<EglGlContext>(options, error);
    }
    return nullptr;
}

bool displayAvailable() {
    const char* x = std::getenv("DISPLAY");
    const char* wayland = std::getenv("WAYLAND_DISPLAY");
    return (x && *x) || (wayland && *wayland);
}

}  // namespace vista
