#pragma once
// The typed set of shader options. Each distinct value is one compiled
// program; preamble() turns it into #defines for the one source per stage.
#include "gl/Program.h"

#include <shadowlab/Scene.h>

#include <cstdint>
#include <string>
#include <vector>

namespace shadowlab {

enum class ShaderPass : std::uint8_t {
    Base,    ///< scene.vert + base.frag
    Light,   ///< scene.vert + lighting.frag
    Resolve, ///< fullscreen.vert + resolve.frag
};

struct ShaderVariant {
    ShaderPass pass = ShaderPass::Base;
    LightType lightType = LightType::Directional;           ///< Light pass only
    ShadowTechnique technique = ShadowTechnique::None;      ///< Light pass only
    bool baseColorTexture = false;                          ///< Base and Light passes
    bool screenVisibility = false;  ///< Light pass: visibility from a per-pixel texture (the reference)
    bool outputVisibility = false;  ///< Light pass: write the visibility term instead of light

    /// Unique per distinct variant (fields that do not apply to the pass are ignored).
    std::uint32_t key() const;
    /// `#define` lines; every define the sources test is always defined.
    std::string preamble() const;
    std::vector<gl::ShaderStage> stages() const;
};

} // namespace shadowlab
