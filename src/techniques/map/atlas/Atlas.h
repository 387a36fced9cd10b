#pragma once
// Technique "map": the shadow atlas that the lights with `atlas` share
// (Scene::shadowAtlas). Each frame every such light's tiles are sized
// from how large on screen what each sees of its reach is (a spot's one
// tile, each face of a point light's cube; core/AtlasLayout: a far or
// small light gets few texels, a near one many, the largest halved first
// to fit the texel budget and the atlas),
// placed, and described for the lookups (shared::AtlasTile, one per spot
// map or cube face, in a shader storage buffer); each light's shadow pass
// draws its casters into its own tiles, culled per tile.
#include "core/AtlasLayout.h"
#include "techniques/Technique.h"
#include "techniques/map/Light.h"
#include "techniques/map/passes/CasterBatch.h"

#include "shadow_atlas_shared.h"

#include <array>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace shadowlab::map {

class MapAtlas {
public:
    /// Bytes the atlas of `settings` takes (depth32f).
    static double bytesFor(const ShadowAtlasSettings& settings) { return 4.0 * settings.size * static_cast<double>(settings.size); }
    /// Sizes and places the tiles of `lights` (index -> state, cameras
    /// already fitted), fills each one's atlas fields, notes the lights
    /// that were shrunk, makes the texture at its size and uploads the tiles.
    /// With FrameInfo::cacheShadowMaps, a tile at the same place as last
    /// frame whose camera, casters and bias are unchanged keeps its map;
    /// of those that changed, at most shadowAtlas.updateBudget are drawn
    /// again, the longest undrawn first, and the rest keep their last map
    /// and the camera it was drawn from (the placement is kept while every
    /// light asks for the same tiles, so that there are maps to keep).
    void layout(TechniqueHost& host, const FrameInfo& frame, std::map<int, MapLight*>& lights);
    /// Draws light `p` (scene light `index`)'s casters into its tiles that
    /// this frame draws; the first call after a layout clears every light's
    /// tiles to be drawn first.
    void draw(TechniqueHost& host, const FrameInfo& frame, const MapLight& p, int index);
    /// Whether the last layout left changed tiles undrawn (past the update
    /// budget): the maps do not hold that frame's inputs yet.
    bool behind() const { return behind_; }
    /// Binds the atlas and its tiles where shadow_atlas.glsl reads them (shadow_atlas_shared.h).
    void bind() const;
    /// ListedLight::shadow for light `p` (shadowlab_shared.h).
    static glm::vec4 shadowOf(const MapLight& p);
    /// The atlas's texture (debug views), its side in texels (0: none yet).
    const gl::Texture& texture() const { return depth_; }
    int size() const { return size_; }
    /// The last layout's tiles (one per spot, six per point light).
    const std::vector<shared::AtlasTile>& tiles() const { return tiles_; }

private:
    // What layout asks the packer for, light by light (gatherRequests).
    struct Requests {
        std::vector<AtlasRequest> requests;
        std::vector<std::pair<int, AtlasRequest>> asked;  ///< each request with its light's index
        std::vector<int> order;                           ///< the lights, in the order they asked
        std::vector<std::size_t> first;                   ///< per light (in order): its first request; a cube's six are one a face
    };
    // A kept tile whose inputs changed: drawn again within the update budget.
    struct Changed {
        MapLight* p;
        int index, tile;
        std::uint64_t since;  ///< the frame it was last drawn in
    };
    // What assigning the placed tiles to their lights found (assignTiles).
    struct Assigned {
        std::uint64_t casters = 0;     ///< the frame's casters as one hash (casterInputs)
        std::vector<Changed> changed;  ///< kept tiles whose inputs changed
        int mustDraw = 0;              ///< tiles new to their place, drawn whatever the budget
        int shrunkCount = 0;           ///< lights whose tiles are smaller than asked for
        std::string shrunk;            ///< the first eight of them, "lights[i] asked -> given"
    };

    // The texture at settings.size (limit: the GPU's), its framebuffer and samplers.
    void makeTexture(const ShadowAtlasSettings& settings, int limit);
    // Each light's tiles at the side its reach on screen asks for.
    Requests gatherRequests(const FrameInfo& frame, const std::map<int, MapLight*>& lights);
    // The requests placed: last frame's places when the same lights ask for the same tiles.
    AtlasLayout place(const Requests& requests, const ShadowAtlasSettings& settings, double texelBudget);
    // Light requests.order[k]'s tiles: their places, cameras' records, the
    // texels its casters cover, and whether each is kept or drawn.
    void assignTiles(const FrameInfo& frame, const Requests& requests, std::size_t k, MapLight& p, const AtlasLayout& layout, Assigned& out);
    // At most shadowAtlas.updateBudget changed tiles drawn again, the longest undrawn first.
    void applyBudget(TechniqueHost& host, const FrameInfo& frame, Assigned& assigned);
    // Light p's casters drawn into its tiles that this frame draws; the triangles drawn.
    std::size_t drawTiles(TechniqueHost& host, const FrameInfo& frame, const MapLight& p);
    // The notes for lights whose tiles were shrunk, and for a minTile over the budget.
    void noteFit(TechniqueHost& host, const FrameInfo& frame, const Assigned& assigned, const AtlasLayout& layout, double texelBudget) const;

    gl::Texture depth_{gl::NoCreate};
    gl::Framebuffer fbo_{gl::NoCreate};
    gl::Buffer tileBuffer_{gl::NoCreate};
    std::size_t tileBytes_ = 0;
    gl::Sampler nearest_{gl::NoCreate}, compare_{gl::NoCreate};
    int size_ = 0;
    double texelsUsed_ = 0.0;  ///< the last layout's tiles' area
    MapCasterBatch batch_;     ///< the opaque casters, world space, drawn in one call per tile
    /// What each light's tiles hold (RenderOptions::cacheShadowMaps): the
    /// inputs a tile was drawn from, when, and its record and covered texels then.
    struct Drawn {
        bool valid = false;
        std::uint64_t key = 0;
        std::uint64_t frame = 0;
        shared::AtlasTile record{};
        TexelRect covered{};
    };
    std::map<int, std::array<Drawn, 6>> drawn_;
    /// What the last layout kept for the next (its hysteresis): the next
    /// asks for the same sides while they still fit, and keeps the same
    /// places while the same lights ask for the same tiles.
    struct LastFrame {
        std::vector<std::pair<int, AtlasRequest>> requests;  ///< its lights and requests
        AtlasLayout layout;
        double budget = 0.0;                       ///< the texel budget it was packed to
        std::map<int, std::array<int, 6>> sides;   ///< per light, the sides its tiles asked for (tileSideKeeping)
        glm::vec3 sizing{0.0f};                    ///< the texelsPerPixel, minTile and maxTile they were asked with
    };
    LastFrame last_;
    bool behind_ = false;
    std::vector<glm::ivec4> clears_;  ///< the texels (x, y, width, height) the next draw clears first: every drawn tile's covered rectangle
    std::vector<shared::AtlasTile> pending_;  ///< this frame's records of the tiles it draws (tiles_ holds a kept tile's old one)
    std::vector<shared::AtlasTile> tiles_;
};

} // namespace shadowlab::map
