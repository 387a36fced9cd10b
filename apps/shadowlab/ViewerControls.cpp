// The viewer's mouse and keys: the orbiting camera (left drag orbits, right
// drag pans, the wheel zooms, R resets), WASD fly, Shift + drag moving the
// selected light, and the keys for play (space), screenshot (F12) and
// compare (C).
#include "ViewerSession.h"

#define GLFW_INCLUDE_NONE
#include <GLFW/glfw3.h>
#include <imgui.h>

#include <sstream>

namespace shadowlab::viewer {

void ViewerSession::handleMouse(int height) {
    ImGuiIO& io = ImGui::GetIO();
    // Camera: left drag orbits, right drag pans, the wheel zooms, R resets.
    // Shift + left drag moves the selected point or spot light across the view.
    const bool dragLight = io.KeyShift && selectedLight >= 0 && static_cast<std::size_t>(selectedLight) < scene.lights.size() &&
                           scene.lights[static_cast<std::size_t>(selectedLight)].type != LightType::Directional;
    if (!io.WantCaptureMouse && dragLight && ImGui::IsMouseDragging(ImGuiMouseButton_Left) && (io.MouseDelta.x != 0.0f || io.MouseDelta.y != 0.0f)) {
        const Light& light = scene.lights[static_cast<std::size_t>(selectedLight)];
        const glm::vec3 eye = cameraMoved ? orbit.position() : scene.camera.position;
        const glm::vec3 at = cameraMoved ? orbit.target : scene.camera.target;
        const glm::vec3 forward = glm::normalize(at - eye);
        const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
        const glm::vec3 up = glm::cross(right, forward);
        // A pixel moves the light by one pixel's width at its distance (orthographic: anywhere).
        const float viewHeight = scene.camera.orthoHeight > 0.0f ? scene.camera.orthoHeight
                                                                  : 2.0f * glm::length(light.position - eye) * std::tan(glm::radians(scene.camera.fovYDeg) * 0.5f);
        const float perPixel = viewHeight / static_cast<float>(height);
        const glm::vec3 p = light.position + (io.MouseDelta.x * right - io.MouseDelta.y * up) * perPixel;
        std::ostringstream s;
        s << "[" << p.x << ", " << p.y << ", " << p.z << "]";
        apply("lights[" + std::to_string(selectedLight) + "].position", s.str());
    } else if (!io.WantCaptureMouse) {
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Left)) {
            orbit.yaw -= io.MouseDelta.x * 0.008f;
            orbit.pitch = std::clamp(orbit.pitch + io.MouseDelta.y * 0.008f, -1.5f, 1.5f);
            cameraMoved = true;
        }
        if (ImGui::IsMouseDragging(ImGuiMouseButton_Right)) {
            const glm::vec3 forward = glm::normalize(orbit.target - orbit.position());
            const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
            const glm::vec3 up = glm::cross(right, forward);
            orbit.target += (-io.MouseDelta.x * right + io.MouseDelta.y * up) * orbit.distance * 0.002f;
            cameraMoved = true;
        }
        if (io.MouseWheel != 0.0f) {
            orbit.distance *= std::pow(0.9f, io.MouseWheel);
            cameraMoved = true;
        }
    }
}

// Returns whether F12 asked for a screenshot.
bool ViewerSession::handleKeys() {
    ImGuiIO& io = ImGui::GetIO();
    // Keys (ImGui 1.86 names only a few): pressed on this frame, not held.
    auto pressed = [&](int key) {
        const bool down = glfwGetKey(window, key) == GLFW_PRESS;
        const bool was = keysDown[key];
        keysDown[key] = down;
        return down && !was && !io.WantCaptureKeyboard;
    };
    if (pressed(GLFW_KEY_R)) {
        orbit.from(scene.camera);
        cameraMoved = false;
    }
    if (pressed(GLFW_KEY_SPACE)) playing = !playing;
    // WASD (and Q/E down/up) fly: the orbit's centre moves with the camera.
    if (!io.WantCaptureKeyboard) {
        const glm::vec3 forward = glm::normalize(orbit.target - orbit.position());
        const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(0.0f, 1.0f, 0.0f)));
        glm::vec3 move(0.0f);
        if (glfwGetKey(window, GLFW_KEY_W) == GLFW_PRESS) move += forward;
        if (glfwGetKey(window, GLFW_KEY_S) == GLFW_PRESS) move -= forward;
        if (glfwGetKey(window, GLFW_KEY_D) == GLFW_PRESS) move += right;
        if (glfwGetKey(window, GLFW_KEY_A) == GLFW_PRESS) move -= right;
        if (glfwGetKey(window, GLFW_KEY_E) == GLFW_PRESS) move.y += 1.0f;
        if (glfwGetKey(window, GLFW_KEY_Q) == GLFW_PRESS) move.y -= 1.0f;
        if (glm::length(move) > 0.0f) {
            orbit.target += glm::normalize(move) * orbit.distance * 0.6f * std::max(io.DeltaTime, 1.0f / 240.0f);
            cameraMoved = true;
        }
    }
    bool screenshotKey = pressed(GLFW_KEY_F12);
    if (pressed(GLFW_KEY_C) && !tracing) {
        referenceAsked = true;
        referenceAskedAt = frame;
    }
    return screenshotKey;
}

} // namespace shadowlab::viewer
