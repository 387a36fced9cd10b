#pragma once
// The plug-in point of every shadow technique.
//
// A technique is a module (src/techniques/<Name>.{h,cpp}) with an options
// struct and table (include/shadowlab/), a GLSL file defining the light
// pass's visibility hook (shaders/shadow_<name>.glsl) and one line in
// src/techniques/Registry.cpp. The renderer keeps one instance per technique
// name and hands it every light that uses it, so the instance can own
// resources per light and resources shared by several lights (a texture
// array, an atlas). It only ever talks to the renderer through
// TechniqueHost; nothing here includes src/render/.
#include "core/Bounds.h"
#include "core/MeshLevels.h"
#include "gl/PassClock.h"
#include "gl/Program.h"
#include "gl/RenderState.h"

#include <shadowlab/Context.h>
#include <shadowlab/Options.h>
#include <shadowlab/DebugImage.h>
#include <shadowlab/Scene.h>
#include <shadowlab/Techniques.h>

#include <optional>

#include <cstdint>
#include <functional>
#include <memory>
#include <span>
#include <string>
#include <vector>

namespace shadowlab {

/// What every pass of a frame may read.
struct FrameInfo {
    const Scene& scene;
    const std::vector<DrawItem>& items;      ///< every mesh instance, world transforms resolved
    const std::vector<Bounds>& itemBounds;   ///< world-space bounds of each item
    const std::vector<std::optional<glm::vec4>>& itemPlanes; ///< world-space plane (n, d) of each planar item (geometry/Plane.h)
    const std::vector<std::vector<glm::vec4>>& itemConvex;   ///< world-space planes of each convex item (geometry/Plane.h), else empty
    const std::vector<std::int8_t>& itemWinding;             ///< each closed item's winding in world space (+1: its counter-clockwise sides face out, -1: its clockwise ones; core/Adjacency.h: closedWinding), 0 for an open one
    glm::ivec2 viewport{0};                  ///< the frame's size, pixels
    glm::mat4 viewFromWorld{1.0f};           ///< the camera's
    glm::mat4 clipFromView{1.0f};
    glm::mat4 clipFromWorld{1.0f};
    double timeSeconds = 0.0;                ///< RenderOptions::timeSeconds (animated lights)
    std::uint64_t frameIndex = 0;            ///< frames this Renderer has drawn before this one
    bool measureFloors = false;              ///< RenderOptions::measureFloors: time a bare "floor" draw beside each pass
    bool reuseShadowMaps = false;            ///< RenderOptions::reuseShadowMaps: no shadow pass; keep the maps and their light cameras
    bool cacheShadowMaps = false;            ///< RenderOptions::cacheShadowMaps: keep the maps when their inputs did not change
    bool shadowRegions = true;               ///< RenderOptions::shadowRegions: passes may draw only the parts of a map its lookups read
    std::uint64_t sceneUpload = 0;           ///< how many times Renderer::upload ran: a new upload is new geometry
};

/// One light of the frame.
struct LightView {
    const Light& light;
    int index = 0;     ///< into Scene::lights
};

/// Which items a draw covers.
enum class ItemFilter {
    Opaque,    ///< every item but translucent (AlphaMode::Blend) surfaces: what the camera's depth holds (the renderer draws those last, blended)
    Casters,   ///< DrawItem::castsShadows
    Receivers, ///< DrawItem::receivesShadows
};

enum class Topology {
    Triangles,
    TrianglesAdjacency, ///< GL_TRIANGLES_ADJACENCY: 6 indices per triangle (edge neighbours), for silhouettes
};

/// What the renderer offers a technique.
///
/// Uniform blocks and texture units: the renderer owns the blocks at
/// SL_BINDING_FRAME, SL_BINDING_LIGHT and SL_BINDING_DRAW and binds them
/// again before each of its own passes and draws; a technique binds its own
/// at SL_BINDING_TECHNIQUE and textures at SL_UNIT_SHADOW_FIRST and above.
class TechniqueHost {
public:
    virtual ~TechniqueHost() = default;
    /// A program from the context's cache (compiled once per context).
    virtual const gl::Program& program(const gl::ProgramKey& key) = 0;
    /// Applies a whole render state.
    virtual void apply(const gl::RenderState& state) = 0;
    /// Draws the items that pass `filter` with `program` (already in use by
    /// the caller or not: it is made current), each with its transforms and
    /// material in the draw block (SL_BINDING_DRAW: worldFromObject,
    /// normalFromObject). `perItem(i)` runs before item i's draw and skips
    /// it by returning false (culling per light or per face). `level(i)`,
    /// when given, runs after it and picks the triangles drawn: 0 the
    /// mesh's own, k its detailLevels(i)[k - 1] (Topology::Triangles only).
    virtual void drawItems(ItemFilter filter, const gl::Program& program,
                           const std::function<bool(std::size_t item)>& perItem = {},
                           Topology topology = Topology::Triangles,
                           const std::function<int(std::size_t item)>& level = {}) = 0;
    /// The coarser levels of item i's mesh for depth passes, finest first
    /// (core/MeshLevels.h; built on first use): empty for a small mesh.
    virtual const std::vector<DetailLevel>& detailLevels(std::size_t item) = 0;
    /// A triangle covering the viewport (fullscreen.vert, no vertex input).
    virtual void drawFullscreenTriangle() = 0;
    /// Binds the renderer's blocks and item i's own (its transforms at
    /// SL_BINDING_DRAW), for a technique that draws its own geometry per
    /// item (a shadow volume built on the CPU).
    virtual void bindItem(std::size_t i) = 0;
    /// Draws the light's shading (or, when compare asks, its visibility)
    /// over the base pass's depth, with `state` (start from litState()).
    virtual void drawLit(const gl::RenderState& state) = 0;
    /// Additive blend, depth EQUAL on the base pass's depth, no depth writes.
    virtual gl::RenderState litState() const = 0;
    /// Binds the frame's framebuffer (colour, depth+stencil) and viewport.
    virtual void bindFrameTarget() = 0;
    /// A depth pre-pass of the frame, shared with the base pass: in a
    /// shadow pass, for a technique that needs the view's depth before its
    /// map (fit "sdsm"). Binds the frame's framebuffer and viewport and
    /// clears its depth and stencil, once a frame: the base pass then keeps
    /// that depth and tests LEQUAL against it, so it shades each pixel's
    /// nearest surface only (at an exact tie between two surfaces, the one
    /// drawn last, not first). Draw into it only surfaces the base pass
    /// draws, opaque, through scene.vert (invariant: the same depth, bit for
    /// bit), with colour writes off; any subset. Returns false, binding
    /// nothing, when this frame's pre-pass is drawn already.
    virtual bool beginDepthPrepass() = 0;
    /// The frame's depth (DEPTH24_STENCIL8; sampled, depth in 0..1).
    virtual const gl::Texture& frameDepth() const = 0;
    /// Index buffer with adjacency of Scene::meshes[mesh] (built on first use).
    virtual const gl::Buffer& adjacencyIndices(int mesh) = 0;
    /// Times a nested scope of the current pass: "shadow[2]" + "moments".
    virtual gl::ScopedPass timeScope(const std::string& name) = 0;
    /// Records a number for the current pass, e.g. count("triangles", n) in
    /// shadow pass 2 gives FrameStats::counters "shadow[2].triangles".
    virtual void count(const std::string& name, double value) = 0;
    /// Something the user should know about the scene (FrameStats::notes;
    /// the CLI prints each once).
    virtual void note(const std::string& text) = 0;
    virtual const GlInfo& glInfo() const = 0;
};

class Technique {
public:
    virtual ~Technique() = default;
    /// Once per frame before any pass, with the indices of every light that
    /// uses this technique: create, resize or release resources.
    virtual void prepare(TechniqueHost&, const FrameInfo&, std::span<const int> /*lights*/) {}
    /// Whether renderShadowPass does anything for this light (only such
    /// passes run and are timed, as "shadow[i]").
    virtual bool hasShadowPass(const Light&) const { return false; }
    /// Runs before the base pass with the technique's own framebuffers.
    virtual void renderShadowPass(TechniqueHost&, const FrameInfo&, const LightView&) {}
    /// Whether the light's shading can be drawn inside the base pass (the
    /// visibility hook reads only what bindLightPass binds). Techniques
    /// that need passes after the base pass (stencil) return false.
    virtual bool sharesBasePass(const Light&) const { return true; }
    /// Whether the light, when it is not the base pass's, may be shaded in
    /// the one pass over the clustered light list with the other such lights
    /// (RenderOptions::groupLights): its visibility is 1 everywhere ("none"),
    /// or read from what bindLightList binds by shadows/atlas lookups
    /// described by listedShadow ("map" with `atlas`: listShadowFile).
    virtual bool joinsLightList(const LightView&) const { return false; }
    /// The light's ListedLight::shadow (shadowlab_shared.h): zero for no shadow.
    virtual glm::vec4 listedShadow(const LightView&) const { return glm::vec4(0.0f); }
    /// The GLSL file that fills lighting.frag's "@list_shadow" slot when
    /// some listed light of this technique has a shadow: it defines
    /// `float listedVisibility(vec4 shadow, vec3 lightPosition, vec3 p,
    /// vec3 n, vec3 L, float NdotL)`, `shadow` being listedShadow's value
    /// ("map": shadow_atlas_list.glsl). Empty: no listed shadows.
    virtual std::string listShadowFile() const { return {}; }
    /// Binds what the light list's shadow lookups read (once per frame's
    /// list pass, for each technique with listed lights).
    virtual void bindLightList(TechniqueHost&) {}
    /// Whether the frame's camera needs its far plane at infinity (shadow
    /// volumes: far caps are never clipped). Any light asking for it turns
    /// it on for the whole frame; FrameInfo::clipFromView says which was used.
    virtual bool needsInfiniteFar(const Light&) const { return false; }
    /// `#define` lines for this light's variant of the technique's GLSL file
    /// (asked after prepare() for the frame).
    virtual std::string lightPassDefines(const LightView&) const { return {}; }
    /// Files that fill the technique's own `#include "@slot"` lines in this
    /// light's variant (slot, embedded file), e.g. a filter's kernel.
    virtual gl::IncludeAliases lightPassIncludes(const LightView&) const { return {}; }
    /// Binds what the GLSL hook reads (textures, the technique's block).
    virtual void bindLightPass(TechniqueHost&, const FrameInfo&, const LightView&) {}
    /// Screen rectangles outside of which the light's visibility (its
    /// light-pass hook) is exactly 1 this frame, each (x0, y0, x1, y1) in
    /// pixels from the lower left, x1 and y1 excluded (none: lit
    /// everywhere), or nothing when it may be less than 1 anywhere (the
    /// default). The renderer shades the pixels outside them without the
    /// hook (RenderOptions::shadowRegions).
    virtual std::optional<std::vector<glm::ivec4>> shadowedPixels(const FrameInfo&, const LightView&) const { return std::nullopt; }
    /// The light's pass after the base pass; the frame target is bound. The
    /// default binds and draws lit; stencil techniques fill the stencil first.
    virtual void renderLightPass(TechniqueHost& host, const FrameInfo& frame, const LightView& light) {
        bindLightPass(host, frame, light);
        host.drawLit(host.litState());
    }
    /// Images worth looking at (depth maps, cube crosses, texel density),
    /// each with the kind that `shadowlab render --debug` picks it by;
    /// `shadowlab render --debug-images DIR` writes them all. Only the
    /// kinds `kinds` wants need be made.
    virtual void debugImages(TechniqueHost&, const FrameInfo&, const LightView&, const DebugImageKinds& /*kinds*/, std::vector<DebugImage>&) {}
    /// The clip-from-world matrices of the light's cameras in the last frame
    /// (a 2D map's one, a cube's six faces), for drawing their frustums;
    /// none for techniques without a light camera.
    virtual void lightFrustums(const LightView&, std::vector<glm::mat4>&) const {}
};

/// The GL half of a registered technique (techniques/Registry.h); its
/// options and the rest of what the scene loader needs are its catalog row
/// of the same name (TechniqueKind, techniques/Catalog.h).
struct TechniqueEntry {
    std::string name;                      ///< `lights[i].shadow.technique`
    std::string shaderFile;                ///< GLSL defining `vec3 shadowVisibility(vec3 worldPosition, vec3 worldNormal)`
    std::function<std::unique_ptr<Technique>()> create;
    /// Optional GLSL for scene.vert's "@shadow_vertex?" slot: defines
    /// SHADOW_VERTEX_HOOK and `void shadowVertex(vec3 worldPosition, vec3
    /// worldNormal)`, which writes outputs the fragment file reads (e.g.
    /// light-space coordinates computed per vertex instead of per fragment).
    std::string vertexShaderFile = {};
};

/// The registry row of technique class T: its name, light-pass GLSL file
/// and a factory for T.
template <class T>
TechniqueEntry entryOf(std::string name, std::string shaderFile) {
    return {std::move(name), std::move(shaderFile), [] { return std::make_unique<T>(); }};
}

} // namespace shadowlab
