#pragma once
// The typed set of shader options of the renderer's own passes. Each
// distinct value is one program; program() turns it into the stages, the
// `#define` preamble and the technique's file in the "@shadow" slot.
#include "gl/Program.h"

#include <shadowlab/Scene.h>

#include <string>

namespace shadowlab {

struct ShaderVariant {
    bool ambient = true;            ///< add the ambient term (the base pass)
    bool light = false;             ///< add one light's term (merged base pass, light passes)
    /// Add the terms of the clustered light list's lights (no shadows; the
    /// light-list pass, LightList.h). Not with `light`.
    bool lightList = false;
    /// With `lightList`: some listed lights have shadows, looked up by
    /// `listShadowFile` (their technique's, Technique::listShadowFile). Only
    /// then: a software rasteriser pays for a lookup it could skip.
    bool lightListShadows = false;
    /// "@list_shadow"'s file when no listed light has a shadow (its listedVisibility is never called).
    static constexpr const char* kNoListShadow = "shadow_list_none.glsl";
    std::string listShadowFile = kNoListShadow; ///< with lightListShadows: fills "@list_shadow"
    LightType lightType = LightType::Directional; ///< with `light`
    std::string techniqueFile = "shadow_none.glsl"; ///< with `light`: fills "@shadow"
    std::string techniqueDefines;   ///< with `light`: the technique's own `#define` lines
    std::string techniqueVertexFile; ///< with `light`: fills "@shadow_vertex?" in scene.vert; empty for none
    gl::IncludeAliases techniqueIncludes; ///< with `light`: the technique's own slots (Technique::lightPassIncludes)
    bool baseColorTexture = false;
    /// The material's alphaMode is mask: fragments under its cutoff are
    /// discarded. Only then: a shader that may discard loses early depth
    /// testing on a software rasteriser (llvmpipe: 0.7 ms of a 6.7 ms frame).
    bool alphaTest = false;
    bool projector = false;         ///< with a spot `light`: its projected image multiplies its colour
    bool writeSurfaces = false;     ///< world position and geometric normal (compare)
    bool screenVisibility = false;  ///< with `light`: visibility from a per-pixel texture (the reference)
    bool outputVisibility = false;  ///< with `light`: write the visibility term instead of light
    bool blended = false;           ///< write the surface's alpha (a translucent surface blended over the frame)

    /// `#define` lines; every define the sources test is always defined, and
    /// fields that do not apply (light type without a light) are left out so
    /// they do not split the cache.
    std::string preamble() const;
    /// The program: scene.vert + lighting.frag with preamble and slot.
    gl::ProgramKey program() const;
    /// Every combination of the switches and light types (technique "none"),
    /// duplicates included (fields that do not apply): for tests and warm-up.
    static std::vector<ShaderVariant> all();
};

} // namespace shadowlab
