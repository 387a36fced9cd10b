#include "render/ShaderVariant.h"

namespace shadowlab {

namespace {
// The GLSL names of the shared constants (shaders/shadowlab_shared.h).
const char* lightDefine(LightType t) {
    switch (t) {
    case LightType::Directional: return "SL_LIGHT_DIRECTIONAL";
    case LightType::Spot: return "SL_LIGHT_SPOT";
    case LightType::Point: return "SL_LIGHT_POINT";
    }
    return "?";
}
const char* techniqueDefine(ShadowTechnique t) {
    switch (t) {
    case ShadowTechnique::None: return "SL_SHADOW_NONE";
    }
    return "?";
}
} // namespace

std::uint32_t ShaderVariant::key() const {
    const bool surface = pass != ShaderPass::Resolve;
    const bool light = pass == ShaderPass::Light;
    return static_cast<std::uint32_t>(pass) | (light ? static_cast<std::uint32_t>(lightType) << 4 : 0u) |
           (light ? static_cast<std::uint32_t>(technique) << 8 : 0u) | (surface && baseColorTexture ? 1u << 16 : 0u) |
           (light && screenVisibility ? 1u << 17 : 0u) | (light && outputVisibility ? 1u << 18 : 0u);
}

std::string ShaderVariant::preamble() const {
    std::string out;
    out += "#define HAS_BASE_COLOR_TEXTURE " + std::string(baseColorTexture && pass != ShaderPass::Resolve ? "1" : "0") + "\n";
    out += "#define LIGHT_TYPE " + std::string(lightDefine(lightType)) + "\n";
    out += "#define SHADOW_TECHNIQUE " + std::string(techniqueDefine(technique)) + "\n";
    const bool light = pass == ShaderPass::Light;
    out += "#define SCREEN_VISIBILITY " + std::string(light && screenVisibility ? "1" : "0") + "\n";
    out += "#define OUTPUT_VISIBILITY " + std::string(light && outputVisibility ? "1" : "0") + "\n";
    return out;
}

std::vector<gl::ShaderStage> ShaderVariant::stages() const {
    switch (pass) {
    case ShaderPass::Base: return {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "base.frag"}};
    case ShaderPass::Light: return {{GL_VERTEX_SHADER, "scene.vert"}, {GL_FRAGMENT_SHADER, "lighting.frag"}};
    case ShaderPass::Resolve: return {{GL_VERTEX_SHADER, "fullscreen.vert"}, {GL_FRAGMENT_SHADER, "resolve.frag"}};
    }
    return {};
}

} // namespace shadowlab
