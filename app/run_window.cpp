// The window loop: one screen, one frame.
#include "app/run_window.h"

#include "app/camera_controller.h"
#include "app/frame.h"
#include "app/frame_rate.h"
#include "app/gl_context.h"
#include "app/image_writer.h"
#include "app/panel.h"
#include "app/scene.h"

#include <glad/gl.h>
#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <imgui.h>

#include <chrono>
#include <cstdio>
#include <ctime>

namespace vista {
namespace {

// Edge-triggered keys and scroll, gathered by GLFW callbacks.
struct WindowEvents {
    bool toggle_panel = false, screenshot = false, reload = false, pause = false, restart = false, walk = false;
    double scroll = 0.0;
};

WindowEvents& events(GLFWwindow* w) { return *static_cast<WindowEvents*>(glfwGetWindowUserPointer(w)); }

void onKey(GLFWwindow* w, int key, int, int action, int) {
    if (action != GLFW_PRESS) return;
    WindowEvents& e = events(w);
    switch (key) {
        case GLFW_KEY_F1: e.toggle_panel = true; break;
        case GLFW_KEY_F12: e.screenshot = true; break;
        case GLFW_KEY_ESCAPE: glfwSetWindowShouldClose(w, GLFW_TRUE); break;
        default: break;
    }
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureKeyboard) return;
    if (key == GLFW_KEY_R) e.reload = true;
    if (key == GLFW_KEY_SPACE) e.pause = true;
    if (key == GLFW_KEY_BACKSPACE) e.restart = true;
    if (key == GLFW_KEY_F) e.walk = true;
}

void onScroll(GLFWwindow* w, double, double dy) {
    if (ImGui::GetCurrentContext() && ImGui::GetIO().WantCaptureMouse) return;
    events(w).scroll += dy;
}

CameraInput pollCamera(GLFWwindow* w, double& last_x, double& last_y) {
    CameraInput in;
    auto down = [w](int key) { return glfwGetKey(w, key) == GLFW_PRESS; };
    bool keyboard = !ImGui::GetIO().WantCaptureKeyboard;
    if (keyboard) {
        in.forward = float(down(GLFW_KEY_W)) - float(down(GLFW_KEY_S));
        in.right = float(down(GLFW_KEY_D)) - float(down(GLFW_KEY_A));
        in.up = float(down(GLFW_KEY_E)) - float(down(GLFW_KEY_Q));
        in.fast = down(GLFW_KEY_LEFT_SHIFT) || down(GLFW_KEY_RIGHT_SHIFT);
        in.slow = down(GLFW_KEY_LEFT_CONTROL) || down(GLFW_KEY_RIGHT_CONTROL);
    }
    double x = 0, y = 0;
    glfwGetCursorPos(w, &x, &y);
    bool looking = glfwGetMouseButton(w, GLFW_MOUSE_BUTTON_RIGHT) == GLFW_PRESS && !ImGui::GetIO().WantCaptureMouse;
    if (looking) {
        in.look_dx = x - last_x;
        in.look_dy = y - last_y;
    }
    last_x = x;
    last_y = y;
    return in;
}

// Saves what the user sees (scene and panel) from the back buffer.
void screenshot(int width, int height) {
    std::vector<unsigned char> rgba(std::size_t(width) * std::size_t(height) * 4);
    glBindFramebuffer(GL_READ_FRAMEBUFFER, 0);
    glReadBuffer(GL_BACK);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, width, height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    std::size_t row = std::size_t(width) * 4;
    for (int y = 0; y < height / 2; ++y)
        std::swap_ranges(rgba.begin() + std::ptrdiff_t(row * std::size_t(y)), rgba.begin() + std::ptrdiff_t(row * std::size_t(y + 1)),
                         rgba.begin() + std::ptrdiff_t(row * std::size_t(height - 1 - y)));
    std::time_t now = std::time(nullptr);
    char name[64];
    std::strftime(name, sizeof name, "screenshot_%Y%m%d_%H%M%S.png", std::localtime(&now));
    std::error_code ec;
    std::filesystem::create_directories("out", ec);
    std::filesystem::path file = std::filesystem::path("out") / name;
    // Two screenshots in one second: the second is refused rather than replacing the first.
    std::string problem = writePng(file, width, height, rgba, /*force=*/false);
    std::fprintf(stderr, "vista: %s\n", problem.empty() ? ("screenshot saved to " + file.string()).c_str() : problem.c_str());
}

}  // namespace

