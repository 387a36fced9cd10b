#pragma once
// Technique "map": the texture arrays that hold the maps. Lights whose maps
// agree on format, size and kind share one array (a 2D map or cascade per
// layer, six layers per cube), allocated within a stated memory budget and
// kept from frame to frame while the layers they need stay the same.
#include "gl/Object.h"

#include <shadowlab/Context.h>
#include <shadowlab/MapOptions.h>

#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace shadowlab::map {

/// The depth texture format of a map (rgba8 and r8: their depth test's buffer).
GLenum depthFormat(MapFormat f);

/// What lights must agree on to share one texture array.
/// Whether a moment map's moments are taken from its depth by the light
/// pass itself (four depths gathered where a bilinear lookup of moments
/// would read, their moments blended with the same weights): with no blur,
/// no mipmaps and 32-bit moments, the moments a fullscreen pass would store
/// are just those of each depth texel, and making them cost more than the
/// depth map's whole frame (light-leak at 1024^2: 4-6 ms). Otherwise
/// (blurred, mipmapped or 16-bit moments) makeMoments stores them.
bool momentsFromDepth(const MapOptions& o);

struct ArrayKey {
    MapFormat format = MapFormat::Depth32F;
    bool mipmaps = false;
    bool cube = false;  ///< a cube-map array: six layers per light
    MapRepresentation representation = MapRepresentation::Depth;
    MapMomentFormat momentFormat = MapMomentFormat::Rgba32f;  ///< moments only
    int size = 0;
    bool storedMoments = false;  ///< moments only: made into a texture of their own (not momentsFromDepth)
    static ArrayKey of(const MapOptions& o, bool cube) {
        const bool moments = o.representation != MapRepresentation::Depth;
        return {o.format, o.mipmaps, cube, o.representation, moments ? o.momentFormat : MapMomentFormat::Rgba32f, o.size,
                moments && !momentsFromDepth(o)};
    }
    auto tie() const { return std::tie(format, mipmaps, cube, representation, momentFormat, size, storedMoments); }
    bool operator<(const ArrayKey& o) const { return tie() < o.tie(); }
    bool operator==(const ArrayKey& o) const { return tie() == o.tie(); }
};

/// The depth texture format of an array: depthFormat, but 32-bit float for
/// moments (their moments are made from it, whatever `format` says).
GLenum depthFormat(const ArrayKey& key);
/// Moments stored per texel: 0 for depth maps.
int momentCount(MapRepresentation r);
/// Whether the array's depth-test buffer is one layer shared by all its
/// lights (r8 2D maps: each pass clears it first), not a layer per map.
bool sharedDepthBuffer(const ArrayKey& key);
/// Bytes a texel of one map layer takes: its depth (the map itself for
/// depth formats; the depth test's buffer for rgba8 and moments, r8 shares
/// one), a packed format's colour, the moments.
double texelBytes(const ArrayKey& key);
/// The colour format of a moment array.
GLenum momentFormatOf(const ArrayKey& k);

/// One texture array and the textures beside it.
struct MapArray {
    ArrayKey key;
    int layers = 0;                   ///< lights' maps (a cube counts once, a cascaded light once per cascade)
    std::uint64_t generation = 0;     ///< unique per allocation: framebuffers attached to an older one are rebuilt
    gl::Texture depth{gl::NoCreate};  ///< DEPTH_COMPONENT* array: the map, the depth test's buffer for rgba8, or for moments the depth they are made from (32-bit)
    gl::Texture packed{gl::NoCreate}; ///< RGBA8 array: the map for rgba8
    gl::Texture moments{gl::NoCreate};///< RG/RGBA float array: the map for moment representations whose moments are stored (key.storedMoments)
    gl::Texture blurScratch{gl::NoCreate};   ///< moments: one layer's horizontal blur
    gl::Texture transmit{gl::NoCreate};      ///< RGBA8 array: the translucent casters' transmittance per layer (cube: per face)
    gl::Texture transmitDepth{gl::NoCreate}; ///< R32F array: the nearest translucent caster's depth per layer
    gl::Framebuffer blurFbo{gl::NoCreate};   ///< the scratch as a target
    gl::Framebuffer momentFbo{gl::NoCreate}; ///< moments: one moment layer as the only target (makeMoments attaches it)
    GLenum target() const { return key.cube ? GL_TEXTURE_CUBE_MAP_ARRAY : GL_TEXTURE_2D_ARRAY; }
    int layersPerLight() const { return key.cube ? 6 : 1; }
    bool hasMoments() const { return key.representation != MapRepresentation::Depth; }
    bool storesMoments() const { return hasMoments() && key.storedMoments; }
    // Shorthands.
    MapFormat format() const { return key.format; }
    bool mipmaps() const { return key.mipmaps; }
    bool cube() const { return key.cube; }
    int size() const { return key.size; }
};

/// Every array of the frame.
class MapArrays {
public:
    /// Makes the arrays `layersWanted` asks for (layers per key), keeping
    /// those that already fit; throws Error naming lights[firstLight] when
    /// they exceed the GPU's layers or the 1 GiB budget.
    /// `firstLightOf`: the first light of each array, named in errors;
    /// `translucent`: the arrays will get transmittance layers (addTransmittance), counted in the budget;
    /// `atlasBytes`: the shadow atlas's (MapAtlas), counted in it too.
    void allocate(const std::map<ArrayKey, int>& layersWanted, const std::map<ArrayKey, int>& firstLightOf, const GlInfo& info,
                  std::size_t lightCount, bool translucent, double atlasBytes = 0.0);
    /// Gives every array its translucent casters' transmittance layers (made once, kept with the array).
    void addTransmittance();
    /// The array of `key` (allocate() made one).
    std::size_t indexOf(const ArrayKey& key) const;
    const MapArray& operator[](std::size_t i) const { return arrays_[i]; }

private:
    std::vector<MapArray> arrays_;
    std::uint64_t generations_ = 0;
};

} // namespace shadowlab::map
