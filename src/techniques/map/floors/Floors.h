#pragma once
// Technique "map": the floor of a shadow pass, what it costs at least: the
// same casters, depth only, into a scratch target of the same size and
// format, with no bias, culling or packing (FrameInfo::measureFloors; bench
// times it as "shadow[i].floor"). And the floor of the light pass's
// lookups, one nearest fetch a pixel from that map (drawLookup).
#include "techniques/Technique.h"
#include "techniques/map/Light.h"
#include "techniques/map/lookup/Block.h"
#include "techniques/map/passes/Arrays.h"

#include <array>
#include <optional>

namespace shadowlab::map {

class MapFloors {
public:
    /// The floor of a 2D map's pass (each cascade's camera in turn).
    void draw(TechniqueHost& host, MapBlock& block, const FrameInfo& frame, const MapArray& g, const MapLight& p);
    /// A cube's floor: per face it uses, that face's casters, into a cube
    /// of the same size and format; then its lookups' floor (drawLookup).
    void drawCube(TechniqueHost& host, MapBlock& block, const FrameInfo& frame, const MapArray& g, const MapLight& p,
                  const std::array<bool, 6>& used);

private:
    /// The floor of the lookups of the map just drawn by draw() (a 2D map
    /// seen by the block's light camera) or drawCube() (a cube around
    /// `cubeCentre`, given for a cube only): the
    /// frame's opaque items from the camera into a scratch target of the
    /// frame's size, first with their point in the light's space alone
    /// ("lookupFloor.bare"), then with one nearest depth a pixel fetched
    /// from that map and compared ("lookupFloor.fetch"); the difference is
    /// what one lookup a pixel costs at the least, with the map as freshly
    /// drawn as the light's.
    void drawLookup(TechniqueHost& host, const FrameInfo& frame, const std::optional<glm::vec3>& cubeCentre);
    void ensureTarget(const MapArray& g);
    void ensureCube(const MapArray& g);
    const gl::Program& bind(TechniqueHost& host, const MapArray& g);
    /// Clears `fbo` (or only the 2D target's texels `part`, then scissored to
    /// them) and leaves depth-only writes on: the state it returns.
    gl::RenderState clear(TechniqueHost& host, const gl::Framebuffer& fbo, bool depthClamp, const std::optional<TexelRect>& part = std::nullopt);

    gl::Texture target_{gl::NoCreate};
    gl::Framebuffer fbo_{gl::NoCreate};
    int size_ = 0;
    gl::Texture cube_{gl::NoCreate};  ///< drawCube's target
    gl::Framebuffer cubeFbo_{gl::NoCreate};
    int cubeSize_ = 0;
    MapFormat cubeFormat_ = MapFormat::Depth32F;
    gl::Texture viewColor_{gl::NoCreate}, viewDepth_{gl::NoCreate};  ///< drawLookup's target, the frame's size
    gl::Framebuffer viewFbo_{gl::NoCreate};
    glm::ivec2 viewSize_{0};
    MapFormat format_ = MapFormat::Depth32F;
};

} // namespace shadowlab::map
