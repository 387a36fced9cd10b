// Technique "disc": each light's discs (the casting `disc` shapes, or the
// nodes the option names) as centres and semi-axes in world space, one
// uniform block; shaders/shadow_disc.glsl tests the segment to the light
// against each. It shares the base pass: no shadow pass, no map.
#include "techniques/Disc.h"

#include "geometry/ShadowRegion.h"
#include "techniques/NodeNames.h"
#include "techniques/TechniqueBlock.h"

#include <shadowlab/DiscOptions.h>
#include <shadowlab/Error.h>

#include "shadow_disc_shared.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cmath>
#include <map>

namespace shadowlab {

namespace {

struct Disc {
    glm::vec3 centre{0.0f}, a{0.0f}, b{0.0f};
};

// The circle's radius when `mesh` is a disc shape's fan (shapes::disc:
// every vertex in the object's XZ plane, one at the origin, the rest on one
// circle), else 0.
float discRadius(const Mesh& mesh) {
    if (mesh.positions.size() < 4) return 0.0f;
    float radius = 0.0f, smallest = 1e30f;
    int centres = 0;
    for (const glm::vec3& p : mesh.positions) {
        if (p.y != 0.0f) return 0.0f;
        const float r = glm::length(glm::vec2(p.x, p.z));
        if (r == 0.0f) {
            ++centres;
            continue;
        }
        radius = std::max(radius, r);
        smallest = std::min(smallest, r);
    }
    return centres == 1 && smallest >= radius * (1.0f - 1e-5f) ? radius : 0.0f;
}

// Item i as a disc in world space, given its mesh's disc radius (0: none).
bool discOf(const DrawItem& item, float radius, Disc& out) {
    if (radius <= 0.0f) return false;
    const glm::mat4& m = item.worldFromObject;
    out.centre = glm::vec3(m * glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
    out.a = glm::vec3(m * glm::vec4(radius, 0.0f, 0.0f, 0.0f));
    out.b = glm::vec3(m * glm::vec4(0.0f, 0.0f, radius, 0.0f));
    return true;
}

class DiscShadow final : public Technique {
public:

    void prepare(TechniqueHost& host, const FrameInfo& frame, std::span<const int> lights) override {
        Bounds scene;
        for (const Bounds& b : frame.itemBounds) scene.add(b);
        offset_ = scene.empty() ? 1e-5f : 1e-5f * std::max(glm::length(scene.size()), 1.0f);
        // Which meshes are discs, found once per mesh contents.
        radii_.resize(frame.scene.meshes.size());
        for (std::size_t m = 0; m < frame.scene.meshes.size(); ++m) {
            const Mesh& mesh = frame.scene.meshes[m];
            Known& k = radii_[m];
            if (k.positions != mesh.positions.data() || k.count != mesh.positions.size()) k = {mesh.positions.data(), mesh.positions.size(), discRadius(mesh)};
        }
        const auto radiusOf = [&](std::size_t i) { return radii_[static_cast<std::size_t>(frame.items[i].mesh)].radius; };
        discs_.clear();
        counts_.clear();
        for (int index : lights) {
            const DiscOptions& o = frame.scene.lights[static_cast<std::size_t>(index)].shadow.get<DiscOptions>();
            const std::string at = "lights[" + std::to_string(index) + "].shadow.disc.casters";
            std::vector<Disc>& list = discs_[index];
            Disc d;
            for (std::size_t i : itemsNamed(frame, o.casters, at, [&](std::size_t item) { return radiusOf(item) > 0.0f; }, "is not a disc shape",
                                            [&](std::size_t item) { return frame.items[item].castsShadows; })) {
                discOf(frame.items[i], radiusOf(i), d);
                list.push_back(d);
            }
            if (list.empty())
                host.note("lights[" + std::to_string(index) + "].shadow.disc: no casting node is a disc shape, so this light casts no shadow");
            if (list.size() > SL_DISC_MAX)
                throw InputError(at + ": " + std::to_string(list.size()) + " discs, more than the " + std::to_string(SL_DISC_MAX) + " one light tests");
            counts_[&frame.scene.lights[static_cast<std::size_t>(index)]] = list.size();
        }
    }

    std::string lightPassDefines(const LightView& view) const override {
        // A light this frame did not prepare: every slot of the block (the
        // ones past its discs are zero, which no ray crosses), slower but right.
        const auto found = counts_.find(&view.light);
        return "#define DISC_COUNT " + std::to_string(found == counts_.end() ? std::size_t{SL_DISC_MAX} : found->second) + "\n";
    }

    void bindLightPass(TechniqueHost&, const FrameInfo&, const LightView& view) override {
        const std::vector<Disc>& list = discs_[view.index];
        shared::DiscUniforms u{};
        for (std::size_t k = 0; k < list.size(); ++k) {
            const Disc& d = list[k];
            // A point light in the disc's plane (within the receivers' offset
            // of it) sees the disc edge-on: a disc of no thickness shadows
            // nothing. Its slot stays zero, a disc of no extent (no ray
            // crosses a zero normal's plane), so that the count is the variant's.
            const glm::vec3 normal = glm::cross(d.a, d.b);
            if (view.light.type != LightType::Directional && std::abs(glm::dot(normal, view.light.position - d.centre)) <= offset_ * glm::length(normal))
                continue;
            u.centre[k] = glm::vec4(d.centre, 1.0f);
            u.axisA[k] = glm::vec4(d.a, 0.0f);
            u.axisB[k] = glm::vec4(d.b, 0.0f);
        }
        u.light = view.light.type == LightType::Directional ? glm::vec4(-glm::normalize(view.light.direction), 0.0f) : glm::vec4(view.light.position, 1.0f);
        u.params = glm::vec4(0.0f, offset_, 0.0f, 0.0f);
        block_.write(u);
    }

    std::optional<std::vector<glm::ivec4>> shadowedPixels(const FrameInfo& frame, const LightView& view) const override {
        const auto found = discs_.find(view.index);
        if (found == discs_.end()) return std::nullopt;
        // Each disc's box, widened by the ray's start off the surface
        // (offset_) four times over: a receiver's ray can meet the disc only
        // where the receiver lies in the disc's column, past it from the light.
        const float margin = 4.0f * offset_;
        std::vector<Bounds> boxes;
        for (const Disc& d : found->second) {
            const glm::vec3 extent = glm::sqrt(d.a * d.a + d.b * d.b) + margin;
            boxes.push_back(Bounds{d.centre - extent, d.centre + extent});
        }
        if (boxes.empty()) return std::vector<glm::ivec4>{};
        const RegionScene scene{frame.items, frame.itemBounds, frame.itemPlanes, frame.clipFromWorld, frame.viewport};
        Bounds all;
        for (const Bounds& b : frame.itemBounds) all.add(b);
        const float sceneSize = std::max(glm::length(all.size()), 1.0f);
        if (view.light.type == LightType::Directional) {
            // An orthographic light space around every item along the light.
            const glm::vec3 direction = glm::normalize(view.light.direction);
            const glm::vec3 up = std::abs(direction.y) > 0.99f ? glm::vec3(1.0f, 0.0f, 0.0f) : glm::vec3(0.0f, 1.0f, 0.0f);
            const glm::mat4 lightView = glm::lookAt(all.centre() - direction * sceneSize, all.centre(), up);
            const Bounds seen = all.transformed(lightView);
            const float nearPlane = -seen.hi.z - 1.0f, farPlane = -seen.lo.z + 1.0f;
            const glm::mat4 clip = glm::ortho(seen.lo.x - 1.0f, seen.hi.x + 1.0f, seen.lo.y - 1.0f, seen.hi.y + 1.0f, nearPlane, farPlane) * lightView;
            return shadowRects(clip, false, boxes, 2.0f * margin / (farPlane - nearPlane) + 1e-5f, scene, kMaxShadowRects);
        }
        // A point or spot light: a perspective light space from the light
        // around each disc, out past every item.
        const glm::vec3 light = view.light.position;
        float farthest = 0.0f;
        for (int c = 0; c < 8; ++c) farthest = std::max(farthest, glm::length(all.corner(c) - light));
        std::vector<glm::ivec4> rects;
        for (const Bounds& box : boxes) {
            const auto some = pointCasterRects(light, box, 0.0f, TapReach{}, [](float nearestDepth) { return 0.5f * nearestDepth; }, 1.01f * farthest + 1.0f, scene);
            if (!some) return std::nullopt;
            rects.insert(rects.end(), some->begin(), some->end());
        }
        return mergedRects(std::move(rects), kMaxShadowRects);
    }

private:
    struct Known {
        const glm::vec3* positions = nullptr;
        std::size_t count = 0;
        float radius = 0.0f;  ///< discRadius() of the mesh
    };
    std::vector<Known> radii_;  ///< per mesh
    std::map<int, std::vector<Disc>> discs_;
    std::map<const Light*, std::size_t> counts_;  ///< this frame's discs per light (the variant's DISC_COUNT)
    float offset_ = 1e-5f;
    TechniqueBlock<shared::DiscUniforms> block_;
};

} // namespace

TechniqueEntry discTechnique() { return entryOf<DiscShadow>("disc", "shadow_disc.glsl"); }

} // namespace shadowlab
