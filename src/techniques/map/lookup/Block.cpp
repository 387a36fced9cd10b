// Technique "map": its uniform block (lookup/Block.h).
#include "techniques/map/lookup/Block.h"

#include "techniques/map/fit/Sdsm.h"
#include "techniques/map/options/Settings.h"

#include <glm/gtc/matrix_transform.hpp>

#include <cstddef>

namespace shadowlab::map {

// std140 places a vec3 on 16 bytes and packs the float after it; C++ does
// the same only where the members before fill whole 16 bytes.
static_assert(offsetof(shared::MapUniforms, lightPosition) % 16 == 0 && offsetof(shared::MapUniforms, towardsLight) % 16 == 0 &&
                  offsetof(shared::MapUniforms, lightAxis) % 16 == 0 && offsetof(shared::MapUniforms, viewForward) % 16 == 0 &&
                  offsetof(shared::MapUniforms, texelWorld) % 16 == 0 && sizeof(shared::MapUniforms) % 16 == 0,
              "MapUniforms must keep std140's layout (shaders/shadow_map_shared.h)");
static_assert(offsetof(shared::MapUniforms, blurLayer) == offsetof(shared::MapUniforms, blurRadius) + 2 * sizeof(float),
              "setBlur writes blurRadius, blurAxis and blurLayer as one range");
static_assert(offsetof(shared::MapUniforms, lightClipFromWorld) == 0 && offsetof(shared::MapUniforms, shadowFromWorld) == sizeof(glm::mat4) &&
                  offsetof(SdsmFit, shadowFromWorld) == offsetof(SdsmFit, clipFromWorld) + sizeof(glm::mat4) &&
                  offsetof(shared::MapUniforms, farPlane) == offsetof(shared::MapUniforms, nearPlane) + sizeof(float) &&
                  offsetof(SdsmFit, farPlane) == offsetof(SdsmFit, nearPlane) + sizeof(float),
              "copyFit copies both matrices, and the near and far planes, as one range each");
static_assert(offsetof(shared::MapUniforms, warpV) == offsetof(shared::MapUniforms, warpU) + sizeof(float) &&
                  offsetof(SdsmFit, warpV) == offsetof(SdsmFit, warpU) + sizeof(float),
              "copyFit copies warpU and warpV as one range");
static_assert(offsetof(shared::MapUniforms, cascadeRange) - offsetof(shared::MapUniforms, cascadeShadowFromWorld) ==
                      offsetof(SdsmFit, cascadeRange) - offsetof(SdsmFit, cascadeShadowFromWorld) &&
                  offsetof(shared::MapUniforms, cascadeFar) - offsetof(shared::MapUniforms, cascadeShadowFromWorld) ==
                      offsetof(SdsmFit, cascadeFar) - offsetof(SdsmFit, cascadeShadowFromWorld) &&
                  offsetof(shared::MapUniforms, cascadeTexel) - offsetof(shared::MapUniforms, cascadeShadowFromWorld) ==
                      offsetof(SdsmFit, cascadeTexel) - offsetof(SdsmFit, cascadeShadowFromWorld),
              "copyFit copies the cascades' matrices, far ends, texels and ranges as one range, laid out alike");
static_assert(offsetof(SdsmFit, cascadeWarp) - offsetof(SdsmFit, cascadeWarpPlane) ==
                  offsetof(shared::MapUniforms, cascadeWarp) - offsetof(shared::MapUniforms, cascadeWarpPlane),
              "copyFit copies the warped cascades' planes and texels as one range, laid out alike");

namespace {

// Texture space from clip space: the lecture's bias matrix (scale and offset by 0.5).
const glm::mat4 kBias = glm::translate(glm::mat4(1.0f), glm::vec3(0.5f)) * glm::scale(glm::mat4(1.0f), glm::vec3(0.5f));

// A cube's members: its faces' cameras, its far plane, bias and filter radius.
void cubeMembers(shared::MapUniforms& u, const MapLight& p, const MapArray& g) {
    const CubeCamera& c = p.cubeCamera();
    for (std::size_t f = 0; f < 6; ++f) u.faceClipFromWorld[f] = c.faceClipFromWorld[f];
    const bool presetBias = usesPresetBias(p.options, true);
    // The presets give their constant bias in world units (Lawonn, LearnOpenGL: 0.15).
    u.constantBias = presetBias ? p.options.constantBias / c.farPlane : p.options.constantBias;
    // The constant offset in the format's smallest steps.
    const float step = g.format() == MapFormat::Depth16 ? 1.0f / 65535.0f : g.format() == MapFormat::Depth24 ? 1.0f / 16777215.0f : 1.0f / 16777216.0f;
    u.cubeFar = c.farPlane;
    u.cubeSlopeBias = p.options.slopeBias;
    u.cubeTexelPerDistance = 2.0f / static_cast<float>(g.size());
    u.diskRadius = p.options.diskRadius;
    u.diskGrowth = p.options.diskGrowth;
    u.cubeOffset = p.options.offsetUnits * step;
}

// The cascades' members: each one's texture-space matrix, far end, texel and planes.
void cascadeMembers(shared::MapUniforms& u, const MapLight& p) {
    static const CascadeSet none;  // a light without cascades: none, and the default view direction
    const CascadeSet& set = p.cascadeSet() ? *p.cascadeSet() : none;
    const std::vector<LightCamera>& cascades = set.cameras;
    const glm::dmat4 worldFromFirst = cascades.empty() ? glm::dmat4(1.0) : glm::inverse(glm::dmat4(kBias * cascades.front().clipFromWorld()));
    for (std::size_t c = 0; c < cascades.size(); ++c) {
        u.cascadeShadowFromWorld[c] = kBias * cascades[c].clipFromWorld();
        // Warped: its texel's size per point (shadow_map_bias.glsl: mapWarpedTexel). The
        // cascades share cascade 0's light view, whose warpAcross and warpU (the flag) upload() sets.
        if (cascades[c].warped) {
            u.cascadeWarpPlane[c] = cascades[c].warpPlane;
            u.cascadeWarp[c] = glm::vec4(cascades[c].warpU, cascades[c].warpV, 0.0f, 0.0f);
        }
        // Its texture space from the first cascade's (shadowFromWorld: p.camera
        // is the first): the diagonal and the translation of M_c M_0^-1, in
        // double; the cascades share a light view (MAP_CASCADE_AXES), so the
        // rest is 0 (CascadeTest.UnwarpedCascadesShareOneLightViewUpToScaleAndOffset).
        const glm::dmat4 fromFirst = glm::dmat4(u.cascadeShadowFromWorld[c]) * worldFromFirst;
        // w: its texel along the light view's y (offset's w: along x; shadow_map_2d.glsl weighs them by the normal).
        const glm::vec2 axes = cascades[c].texelAxes.x > 0.0f ? cascades[c].texelAxes : glm::vec2(cascades[c].texelSize);
        u.cascadeScale[c] = glm::vec4(fromFirst[0][0], fromFirst[1][1], fromFirst[2][2], axes.y);
        u.cascadeOffset[c] = glm::vec4(glm::dvec3(fromFirst[3]), axes.x);
        u.cascadeFar[c / 4][static_cast<int>(c % 4)] = set.far[c];
        u.cascadeTexel[c / 4][static_cast<int>(c % 4)] = cascades[c].texelSize;
    }
    u.viewForward = glm::normalize(set.viewForward);
    u.cascadeBlend = p.options.cascadeBlend;
    u.cascadeRounds = 2.0f;  // the slice's cascade, then the next where it fades (shadow_map_2d.glsl)
    for (std::size_t c = 0; c < cascades.size(); ++c) u.cascadeRange[c] = glm::vec4(cascades[c].nearPlane, cascades[c].farPlane, 0.0f, 0.0f);
}

} // namespace

void MapBlock::upload(const MapLight& p, const MapArray& g, const Light& light, bool translucent) {
    shared::MapUniforms u{};
    u.lightClipFromWorld = p.camera.clipFromWorld();
    u.shadowFromWorld = kBias * u.lightClipFromWorld;
    if (p.camera.perspective) u.lightTexture = u.shadowFromWorld * glm::vec4(light.position, 1.0f);
    u.layer = static_cast<float>(p.layer);
    u.reachTexels = reach(p.options);
    u.texelWorld = p.camera.texelSize;
    if (p.camera.warped) {  // a texel's size per point (shadow_map_vertex.glsl; cascades: p.camera is cascade 0)
        u.warpPlane = p.camera.warpPlane;
        const glm::mat4& view = p.camera.viewFromWorld;
        u.warpAcross = glm::vec4(view[0][0], view[1][0], view[2][0], 0.0f);  // the view's first row: light-space x
        u.warpU = p.camera.warpU;
        u.warpV = p.camera.warpV;
    }
    u.perspective = p.camera.perspective ? 1.0f : 0.0f;
    u.constantBias = p.options.constantBias;
    u.normalBiasTexels = p.options.normalBias;
    if (usesPresetBias(p.options, p.cube()) && !p.cube()) {
        // LearnOpenGL's bias: max(0.05 (1 - N.L), 0.005), nothing else (MAP_PRESET_BIAS).
        u.constantBias = 0.0f;
        u.slopeDepthBias = 0.05f;
        u.minDepthBias = 0.005f;
        u.normalBiasTexels = 0.0f;
    }
    // Dither spread: one texel (the lecture's 2.5 x 0.001 uv at 1024 texels, about 2.5 texels, with preset lecture).
    u.ditherSpread = isLecture2D(p.options, light) ? 2.5f * 0.001f * static_cast<float>(g.size()) : 1.0f;
    u.texelUv = 1.0f / static_cast<float>(g.size());
    u.poissonRadius = p.options.radius;
    u.filterTaps = static_cast<float>(p.options.samples);
    u.kernelRounds = static_cast<float>(kernelRounds(p.options, p.cube()));
    if (light.type == LightType::Directional)
        u.towardsLight = -glm::normalize(light.direction);
    else
        u.lightPosition = light.position;
    u.shadowedLight = p.options.shadowedLight;
    u.lightAxis = p.camera.axis();
    if (p.cube()) cubeMembers(u, p, g);
    cascadeMembers(u, p);
    // PCSS: the light's size as the similar triangles take it.
    const float size = light.type == LightType::Directional ? std::tan(glm::radians(0.5f * light.size)) : light.size;
    u.lightSize = size;
    u.nearPlane = p.cube() ? p.cubeCamera().nearPlane : p.camera.nearPlane;  // a cube's reversed window depth needs both (cubeWindowDepth)
    u.farPlane = p.cube() ? p.cubeCamera().farPlane : p.camera.farPlane;
    u.blockerTaps = static_cast<float>(p.options.blockerSamples);
    u.blockerHull = vogelHullInradius(p.options.blockerSamples);
    u.blockerNear = p.nearestCaster();
    u.bleedReduction = p.options.bleedReduction;
    u.transmittance = translucent ? 1.0f : 0.0f;
    uniforms_ = u;
    block_.write(u);
    fitted_ = p.gpuFit();
    fittedCascades_ = p.cascadeCount() > 0;
    fittedWarp_ = p.camera.warped;
    copyFit();
}

void MapBlock::copyFit() {
    if (!fitted_) return;
    block_.copyPart(*fitted_, offsetof(SdsmFit, clipFromWorld), offsetof(shared::MapUniforms, lightClipFromWorld), 2 * sizeof(glm::mat4));
    block_.copyPart(*fitted_, offsetof(SdsmFit, texelWorld), offsetof(shared::MapUniforms, texelWorld), sizeof(float));
    block_.copyPart(*fitted_, offsetof(SdsmFit, nearPlane), offsetof(shared::MapUniforms, nearPlane), 2 * sizeof(float));
    if (fittedWarp_) {
        block_.copyPart(*fitted_, offsetof(SdsmFit, warpPlane), offsetof(shared::MapUniforms, warpPlane), sizeof(glm::vec4));
        block_.copyPart(*fitted_, offsetof(SdsmFit, warpU), offsetof(shared::MapUniforms, warpU), 2 * sizeof(float));
    }
    if (fittedCascades_) {
        // Their matrices, far ends, texels and depth ranges (laid out alike: one range).
        const std::size_t first = offsetof(SdsmFit, cascadeShadowFromWorld), end = offsetof(SdsmFit, cascadeRange) + sizeof(SdsmFit::cascadeRange);
        block_.copyPart(*fitted_, first, offsetof(shared::MapUniforms, cascadeShadowFromWorld), end - first);
        if (fittedWarp_) {
            // Warped (not stabilised): each one's warp plane and texels.
            const std::size_t warpFirst = offsetof(SdsmFit, cascadeWarpPlane), warpEnd = offsetof(SdsmFit, cascadeWarp) + sizeof(SdsmFit::cascadeWarp);
            block_.copyPart(*fitted_, warpFirst, offsetof(shared::MapUniforms, cascadeWarpPlane), warpEnd - warpFirst);
        }
    }
}

void MapBlock::uploadAtlas(const MapLight& p, const Light& light) {
    shared::MapUniforms u{};
    u.layer = static_cast<float>(p.atlas->first);
    u.atlasTiles = static_cast<float>(p.atlas->count);
    u.atlasBilinear = p.options.filter == MapFilter::Hardware ? 1.0f : 0.0f;
    u.normalBiasTexels = p.options.normalBias;
    u.lightPosition = light.position;
    u.shadowedLight = p.options.shadowedLight;
    uniforms_ = u;
    block_.write(u);
    fitted_ = nullptr;
}

void MapBlock::setLightClip(const glm::mat4& lightClipFromWorld) {
    block_.writePart(0, sizeof lightClipFromWorld, &lightClipFromWorld);
}

void MapBlock::setCamera(const MapLight& p, std::size_t c) {
    if (p.gpuFit())
        block_.copyPart(*p.gpuFit(), p.cascadeCount() == 0 ? offsetof(SdsmFit, clipFromWorld) : offsetof(SdsmFit, cascadeClip) + c * sizeof(glm::mat4),
                        offsetof(shared::MapUniforms, lightClipFromWorld), sizeof(glm::mat4));
    else
        setLightClip(p.cameras()[c].clipFromWorld());
}

void MapBlock::setBlur(float radius, float axis, float layer) {
    const float blur[3] = {radius, axis, layer};  // blurRadius, blurAxis, blurLayer: adjacent
    block_.writePart(offsetof(shared::MapUniforms, blurRadius), sizeof blur, blur);
}

void MapBlock::writeWithLightClip(const glm::mat4& lightClipFromWorld) {
    shared::MapUniforms u = uniforms_;
    u.lightClipFromWorld = lightClipFromWorld;
    block_.writePart(0, sizeof u, &u);
}

void MapBlock::restore() {
    block_.writePart(0, sizeof uniforms_, &uniforms_);
    copyFit();
}

} // namespace shadowlab::map
