// Technique "map": the framebuffers on each light's layers (passes/Targets.h).
#include "techniques/map/passes/Targets.h"

#include "gl/Calls.h"
#include "techniques/map/options/Settings.h"

#include <algorithm>

namespace shadowlab::map {

namespace {

// Attaches layer `layer` of `g` (the whole array, layered, when negative)
// to `fbo`: its depth and the colour the pass writes, if any.
void attachLayer(gl::Framebuffer& fbo, const MapArray& g, GLuint colour, int layer, const char* what) {
    if (layer < 0) {  // the whole array, layered (gl_Layer picks)
        gl::namedFramebufferTexture(fbo.id(), GL_DEPTH_ATTACHMENT, g.depth.id(), 0);
        if (colour) gl::namedFramebufferTexture(fbo.id(), GL_COLOR_ATTACHMENT0, colour, 0);
    } else {
        gl::namedFramebufferTextureLayer(fbo.id(), GL_DEPTH_ATTACHMENT, g.depth.id(), 0, sharedDepthBuffer(g.key) ? 0 : layer);
        if (colour) gl::namedFramebufferTextureLayer(fbo.id(), GL_COLOR_ATTACHMENT0, colour, 0, layer);
    }
    gl::namedFramebufferDrawBuffer(fbo.id(), colour ? GL_COLOR_ATTACHMENT0 : GL_NONE);
    gl::namedFramebufferReadBuffer(fbo.id(), GL_NONE);
    gl::checkFramebuffer(fbo, what);
}

// The light pass's view of the light's layers when it samples one
// (MapSettings: layerView: a 2D map's layer, a cube's six), made unless it
// is there; none otherwise.
void viewLayer(MapLight& p, const MapArray& g) {
    if (!layerView(p.options, p.cube(), static_cast<int>(std::max<std::size_t>(p.cascadeCount(), 1)))) {
        p.targets.layerView = gl::TextureView(gl::NoCreate);
        return;
    }
    if (p.targets.layerView) return;
    const GLuint first = static_cast<GLuint>(p.layer * g.layersPerLight()), count = static_cast<GLuint>(g.layersPerLight());
    p.targets.layerView = gl::TextureView(p.cube() ? GL_TEXTURE_CUBE_MAP : GL_TEXTURE_2D, g.depth.id(), depthFormat(g.key), 0u, 1u, first, count);
}

} // namespace

void attachTargets(MapLight& p, const MapArray& g) {
    const bool attached = p.targets.attachedGeneration == g.generation && p.targets.attachedLayer == p.layer &&
                          (p.cascadeCount() == 0 ? static_cast<bool>(p.targets.fbo) : p.cascadeSet()->fbos.size() == p.cascadeCount());
    if (attached) {
        viewLayer(p, g);  // the options may have changed, not the layer
        return;
    }
    if (!p.targets.fbo || p.targets.attachedGeneration != g.generation) p.targets.fbo = gl::Framebuffer();
    const bool packed = isPacked(g.format());
    // The colour the pass writes: depth packed into RGBA8 (moment maps are
    // drawn as depth alone, their moments made from it: makeMoments).
    const GLuint colour = packed ? g.packed.id() : 0;
    if (p.cube()) {
        attachLayer(p.targets.fbo, g, colour, -1, "cube shadow map framebuffer (layered)");
        for (int f = 0; f < 6; ++f) {
            gl::Framebuffer& face = p.cubeMap().faceFbos[static_cast<std::size_t>(f)];
            face = gl::Framebuffer();
            attachLayer(face, g, colour, 6 * p.layer + f, "cube shadow map framebuffer (one face)");
        }
        p.cubeMap().faceDirty.fill(TexelRect::whole());  // a new array or layer: its contents are undefined
    } else if (p.cascadeCount() > 0) {
        std::vector<gl::Framebuffer>& fbos = p.cascadeSet()->fbos;
        fbos.clear();
        for (std::size_t c = 0; c < p.cascadeCount(); ++c) {
            fbos.emplace_back();
            attachLayer(fbos.back(), g, colour, p.layer + static_cast<int>(c), "cascade shadow map framebuffer");
        }
    } else {
        attachLayer(p.targets.fbo, g, colour, p.layer, "shadow map framebuffer");
    }
    p.targets.layerView = gl::TextureView(gl::NoCreate);  // of the layer it held
    viewLayer(p, g);
    p.targets.attachedGeneration = g.generation;
    p.targets.attachedLayer = p.layer;
}

} // namespace shadowlab::map
