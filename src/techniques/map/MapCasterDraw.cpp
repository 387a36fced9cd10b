// Technique "map": the casters of a depth-only pass by surface (MapCasterDraw.h).
#include "techniques/map/MapCasterDraw.h"

namespace shadowlab::map {

CasterSurface casterSurface(const FrameInfo& frame, std::size_t i) {
    const int m = frame.items[i].material;
    if (m < 0) return CasterSurface::Opaque;
    switch (frame.scene.materials[static_cast<std::size_t>(m)].alphaMode) {
    case AlphaMode::Mask: return CasterSurface::Holes;
    case AlphaMode::Blend: return CasterSurface::Translucent;
    case AlphaMode::Opaque: break;
    }
    return CasterSurface::Opaque;
}

bool hasCastersWithHoles(const FrameInfo& frame) {
    for (std::size_t i = 0; i < frame.items.size(); ++i)
        if (frame.items[i].castsShadows && casterSurface(frame, i) == CasterSurface::Holes) return true;
    return false;
}

void drawDepthCasters(TechniqueHost& host, const FrameInfo& frame, bool holes, const CasterProgram& program, const CasterFilter& keep) {
    for (const bool withHoles : {false, true}) {
        if (withHoles && !holes) break;
        const gl::Program& p = program(withHoles);
        const CasterSurface wanted = withHoles ? CasterSurface::Holes : CasterSurface::Opaque;
        host.drawItems(ItemFilter::Casters, p, [&](std::size_t i) { return casterSurface(frame, i) == wanted && keep(i, p); });
    }
}

} // namespace shadowlab::map
