// Technique "map": the casters of a depth-only pass by surface (passes/CasterDraw.h).
#include "gl/Calls.h"
#include "techniques/map/passes/CasterDraw.h"

#include <algorithm>
#include <array>
#include <cmath>

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

bool seesWhole(const LightCamera& camera, const Bounds& box) {
    if (box.empty()) return false;
    if (!camera.perspective) return true;
    const glm::mat4 clipFromWorld = camera.clipFromWorld();
    for (int c = 0; c < 8; ++c) {
        const glm::vec4 p = clipFromWorld * glm::vec4(box.corner(c), 1.0f);
        if (!(p.w > 0.0f) || !(p.z + p.w > 0.0f)) return false;
    }
    return true;
}

bool seesWhole(const CubeCamera& camera, const Bounds& box) {
    return !box.empty() && box.distanceTo(camera.position) > 1.7320508f * camera.nearPlane;
}

CasterDetail casterDetail(float lodTexels, const LightCamera& camera, const FrameInfo& frame) {
    if (!(lodTexels > 0.0f)) return {};
    const float fixed = lodTexels * camera.texelSize;
    if (!camera.perspective || camera.warped) return [fixed](std::size_t) { return fixed; };
    // A perspective camera's texel grows along its axis: taken at the box's nearest corner.
    const glm::vec3 eye(glm::inverse(camera.viewFromWorld)[3]);
    const glm::vec3 axis = camera.axis();
    return [lodTexels, fixed, eye, axis, &camera, &frame](std::size_t i) {
        const Bounds& box = frame.itemBounds[i];
        if (box.empty()) return fixed;
        float nearest = INFINITY;
        for (int c = 0; c < 8; ++c) nearest = std::min(nearest, glm::dot(box.corner(c) - eye, axis));
        return lodTexels * (camera.texelSize * std::max(nearest, camera.nearPlane));
    };
}

CasterDetail casterDetail(float lodTexels, const CubeCamera& camera, int size, const FrameInfo& frame) {
    if (!(lodTexels > 0.0f)) return {};
    const float perDistance = 2.0f / static_cast<float>(size);
    return [lodTexels, perDistance, &camera, &frame](std::size_t i) {
        const Bounds& box = frame.itemBounds[i];
        if (box.empty()) return 0.0f;
        return lodTexels * perDistance * std::max(box.distanceTo(camera.position) / 1.7320508f, camera.nearPlane);
    };
}

namespace {

// The level a depth pass draws item i from, the push that goes with it,
// and the triangles it has.
struct ChosenLevel {
    int level = 0;       ///< 0: the mesh itself; k: host.detailLevels(i)[k - 1]
    float push = 0.0f;   ///< world units away from the light: the level's error, scaled
    std::size_t triangles = 0;
};

// The coarsest level whose error, scaled by the item's largest stretch,
// is within what `detail` allows for item i (none: the mesh).
ChosenLevel chooseLevel(TechniqueHost& host, const FrameInfo& frame, const CasterDetail& detail, std::size_t i) {
    ChosenLevel chosen;
    const std::size_t mesh = static_cast<std::size_t>(frame.items[i].mesh);
    chosen.triangles = frame.scene.meshes[mesh].triangleCount();
    const float allowed = detail ? detail(i) : 0.0f;
    if (!(allowed > 0.0f)) return chosen;
    // The levels' errors are the mesh's: scaled by the item's largest stretch.
    const glm::mat3 m(frame.items[i].worldFromObject);
    const float scale = std::max({glm::length(m[0]), glm::length(m[1]), glm::length(m[2])});
    const std::vector<DetailLevel>& levels = host.detailLevels(i);
    for (std::size_t k = 0; k < levels.size(); ++k)
        if (levels[k].error * scale <= allowed) chosen = {static_cast<int>(k + 1), levels[k].error * scale, levels[k].triangles};
    return chosen;
}

} // namespace