int runWindow(Settings s, const std::filesystem::path& scene_file) {
    std::string error;
    ContextOptions options{s.window.width, s.window.height, true, s.window.fullscreen, s.window.vsync, s.window.gl_debug,
                           "vista - " + scene_file.filename().string()};
    auto context = createContext(Backend::Glfw, options, error);
    if (!context) {
        std::fprintf(stderr, "vista: %s\n", error.c_str());
        return 1;
    }
    GLFWwindow* window = context->window();
    FrameRenderer renderer(vistaRoot());
    if (!renderer.compilePrograms(error)) {
        std::fprintf(stderr, "vista: shader compilation failed:\n%s", error.c_str());
        return 1;
    }

    InputErrors problems = renderer.prepare(s);
    if (!problems.empty()) {
        printErrors(problems);
        return 2;
    }

    WindowEvents ev;
    glfwSetWindowUserPointer(window, &ev);
    glfwSetKeyCallback(window, onKey);  // installed before ImGui's, which chains to them
    glfwSetScrollCallback(window, onScroll);
    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    ImGui::GetIO().IniFilename = nullptr;
    ImGui_ImplGlfw_InitForOpenGL(window, true);
    ImGui_ImplOpenGL3_Init("#version 450 core");

    CameraController camera(s.camera);
    Panel panel(scene_file);
    PanelStats stats;
    stats.renderer = context->renderer();
    double time_s = 0.0, last_x = 0.0, last_y = 0.0;
    bool paused = false, vsync = s.window.vsync;
    int copy_w = 0, copy_h = 0;
    FrameRateMeter frame_rate;
    auto last = std::chrono::steady_clock::now();
    glfwGetCursorPos(window, &last_x, &last_y);

    while (!glfwWindowShouldClose(window)) {
        glfwPollEvents();
        auto now = std::chrono::steady_clock::now();
        const double wall_s = std::chrono::duration<double>(now - last).count();
        double dt = std::min(wall_s, 0.25);  // the animation step; the panel's fps uses wall_s
        last = now;
        frame_rate.addFrame(wall_s);

        if (ev.toggle_panel) panel.visible = !panel.visible;
        if (ev.reload) renderer.shaders().reloadAll();
        if (ev.pause) paused = !paused;
        if (ev.restart) time_s = 0.0;
        if (ev.walk) s.camera.follow_terrain = !s.camera.follow_terrain;
        CameraInput input = pollCamera(window, last_x, last_y);
        input.scroll = ev.scroll;
        bool take_screenshot = ev.screenshot;
        ev = WindowEvents{};
        camera.update(input, dt, s.camera);
        stats.shader_errors.clear();
        for (const auto& p : renderer.prepare(s)) stats.shader_errors.push_back(p.str());  // settings edited live
        if (Terrain* terrain = renderer.terrain(); terrain && s.terrain.enabled)
            keepAboveGround(camera, terrain->heightAt(camera.position.x, camera.position.z), s.camera);
        if (!paused) time_s += dt;
        renderer.shaders().poll();

        int width = 0, height = 0;
        glfwGetFramebufferSize(window, &width, &height);
        if (width <= 0 || height <= 0) {  // minimised
            glfwWaitEvents();
            continue;
        }
        if (width != copy_w || height != copy_h) {
            stats.reference_copy_ms = renderer.measureReferenceCopy(width, height);
            copy_w = width;
            copy_h = height;
        }

        ViewParams view{camera.position, camera.yaw_deg, camera.pitch_deg, camera.fov_deg, s.camera.near_m, width, height};
        auto frame_start = std::chrono::steady_clock::now();
        FrameRequest request;
        request.present = true;
        request.count_nonfinite = true;
        request.count_grass = true;
        request.count_weather = true;
        FrameReport report = renderer.render(s, view, time_s, request);
        double cpu_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - frame_start).count();

        for (const auto& t : renderer.timers().collect()) {
            stats.passes = t.passes;
            stats.gpu_ms = t.gpu_ms;
        }
        for (const auto& c : renderer.counters().collect()) stats.counters[c.name] = double(c.value);
        for (const auto& [name, value] : report.counters) stats.counters[name] = value;
        stats.cpu_ms += (cpu_ms - stats.cpu_ms) * 0.1;
        stats.fps = frame_rate.fps();
        stats.time_s = time_s;
        stats.paused = paused;
        stats.culled = report.culled;
        std::vector<std::string> shader_errors = renderer.shaders().errors();
        stats.shader_errors.insert(stats.shader_errors.end(), shader_errors.begin(), shader_errors.end());
        stats.pool_textures = renderer.pool().liveCount();

        glBindFramebuffer(GL_FRAMEBUFFER, 0);
        glViewport(0, 0, width, height);
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        ImGui::NewFrame();
        // The panel shows (and "save scene as" stores) the live camera pose; editing it moves the camera.
        s.camera.position = camera.position;
        s.camera.yaw_deg = float(camera.yaw_deg);
        s.camera.pitch_deg = float(camera.pitch_deg);
        s.camera.fov_deg = float(camera.fov_deg);
        if (panel.draw(s, stats)) camera.reset(s.camera);
        ImGui::Render();
        ImGui_ImplOpenGL3_RenderDrawData(ImGui::GetDrawData());
        if (take_screenshot) screenshot(width, height);
        if (s.window.vsync != vsync) glfwSwapInterval((vsync = s.window.vsync) ? 1 : 0);
        glfwSwapBuffers(window);
    }
    ImGui_ImplOpenGL3_Shutdown();
    ImGui_ImplGlfw_Shutdown();
    ImGui::DestroyContext();
    return 0;
}

}  // namespace vista
