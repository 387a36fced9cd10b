#pragma once
// Technique "map": what the technique keeps per light from frame to frame:
// its effective options, its cameras (one, a cascade each, or a cube's
// six), its place in a texture array and the framebuffers on that place.
#include "geometry/LightCamera.h"
#include "gl/Object.h"

#include <shadowlab/MapOptions.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <span>
#include <vector>

namespace shadowlab::map {

/// A rectangle of a map's texels, [x0, x1) x [y0, y1); empty when x0 >= x1.
struct TexelRect {
    int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
    static TexelRect whole() { return {0, 0, 1 << 30, 1 << 30}; }
    bool empty() const { return x0 >= x1 || y0 >= y1; }
    TexelRect united(const TexelRect& o) const {
        if (empty()) return o;
        if (o.empty()) return *this;
        return {std::min(x0, o.x0), std::min(y0, o.y0), std::max(x1, o.x1), std::max(y1, o.y1)};
    }
    TexelRect clamped(int size) const { return {std::max(x0, 0), std::max(y0, 0), std::min(x1, size), std::min(y1, size)}; }
};

struct MapLight {
    MapOptions options;
    bool spot = false;  ///< the shadow pass discards outside the cone
    LightCamera camera;
    std::size_t array = 0;  ///< index into MapArrays
    int layer = 0;
    gl::Framebuffer fbo{gl::NoCreate};  ///< the layer attached (at prepare, when the array or layer changes); cube: the whole array, layered
    std::uint64_t attachedGeneration = 0;
    int attachedLayer = -1;
    /// A 2D map of depth or a cube (MapSettings: layerView): its layer (a
    /// cube's six) of the depth array as a texture of its own (a view, 2D or
    /// cube), which the light pass samples (made with the framebuffers)
    gl::TextureView layerView{gl::NoCreate};
    // Point lights.
    bool cube = false;
    CubeCamera cubeCamera;
    std::array<gl::Framebuffer, 6> faceFbos{gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate},
                                            gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate}};
    /// Per face, the texels that may hold casters' depths from an earlier
    /// frame (cleared again only there, and where casters are drawn now);
    /// whole faces after (re)attaching.
    std::array<TexelRect, 6> faceDirty{TexelRect::whole(), TexelRect::whole(), TexelRect::whole(),
                                       TexelRect::whole(), TexelRect::whole(), TexelRect::whole()};
    // Directional lights with cascades: a camera per slice (the first is
    // also `camera`) in layers layer .. layer + n - 1, each slice's far end
    // along the view, and the view's forward direction (the light pass picks
    // a cascade by the depth along it).
    std::vector<LightCamera> cascades;
    std::vector<float> cascadeFar;
    float cascadeStart = 0.0f;  ///< where the first slice starts along the view (the nearest receiver in view; MapCameras: cascadeStart)
    glm::vec3 viewForward{0.0f, 0.0f, -1.0f};
    /// Fit "sdsm" (fitted on the GPU: MapSdsm): the buffer its last
    /// shadow pass fitted the cameras into (an SdsmFit, kept by the
    /// technique per light), which MapBlock copies over the cameras'; the
    /// cameras are then the CPU's fits around where the samples may lie
    /// (MapCameras: sdsmReach, fitCullingCascades), which cull the
    /// casters. Null otherwise.
    const gl::Buffer* gpuFit = nullptr;
    /// Spot and point lights: how near the light the casters drawn into its
    /// map come, scene units (a point light: the distance to the nearest
    /// caster's box; a spot: along its axis), so that no blocker is nearer
    /// (pcss's blocker search: map.blockerNear); 0 when none is drawn.
    float nearestCaster = 0.0f;
    std::vector<gl::Framebuffer> cascadeFbos;
    /// atlas: its tiles in the shadow atlas (MapAtlas): the first's index
    /// among the atlas's tiles, how many (0 when culled: its reach is out
    /// of view), each one's side in texels (a cube's faces each their
    /// own), lower-left texel and the texels its casters may cover
    /// (tile-local, with a texel of margin: what is cleared and drawn;
    /// empty: no caster).
    int atlasFirst = 0;
    int atlasTiles = 0;
    std::array<int, 6> atlasSides{};
    std::array<glm::ivec2, 6> atlasOrigins{};
    std::array<TexelRect, 6> atlasCovered{};
    /// Whether this frame's shadow pass draws each tile (RenderOptions::
    /// cacheShadowMaps keeps the others: their light and casters unchanged,
    /// or past shadowAtlas.updateBudget), and what a drawn one's map
    /// follows from (MapAtlas keeps it once drawn).
    std::array<bool, 6> atlasDraw{};
    std::array<std::uint64_t, 6> atlasKey{};
    /// Each tile's casters, the items its camera can see, in item order
    /// (found once by MapAtlas::layout, drawn by MapAtlas::draw).
    std::array<std::vector<std::size_t>, 6> atlasCasters;
    /// The cameras its 2D map layers were drawn from: the cascades, or the one camera.
    std::span<const LightCamera> cameras() const { return cascades.empty() ? std::span<const LightCamera>(&camera, 1) : std::span<const LightCamera>(cascades); }
    /// The cube faces item i is drawn into: those its bounds touch, or all
    /// six without face culling; none for an item that cannot shadow anything seen.
    std::uint8_t faceMask(std::size_t i) const {
        const std::uint8_t mask = cubeCamera.faceMasks[i];
        return options.faceCulling || !mask ? mask : std::uint8_t{0x3F};
    }
    /// Fit "sdsm": the cameras the last shadow pass drew from, kept until
    /// this frame's pass refits them, so that a frame without shadow passes
    /// (lit by the reference, or through the previous frame's maps) reads
    /// the maps with the cameras they were drawn from.
    void keepCamerasOf(const MapLight& old) {
        camera = old.camera;
        cascades = old.cascades;
        cascadeFar = old.cascadeFar;
        cascadeStart = old.cascadeStart;
        viewForward = old.viewForward;
        gpuFit = old.gpuFit;
    }
    /// Takes what survives from last frame's state of the same light: its
    /// framebuffers and which layer they hold, the cube faces' dirty texels
    /// (whole faces when the cube changes measure, `sameMeasure` false:
    /// MapSettings cubeWindowDepth; the two clear to different values).
    void keepTargetsOf(MapLight& old, bool sameMeasure) {
        fbo = std::move(old.fbo);
        attachedGeneration = old.attachedGeneration;
        attachedLayer = old.attachedLayer;
        layerView = std::move(old.layerView);
        faceFbos = std::move(old.faceFbos);
        cascadeFbos = std::move(old.cascadeFbos);
        faceDirty = old.faceDirty;
        if (!sameMeasure) faceDirty.fill(TexelRect::whole());
    }
};

} // namespace shadowlab::map