std::size_t drawDepthCasters(TechniqueHost& host, const FrameInfo& frame, bool holes, const CasterProgram& program, const CasterFilter& keep,
                             const gl::RenderState& state, const CasterSeenWhole& seenWhole, const CasterDetail& detail,
                             const gl::RenderState* openCasters) {
    const auto winding = [&](std::size_t i) { return i < frame.itemWinding.size() ? frame.itemWinding[i] : 0; };
    // The side of item i the pass leaves out: none (0), or its far sides, counter-clockwise (+1) or clockwise (-1) as seen.
    const bool cullable = state.cull == gl::Cull::None && seenWhole;
    const auto farSides = [&](std::size_t i) -> int { return cullable && winding(i) != 0 && seenWhole(i) ? winding(i) : 0; };
    // cullFront: closed casters by their far sides (front faces culled,
    // or back faces where mirrored), open ones whole with openCasters.
    const bool backFaces = openCasters != nullptr && state.cull == gl::Cull::Front;
    gl::RenderState mirrored = state;
    mirrored.cull = gl::Cull::Back;
    // The state item i is drawn with (nullptr: the pass's own).
    const auto stateOf = [&](std::size_t i) -> const gl::RenderState* {
        if (!backFaces) return nullptr;
        return winding(i) > 0 ? nullptr : winding(i) < 0 ? &mirrored : openCasters;
    };
    const gl::Program& opaque = program(false);
    std::size_t drawn = 0;
    // The push is the program's own uniform, shared by every pass that
    // draws with it: each call finds it 0 and leaves it 0, so that no other
    // light's casters (nor the casters with holes, which a floor draws
    // through the same program) inherit one.
    float pushed = 0.0f;
    const auto setPush = [&](float push) {
        if (push == pushed) return;
        gl::programUniform1f(opaque.id(), kCasterPushLocation, push);
        pushed = push;
    };
    // Item i's level (0: its mesh), its push set, its triangles counted.
    const auto level = [&](std::size_t i) -> int {
        const ChosenLevel chosen = chooseLevel(host, frame, detail, i);
        setPush(chosen.push);
        drawn += chosen.triangles;
        return chosen.level;
    };
    // The items `pick` accepts, drawn with `drawState` (applied before the
    // first of them, `state` again after), or the pass's own (nullptr).
    const auto drawWith = [&](const gl::RenderState* drawState, const gl::Program& drawing, const std::function<bool(std::size_t)>& pick,
                              const std::function<int(std::size_t)>& levelOf) {
        bool applied = false;
        host.drawItems(ItemFilter::Casters, drawing, [&](std::size_t i) {
            if (!pick(i)) return false;
            if (drawState && !applied) host.apply(*drawState);
            applied = true;
            return true;
        }, Topology::Triangles, levelOf);
        if (drawState && applied) host.apply(state);
    };
    const auto isOpaque = [&](std::size_t i) { return casterSurface(frame, i) == CasterSurface::Opaque; };
    for (const int sides : {1, -1}) {
        if (!cullable) break;
        gl::RenderState culled = state;
        culled.cull = sides > 0 ? gl::Cull::Back : gl::Cull::Front;
        drawWith(&culled, opaque, [&](std::size_t i) { return isOpaque(i) && farSides(i) == sides && keep(i, opaque); }, level);
    }
    for (const gl::RenderState* group : std::array<const gl::RenderState*, 3>{nullptr, &mirrored, openCasters}) {
        if (group && !backFaces) break;
        drawWith(group, opaque, [&](std::size_t i) { return isOpaque(i) && farSides(i) == 0 && stateOf(i) == group && keep(i, opaque); }, level);
    }
    setPush(0.0f);
    if (!holes) return drawn;
    const gl::Program& cut = program(true);
    for (const gl::RenderState* group : std::array<const gl::RenderState*, 3>{nullptr, &mirrored, openCasters}) {
        if (group && !backFaces) break;
        drawWith(group, cut, [&](std::size_t i) {
            if (casterSurface(frame, i) != CasterSurface::Holes || stateOf(i) != group || !keep(i, cut)) return false;
            drawn += frame.scene.meshes[static_cast<std::size_t>(frame.items[i].mesh)].triangleCount();
            return true;
        }, {});
    }
    return drawn;
}

} // namespace shadowlab::map
