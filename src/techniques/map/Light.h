#pragma once
// Technique "map": what the technique keeps per light from frame to frame,
// by kind: a 2D map, cascades, a cube, and a light's tiles in the atlas;
// and what every kind has (MapLight: its effective options, its place in a
// texture array and the framebuffers on that place).
#include "geometry/LightCamera.h"
#include "gl/Object.h"

#include <shadowlab/MapOptions.h>

#include <glm/glm.hpp>

#include <algorithm>
#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <variant>
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

/// What a light's place in a texture array keeps: the framebuffer on its
/// layer (a cube: the whole array, layered) and the layer view its lookups
/// sample, attached again only when the array or the layer changes.
struct LayerTargets {
    gl::Framebuffer fbo{gl::NoCreate};
    std::uint64_t attachedGeneration = 0;
    int attachedLayer = -1;
    /// A 2D map of depth or a cube (MapSettings: layerView): its layer (a
    /// cube's six) of the depth array as a texture of its own (a view, 2D or
    /// cube), which the light pass samples (made with the framebuffers)
    gl::TextureView layerView{gl::NoCreate};
};

/// One 2D map: a spot's, a directional light's without cascades, or a
/// point light's under preset "lecture-000". Its camera is MapLight::camera.
struct FlatMap {
    bool spot = false;  ///< the shadow pass discards outside the cone
    /// A spot: how near the light the casters drawn into its map come along
    /// its axis, scene units, so that no blocker is nearer (pcss's blocker
    /// search: map.blockerNear); 0 when none is drawn or the filter is not pcss.
    float nearestCaster = 0.0f;
    /// Fit "sdsm" (fitted on the GPU: fit/Sdsm.h): the buffer its last
    /// shadow pass fitted the camera into (an SdsmFit, kept by the
    /// technique per light), which lookup/Block copies over the camera's;
    /// the camera is then the CPU's fit around where the samples may lie
    /// (fit/Cameras: sdsmReach), which culls the casters. Null otherwise.
    const gl::Buffer* gpuFit = nullptr;
};

/// A directional light's cascades: a camera per slice in layers layer ..
/// layer + n - 1 (the first is also MapLight::camera), each slice's far end
/// along the view, and the view's forward direction (the light pass picks a
/// cascade by the depth along it).
struct CascadeSet {
    std::vector<LightCamera> cameras;
    std::vector<float> far;
    float start = 0.0f;  ///< where the first slice starts along the view (the nearest receiver in view; fit/Cameras: cascadeStart)
    glm::vec3 viewForward{0.0f, 0.0f, -1.0f};
    /// Fit "sdsm": as FlatMap::gpuFit, every slice's camera (fit/Cameras:
    /// fitCullingCascades fits the CPU's culling cameras).
    const gl::Buffer* gpuFit = nullptr;
    std::vector<gl::Framebuffer> fbos;  ///< one per slice, on its layer
};

/// A point light's cube: its six face cameras, a framebuffer per face,
/// and per face the texels that may hold casters' depths from an earlier
/// frame (cleared again only there, and where casters are drawn now; whole
/// faces after (re)attaching).
struct CubeMap {
    CubeCamera camera;
    std::array<gl::Framebuffer, 6> faceFbos{gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate},
                                            gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate}, gl::Framebuffer{gl::NoCreate}};
    std::array<TexelRect, 6> faceDirty{TexelRect::whole(), TexelRect::whole(), TexelRect::whole(),
                                       TexelRect::whole(), TexelRect::whole(), TexelRect::whole()};
    /// How near the light the casters drawn into the cube come (the
    /// distance to the nearest caster's box), as FlatMap::nearestCaster.
    float nearestCaster = 0.0f;
};

/// A light's tiles in the shadow atlas (atlas/Atlas.h), a spot's one or a
/// cube's six (faces each their own): the first's index among the atlas's
/// tiles, how many (0 when culled: its reach is out of view), each one's
/// side in texels, lower-left texel and the texels its casters may cover
/// (tile-local, with a texel of margin: what is cleared and drawn; empty:
/// no caster).
struct AtlasTiles {
    int first = 0;
    int count = 0;
    std::array<int, 6> sides{};
    std::array<glm::ivec2, 6> origins{};
    std::array<TexelRect, 6> covered{};
    /// Whether this frame's shadow pass draws each tile (RenderOptions::
    /// cacheShadowMaps keeps the others: their light and casters unchanged,
    /// or past shadowAtlas.updateBudget), and what a drawn one's map
    /// follows from (atlas/Atlas keeps it once drawn).
    std::array<bool, 6> draw{};
    std::array<std::uint64_t, 6> key{};
    /// Each tile's casters, the items its camera can see, in item order
    /// (found once by Atlas::layout, drawn by Atlas::draw).
    std::array<std::vector<std::size_t>, 6> casters;
};

