// Technique "map": the light pass's textures and samplers (lookup/Bindings.h).
#include "techniques/map/lookup/Bindings.h"

#include "techniques/map/options/Filters.h"
#include "techniques/map/options/Settings.h"

#include "gl/Calls.h"
#include "shadowlab_shared.h"

namespace shadowlab::map {

namespace {

gl::Sampler makeSampler(GLenum minFilter, GLenum magFilter, bool compare, GLenum compareFunc = GL_LEQUAL) {
    gl::Sampler s;
    glSamplerParameteri(s.id(), GL_TEXTURE_MIN_FILTER, minFilter);
    glSamplerParameteri(s.id(), GL_TEXTURE_MAG_FILTER, magFilter);
    // Outside the map: the border, depth 1 (lit).
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_BORDER);
    glSamplerParameteri(s.id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_BORDER);
    const float one[4] = {1.0f, 1.0f, 1.0f, 1.0f};
    glSamplerParameterfv(s.id(), GL_TEXTURE_BORDER_COLOR, one);
    if (compare) {
        glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_MODE, GL_COMPARE_REF_TO_TEXTURE);
        glSamplerParameteri(s.id(), GL_TEXTURE_COMPARE_FUNC, compareFunc);
    }
    return s;
}

// The translucent casters' transmittance and nearest depth, two units up.
void bindTransmittance(const MapArray& g, const MapSamplers& samplers, bool translucent) {
    if (!translucent || !g.transmit) return;
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST + 2, g.transmit.id());
    glBindSampler(SL_UNIT_SHADOW_FIRST + 2, samplers.plainNearest.id());  // outside the map: the border, white
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST + 3, g.transmitDepth.id());
    glBindSampler(SL_UNIT_SHADOW_FIRST + 3, samplers.plainNearest.id());  // and depth 1
}

// PCSS's blocker search reads the stored depths themselves: the same
// depth array on the next unit through a sampler without comparison.
void bindRawDepth(const MapLight& p, const MapArray& g, const MapSamplers& samplers) {
    if (!filterInfo(p.options.filter).rawDepth || isPacked(g.format())) return;
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST + 1, p.targets.layerView ? p.targets.layerView.id() : g.depth.id());
    glBindSampler(SL_UNIT_SHADOW_FIRST + 1, g.mipmaps() ? samplers.plainNearestMip.id() : samplers.plainNearest.id());
}

// Filters read across face edges (RenderState::seamlessCubeMaps; the test with a plane over the seams).
void bindCube(const MapLight& p, const MapArray& g, const MapSamplers& samplers, bool translucent, DepthTaps taps) {
    const bool packed = isPacked(g.format());
    gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, packed ? g.packed.id() : p.targets.layerView ? p.targets.layerView.id() : g.depth.id());
    const bool linear = taps == DepthTaps::Linear;
    // A reversed window depth (cubeWindowDepth): lit where the receiver's is the greater.
    const bool reversed = cubeWindowDepth(p.options);
    const gl::Sampler& compare = linear ? (reversed ? samplers.compareLinearGreater : samplers.compareLinear)
                                        : (reversed ? samplers.compareNearestGreater : samplers.compareNearest);
    glBindSampler(SL_UNIT_SHADOW_FIRST, packed || taps == DepthTaps::Plain ? samplers.plainNearest.id() : compare.id());
    bindRawDepth(p, g, samplers);
    bindTransmittance(g, samplers, translucent);
}

} // namespace

void MapSamplers::create() {
    if (compareNearest) return;
    compareNearest = makeSampler(GL_NEAREST, GL_NEAREST, true);
    compareLinear = makeSampler(GL_LINEAR, GL_LINEAR, true);
    compareNearestGreater = makeSampler(GL_NEAREST, GL_NEAREST, true, GL_GEQUAL);
    compareLinearGreater = makeSampler(GL_LINEAR, GL_LINEAR, true, GL_GEQUAL);
    plainNearest = makeSampler(GL_NEAREST, GL_NEAREST, false);
    compareNearestMip = makeSampler(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, true);
    compareLinearMip = makeSampler(GL_LINEAR_MIPMAP_NEAREST, GL_LINEAR, true);
    plainNearestMip = makeSampler(GL_NEAREST_MIPMAP_NEAREST, GL_NEAREST, false);
    // Moments are filtered like colour; past the edge, the edge.
    momentLinear = makeSampler(GL_LINEAR, GL_LINEAR, false);
    momentLinearMip = makeSampler(GL_LINEAR_MIPMAP_LINEAR, GL_LINEAR, false);
    for (const gl::Sampler* m : {&momentLinear, &momentLinearMip}) {
        glSamplerParameteri(m->id(), GL_TEXTURE_WRAP_S, GL_CLAMP_TO_EDGE);
        glSamplerParameteri(m->id(), GL_TEXTURE_WRAP_T, GL_CLAMP_TO_EDGE);
    }
}

void bindLightPass(const MapLight& p, const MapArray& g, const MapSamplers& samplers, bool translucent, DepthTaps taps) {
    if (p.cube()) {
        bindCube(p, g, samplers, translucent, taps);
        return;
    }
    if (g.hasMoments() && !g.storesMoments()) {
        // The light pass gathers the depth and makes the moments (momentsFromDepth);
        // a gather ignores the filter, and takes the moments' edge.
        gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, g.depth.id());
        glBindSampler(SL_UNIT_SHADOW_FIRST, samplers.momentLinear.id());
    } else if (g.hasMoments()) {
        gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, g.moments.id());
        glBindSampler(SL_UNIT_SHADOW_FIRST, g.mipmaps() ? samplers.momentLinearMip.id() : samplers.momentLinear.id());
    } else if (isPacked(g.format())) {
        gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, g.packed.id());
        glBindSampler(SL_UNIT_SHADOW_FIRST, g.mipmaps() ? samplers.plainNearestMip.id() : samplers.plainNearest.id());
    } else {
        // One 2D map: a 2D view of its layer (MapSettings: layerView).
        gl::bindTextureUnit(SL_UNIT_SHADOW_FIRST, p.targets.layerView ? p.targets.layerView.id() : g.depth.id());
        // Bilinear compares: the hardware filter, and the grid's paired taps (shadow_map.glsl).
        const bool linear = taps == DepthTaps::Linear;
        glBindSampler(SL_UNIT_SHADOW_FIRST, taps == DepthTaps::Plain ? samplers.plainNearest.id()
                                            : g.mipmaps() ? (linear ? samplers.compareLinearMip.id() : samplers.compareNearestMip.id())
                                                          : (linear ? samplers.compareLinear.id() : samplers.compareNearest.id()));
        bindRawDepth(p, g, samplers);
    }
    bindTransmittance(g, samplers, translucent);
}

} // namespace shadowlab::map
