#pragma once
// Technique "map": the floor of a shadow pass, what it costs at least: the
// same casters, depth only, into a scratch target of the same size and
// format, with no bias, culling or packing (FrameInfo::measureFloors; bench
// times it as "shadow[i].floor").
#include "techniques/Technique.h"
#include "techniques/map/MapArrays.h"
#include "techniques/map/MapBlock.h"
#include "techniques/map/MapLight.h"

#include <array>

namespace shadowlab::map {

class MapFloors {
public:
    /// The floor of a 2D map's pass (each cascade's camera in turn).
    void draw(TechniqueHost& host, MapBlock& block, const FrameInfo& frame, const MapArray& g, const MapLight& p);
    /// A cube's floor: per face it uses, that face's casters.
    void drawCube(TechniqueHost& host, MapBlock& block, const MapArray& g, const MapLight& p, const std::array<bool, 6>& used);

private:
    void ensureTarget(const MapArray& g);
    const gl::Program& bind(TechniqueHost& host, const MapArray& g);
    void clear(TechniqueHost& host, bool depthClamp);

    gl::Texture target_{gl::NoCreate};
    gl::Framebuffer fbo_{gl::NoCreate};
    int size_ = 0;
    MapFormat format_ = MapFormat::Depth32F;
};

} // namespace shadowlab::map