/// What the technique keeps of a light from frame to frame: what every
/// map has (its effective options, the camera of a 2D map or of the first
/// cascade, its place in a texture array and the targets there) and its
/// kind's own state: a 2D map, cascades or a cube; and with `atlas`, its
/// tiles in the atlas instead of a place in an array.
struct MapLight {
    MapOptions options;
    LightCamera camera;
    std::size_t array = 0;  ///< index into MapArrays (not in the atlas)
    int layer = 0;
    LayerTargets targets;
    std::variant<FlatMap, CascadeSet, CubeMap> kind;
    std::optional<AtlasTiles> atlas;  ///< options.atlas: the light's tiles

    bool cube() const { return std::holds_alternative<CubeMap>(kind); }
    CubeMap& cubeMap() { return std::get<CubeMap>(kind); }
    const CubeMap& cubeMap() const { return std::get<CubeMap>(kind); }
    const CubeCamera& cubeCamera() const { return cubeMap().camera; }
    CascadeSet* cascadeSet() { return std::get_if<CascadeSet>(&kind); }
    const CascadeSet* cascadeSet() const { return std::get_if<CascadeSet>(&kind); }
    /// A spot's 2D map (the shadow pass discards outside the cone).
    bool spot() const {
        const FlatMap* f = std::get_if<FlatMap>(&kind);
        return f && f->spot;
    }
    /// How many cascades: 0 without.
    std::size_t cascadeCount() const { return cascadeSet() ? cascadeSet()->cameras.size() : 0; }
    /// The cameras its 2D map layers were drawn from: the cascades, or the one camera.
    std::span<const LightCamera> cameras() const {
        const CascadeSet* c = cascadeSet();
        return c && !c->cameras.empty() ? std::span<const LightCamera>(c->cameras) : std::span<const LightCamera>(&camera, 1);
    }
    /// Fit "sdsm": the buffer the GPU fitted the cameras into, or null.
    const gl::Buffer* gpuFit() const {
        if (const FlatMap* f = std::get_if<FlatMap>(&kind)) return f->gpuFit;
        if (const CascadeSet* c = cascadeSet()) return c->gpuFit;
        return nullptr;
    }
    void setGpuFit(const gl::Buffer* fit) {
        if (FlatMap* f = std::get_if<FlatMap>(&kind)) f->gpuFit = fit;
        if (CascadeSet* c = cascadeSet()) c->gpuFit = fit;
    }
    /// Pcss: how near the light its casters come (FlatMap, CubeMap), or 0.
    float nearestCaster() const {
        if (const FlatMap* f = std::get_if<FlatMap>(&kind)) return f->nearestCaster;
        if (const CubeMap* c = std::get_if<CubeMap>(&kind)) return c->nearestCaster;
        return 0.0f;
    }
    /// The cube faces item i is drawn into: those its bounds touch, or all
    /// six without face culling; none for an item that cannot shadow anything seen.
    std::uint8_t faceMask(std::size_t i) const {
        const std::uint8_t mask = cubeCamera().faceMasks[i];
        return options.faceCulling || !mask ? mask : std::uint8_t{0x3F};
    }
    /// Fit "sdsm": the cameras the last shadow pass drew from, kept until
    /// this frame's pass refits them, so that a frame without shadow passes
    /// (lit by the reference, or through the previous frame's maps) reads
    /// the maps with the cameras they were drawn from (a cascade set's
    /// slices from a cascade set's).
    void keepCamerasOf(const MapLight& old) {
        camera = old.camera;
        if (CascadeSet* c = cascadeSet(); c && old.cascadeSet()) {
            const CascadeSet& o = *old.cascadeSet();
            c->cameras = o.cameras;
            c->far = o.far;
            c->start = o.start;
            c->viewForward = o.viewForward;
        }
        setGpuFit(old.gpuFit());
    }
    /// Takes what survives from last frame's state of the same light: its
    /// framebuffers and which layer they hold, the cube faces' dirty texels
    /// (whole faces when the cube changes measure, `sameMeasure` false:
    /// options/Settings cubeWindowDepth; the two clear to different values).
    void keepTargetsOf(MapLight& old, bool sameMeasure) {
        targets = std::move(old.targets);
        if (CascadeSet* c = cascadeSet(); c && old.cascadeSet()) c->fbos = std::move(old.cascadeSet()->fbos);
        if (cube() && old.cube()) {
            cubeMap().faceFbos = std::move(old.cubeMap().faceFbos);
            cubeMap().faceDirty = old.cubeMap().faceDirty;
            if (!sameMeasure) cubeMap().faceDirty.fill(TexelRect::whole());
        }
    }
};

} // namespace shadowlab::map
